#pragma once

// locate against the exact collision test on random configurations around the
// environment (x, y over its box grown by the robot's reach, theta uniform). The
// exact test runs on the construction's meshes, locate takes the input's coordinates
// (FreeSpace::meshes: they differ by a power of two).

#include <random>
#include <utility>

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/space/free_space.h"
#include "random_configurations.h"

namespace freespace::testing {

struct LocateCheck {
  int disagreements = 0;
  int free = 0;
};

inline LocateCheck locateAgainstCollision(const FreeSpace& space, int samples, unsigned seed) {
  const ExactCollisionChecker collision(space.meshes().robot, space.meshes().world);
  RandomConfigurations configurations(space, seed);
  LocateCheck check;
  for (int i = 0; i < samples; ++i) {
    const Pose2 pose = configurations.next();
    const double scale = space.meshes().scale;
    const bool free = space.locate({pose.x / scale, pose.y / scale, pose.theta}).free;
    check.free += free;
    check.disagreements += free == collision.inCollision(pose);
  }
  return check;
}

}  // namespace freespace::testing
