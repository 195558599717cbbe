#pragma once

#include <array>
#include <optional>

#include "freespace/space/free_space.h"

namespace freespace {

/// The robot's point in the contact a clearance's witness reaches (docs/design.md
/// section 7), from the robot's axis (x and y, the robot turned by the
/// configuration's angle, in the input's coordinates), and how far it may lie from
/// the true one when the contact's place is `slack` from `nearest` at most.
struct ContactPoint {
  std::array<double, 2> fromAxis;
  double error = 0;
};

/// The robot's vertex (VF), the environment's vertex's place on the robot (FV), or
/// where the robot's edge crosses the environment's (EE: the closest points of the two
/// lines at the contact, each within `slack` of the true crossing plus their gap, so
/// within that over the sine of their angle along the edge). None without a contact,
/// or for edges within 1e-6 of parallel or that do not nearly cross.
std::optional<ContactPoint> contactPoint(const FreeSpace& space, const Clearance& clearance, double theta,
                                         double slack);

}  // namespace freespace
