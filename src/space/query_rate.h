#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <mutex>

#include "freespace/geometry/stage_clock.h"
#include "freespace/space/motion_checker.h"

namespace freespace {

/// Clearance queries per second of motion checks, measured as they run (a guess of
/// 5,000 until 200 have run), shared by the stages that budget motion checks by the
/// time left; checks may run on several threads at once.
class QueryRate {
 public:
  MotionCheck check(const MotionChecker& checker, const Pose2& from, const Pose2& to, double slack,
                    double secondsLeft) {
    const auto began = std::chrono::steady_clock::now();
    const auto limit = static_cast<std::size_t>(100 + std::max(0.0, secondsLeft) * perSecond());
    const MotionCheck result = checker.check(from, to, slack, limit);
    const std::lock_guard lock(mutex_);
    queries_ += static_cast<double>(result.clearanceQueries);
    seconds_ += secondsSince(began);
    return result;
  }

 private:
  double perSecond() {
    const std::lock_guard lock(mutex_);
    return queries_ > 200 && seconds_ > 0 ? queries_ / seconds_ : 5000;
  }
  std::mutex mutex_;
  double queries_ = 0, seconds_ = 0;
};

}  // namespace freespace
