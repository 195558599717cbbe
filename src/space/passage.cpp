#include "passage.h"

#include <algorithm>
#include <cmath>

#include "every_core.h"
#include "freespace/geometry/stage_clock.h"

namespace freespace {

namespace {

/// The least clearance at the waypoints (certified upper bounds, on every core).
double leastAtWaypoints(const FreeSpace& space, const std::vector<Pose2>& waypoints,
                        const Cancellation& cancellation) {
  std::vector<double> upper(waypoints.size());
  onEveryCore(waypoints.size(), [] { return true; }, [&](std::size_t k) {
    cancellation.check();
    upper[k] = space.clearance(waypoints[k], MotionChecker::kClearanceWidth).upper;
  });
  return upper.empty() ? HUGE_VAL : *std::min_element(upper.begin(), upper.end());
}

}  // namespace

void tightenBounds(const FreeSpace& space, const MotionChecker& checker, Passage& passage, double slack,
                   std::chrono::steady_clock::time_point deadline, QueryRate& rate, const Cancellation& cancellation) {
  const std::chrono::steady_clock::time_point began = std::chrono::steady_clock::now();
  const double seconds = 0.25 * std::max(0.0, std::chrono::duration<double>(deadline - began).count());
  const double ceiling = leastAtWaypoints(space, passage.waypoints, cancellation);
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < passage.motionClearance.size(); ++k) {
    if (passage.motionClearance[k] < ceiling) order.push_back(k);
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return passage.motionClearance[a] < passage.motionClearance[b]; });
  // Twice: the motions not finished at first get another try at the rate measured
  // meanwhile (the first guess may be far too low). The motions are checked on every
  // core, the tightest first.
  for (int pass = 0; pass < 2 && !order.empty() && secondsSince(began) < seconds; ++pass) {
    std::vector<char> finished(order.size(), 0);
    const auto timeLeft = [&] { return secondsSince(began) < seconds; };
    onEveryCore(order.size(), timeLeft, [&](std::size_t at) {
      cancellation.check();
      const std::size_t k = order[at];
      const double secondsLeft = seconds - secondsSince(began);
      const MotionCheck check =
          rate.check(checker, passage.waypoints[k], passage.waypoints[k + 1], slack, secondsLeft / 2);
      if (!check.free) return;
      passage.motionClearance[k] = std::max(passage.motionClearance[k], check.minClearance);
      finished[at] = 1;
    });
    std::vector<std::size_t> unfinished;
    for (std::size_t at = 0; at < order.size(); ++at) {
      if (!finished[at]) unfinished.push_back(order[at]);
    }
    order = std::move(unfinished);
  }
  passage.lower = *std::min_element(passage.motionClearance.begin(), passage.motionClearance.end());
}

}  // namespace freespace
