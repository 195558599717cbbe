#pragma once

// Random configurations around a free space's environment, in the construction's
// coordinates: x and y over the environment's box grown by the robot's reach, theta
// uniform.

#include <cmath>
#include <random>

#include "freespace/space/free_space.h"

namespace freespace::testing {

class RandomConfigurations {
 public:
  RandomConfigurations(const FreeSpace& space, unsigned seed) : random_(seed), scale_(space.meshes().scale) {
    const Box3 world = space.meshes().world.bounds();
    const double reach = space.meshes().robot.bounds().sizes().head<2>().norm();
    x_ = std::uniform_real_distribution<double>(world.min().x() - reach, world.max().x() + reach);
    y_ = std::uniform_real_distribution<double>(world.min().y() - reach, world.max().y() + reach);
  }

  Pose2 next() { return {x_(random_), y_(random_), theta_(random_)}; }
  /// The next one in the input's coordinates (as FreeSpace's queries take them).
  Pose2 nextInInputUnits() {
    const Pose2 pose = next();
    return {pose.x / scale_, pose.y / scale_, pose.theta};
  }

 private:
  std::mt19937 random_;
  double scale_;
  std::uniform_real_distribution<double> x_, y_, theta_{-M_PI, M_PI};
};

}  // namespace freespace::testing
