// The lazy ranking of a route's travel angles (src/space/lazy_ranking.h) against
// ranking every estimate: the same order, with estimates made only as needed.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "space/lazy_ranking.h"

using namespace freespace;

namespace {

/// Every angle above the floor, ranked by estimate (largest first, ties in order).
std::vector<double> rankedInFull(const std::vector<double>& angles, const std::vector<std::optional<double>>& estimates,
                                 double floor) {
  std::vector<std::pair<double, double>> ranked;  // estimate, angle
  for (std::size_t k = 0; k < angles.size(); ++k) {
    if (estimates[k] && *estimates[k] > floor) ranked.push_back({*estimates[k], angles[k]});
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<double> order;
  for (const auto& entry : ranked) order.push_back(entry.second);
  return order;
}

}  // namespace

RC_GTEST_PROP(LazyRanking, GivesTheOrderOfRankingEveryEstimate, ()) {
  const int count = *rc::gen::inRange(0, 12);
  std::vector<double> angles;
  std::vector<std::optional<double>> estimates;
  std::vector<std::pair<double, double>> bounded;
  for (int k = 0; k < count; ++k) {
    angles.push_back(k * 0.5);
    // Few distinct values: ties between estimates, and between estimates and bounds.
    const int value = *rc::gen::inRange(0, 5);
    const bool hasEstimate = *rc::gen::inRange(0, 4) > 0;
    estimates.push_back(hasEstimate ? std::optional<double>(value) : std::nullopt);
    bounded.push_back({angles.back(), value + *rc::gen::inRange(0, 3)});
  }
  const double floor = *rc::gen::inRange(-1, 4);
  LazyRanking ranking(bounded, floor);
  std::vector<double> order;
  std::size_t made = 0;
  const auto estimate = [&](double angle) {
    ++made;
    return estimates[static_cast<std::size_t>(angle / 0.5)];
  };
  for (std::optional<double> next = ranking.next(estimate); next; next = ranking.next(estimate)) order.push_back(*next);
  RC_ASSERT(order == rankedInFull(angles, estimates, floor));
  RC_ASSERT(made <= angles.size());
}

TEST(LazyRanking, MakesOneEstimateWhenTheBoundsAreExactAndApart) {
  const std::vector<std::pair<double, double>> bounded{{0.1, 3}, {0.2, 7}, {0.3, 5}, {0.4, 1}};
  LazyRanking ranking(bounded, 0);
  int made = 0;
  const auto estimate = [&](double angle) -> std::optional<double> {
    ++made;
    for (const auto& [candidate, bound] : bounded) {
      if (candidate == angle) return bound;
    }
    return std::nullopt;
  };
  EXPECT_EQ(ranking.next(estimate), 0.2);
  EXPECT_EQ(made, 1);
  EXPECT_EQ(ranking.next(estimate), 0.3);
  EXPECT_EQ(made, 2);
}

TEST(LazyRanking, LeavesOutAnglesWhoseBoundsAreNotAboveTheFloor) {
  const std::vector<std::pair<double, double>> bounded{{0.1, 3}, {0.2, 1}, {0.3, 2}};
  LazyRanking ranking(bounded, 2);
  int made = 0;
  const auto estimate = [&](double) -> std::optional<double> {
    ++made;
    return 2.5;
  };
  EXPECT_EQ(ranking.next(estimate), 0.1);
  EXPECT_EQ(ranking.next(estimate), std::nullopt);
  EXPECT_EQ(made, 1);
}
