#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "freespace/geometry/cancellation.h"

namespace freespace {

/// Seconds of wall-clock time since `start`.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct StageTime {
  std::string stage;
  double seconds = 0;
};

/// Runs the stages of a long computation one after another: polls the cancellation
/// and announces each stage to `progress` (when set) as it starts, and records how
/// long each took.
class StageClock {
 public:
  explicit StageClock(std::function<void(const std::string& stage)> progress = {}, Cancellation cancellation = {})
      : progress_(std::move(progress)), cancellation_(cancellation) {}

  template <class Work>
  auto run(const std::string& stage, Work&& work) {
    cancellation_.check();
    if (progress_) progress_(stage);
    const auto start = std::chrono::steady_clock::now();
    auto result = work();
    times_.push_back({stage, secondsSince(start)});
    return result;
  }

  const Cancellation& cancellation() const { return cancellation_; }
  const std::vector<StageTime>& times() const { return times_; }

 private:
  std::function<void(const std::string& stage)> progress_;
  Cancellation cancellation_;
  std::vector<StageTime> times_;
};

}  // namespace freespace
