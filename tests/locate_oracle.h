#pragma once

// locate against the exact collision test on random configurations around the
// environment (x, y over its box grown by the robot's reach, theta uniform). The
// exact test runs on the construction's meshes, locate takes the input's coordinates
// (FreeSpace::meshes: they differ by a power of two).

#include <random>
#include <utility>

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/space/free_space.h"

namespace freespace::testing {

struct LocateCheck {
  int disagreements = 0;
  int free = 0;
};

inline LocateCheck locateAgainstCollision(const FreeSpace& space, int samples, unsigned seed) {
  const ExactCollisionChecker collision(space.meshes().robot, space.meshes().world);
  const Box3 world = space.meshes().world.bounds();
  const double reach = space.meshes().robot.bounds().sizes().head<2>().norm();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(world.min().x() - reach, world.max().x() + reach);
  std::uniform_real_distribution<double> y(world.min().y() - reach, world.max().y() + reach);
  std::uniform_real_distribution<double> theta(-M_PI, M_PI);
  LocateCheck check;
  for (int i = 0; i < samples; ++i) {
    const Pose2 pose{x(random), y(random), theta(random)};
    const double scale = space.meshes().scale;
    const bool free = space.locate({pose.x / scale, pose.y / scale, pose.theta}).free;
    check.free += free;
    check.disagreements += free == collision.inCollision(pose);
  }
  return check;
}

}  // namespace freespace::testing
