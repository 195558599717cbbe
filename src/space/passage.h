#pragma once

#include <array>
#include <chrono>
#include <cmath>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/space/motion_checker.h"
#include "query_rate.h"

namespace freespace {

/// The x and y range paths may use (the volume, within the free cell's box).
struct Domain {
  std::array<double, 2> low, high;
  bool holds(const Pose2& pose) const {
    return pose.x >= low[0] && pose.x <= high[0] && pose.y >= low[1] && pose.y <= high[1];
  }
};

/// A path between the climbs' ends (docs/design.md section 7), each motion with a
/// certified lower bound on its clearance, and the least of them.
struct Passage {
  std::vector<Pose2> waypoints;
  std::vector<double> motionClearance;
  double lower = HUGE_VAL;
};

/// Raises the certified clearance of each motion towards its least (parts halved
/// until each part's bound is within `slack` of its ends' clearance: freedom alone
/// needs far fewer), the tightest motions first (on every core), within a quarter of
/// the time left (each may take half of what is left of that); a motion whose tighter
/// check does not finish keeps its bound. Motions whose bound is already at least the
/// least clearance at the waypoints are left alone: the passage's clearance cannot
/// exceed that, so tightened they would limit nothing.
void tightenBounds(const FreeSpace& space, const MotionChecker& checker, Passage& passage, double slack,
                   std::chrono::steady_clock::time_point deadline, QueryRate& rate,
                   const Cancellation& cancellation = {});

}  // namespace freespace
