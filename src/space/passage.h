#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/geometry/stage_clock.h"
#include "freespace/space/motion_checker.h"

namespace freespace {

/// A path between the climbs' ends (docs/design.md section 7), each motion with a
/// certified lower bound on its clearance, and the least of them.
struct Passage {
  std::vector<Pose2> waypoints;
  std::vector<double> motionClearance;
  double lower = HUGE_VAL;
};

/// Clearance queries per second of motion checks, measured as they run (a guess of
/// 5,000 until 200 have run), shared by the stages that budget motion checks by the
/// time left.
class QueryRate {
 public:
  MotionCheck check(const MotionChecker& checker, const Pose2& from, const Pose2& to, double slack,
                    double secondsLeft) {
    const auto began = std::chrono::steady_clock::now();
    const auto limit = static_cast<std::size_t>(100 + std::max(0.0, secondsLeft) * perSecond());
    const MotionCheck result = checker.check(from, to, slack, limit);
    queries_ += static_cast<double>(result.clearanceQueries);
    seconds_ += secondsSince(began);
    return result;
  }

 private:
  double perSecond() const { return queries_ > 200 && seconds_ > 0 ? queries_ / seconds_ : 5000; }
  double queries_ = 0, seconds_ = 0;
};

/// Raises the certified clearance of each motion towards its least (parts halved
/// until each part's bound is within `slack` of its ends' clearance: freedom alone
/// needs far fewer), the tightest motions first, within a quarter of the time left
/// (each may take half of what is left of that); a motion whose tighter check does
/// not finish keeps its bound.
void tightenBounds(const MotionChecker& checker, Passage& passage, double slack,
                   std::chrono::steady_clock::time_point deadline, QueryRate& rate,
                   const Cancellation& cancellation = {});

}  // namespace freespace
