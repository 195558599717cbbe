#pragma once

#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace freespace {

/// Angles ranked by estimates that are costly to make, each bounded above by a cheap
/// bound: estimates are made, the largest bound first, only until the largest made
/// exceeds every bound left. The order given is that of ranking every estimate,
/// largest first, ties in the order the angles came in; only estimates above a floor.
class LazyRanking {
 public:
  /// Angles with upper bounds on their estimates (angle, bound).
  LazyRanking(const std::vector<std::pair<double, double>>& boundedAngles, double floor) : floor_(floor) {
    for (std::size_t k = 0; k < boundedAngles.size(); ++k) {
      const auto [angle, bound] = boundedAngles[k];
      if (bound > floor) pending_.push_back({bound, k, angle});
    }
    std::stable_sort(pending_.begin(), pending_.end(), [](const auto& a, const auto& b) { return a.bound > b.bound; });
  }

  /// The next angle, by `estimate(angle)` (an optional: none when the angle has no
  /// estimate); none when no estimate left exceeds the floor.
  template <class Estimate>
  std::optional<double> next(const Estimate& estimate) {
    while (!pending_.empty() && !bestMadeLeadsPending()) {
      const Pending first = pending_.front();
      pending_.erase(pending_.begin());
      const std::optional<double> value = estimate(first.angle);
      if (value && *value > floor_) made_.insert({{*value, first.order}, first.angle});
    }
    if (made_.empty()) return std::nullopt;
    const double angle = made_.begin()->second;
    made_.erase(made_.begin());
    return angle;
  }

 private:
  struct Pending {
    double bound;
    std::size_t order;
    double angle;
  };
  /// Estimates made and not yet given (estimate, order), largest first, then in order.
  struct Larger {
    bool operator()(const std::pair<double, std::size_t>& a, const std::pair<double, std::size_t>& b) const {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    }
  };

  /// Whether the largest estimate made exceeds every pending bound (and so every
  /// estimate not made).
  bool bestMadeLeadsPending() const { return !made_.empty() && made_.begin()->first.first > pending_.front().bound; }

  double floor_;
  std::vector<Pending> pending_;  // the largest bound first
  std::map<std::pair<double, std::size_t>, double, Larger> made_;
};

}  // namespace freespace
