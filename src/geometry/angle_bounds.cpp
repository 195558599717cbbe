#include "angle_bounds.h"

#include <algorithm>

#include "freespace/numbers/half_angle.h"

namespace freespace::detail {

namespace {

/// Far above the error of atan on an enclosure's ends.
constexpr double kAnglePadding = 1e-9;

}  // namespace

bool signPatternMayHold(const std::vector<TrigLinear<Interval>>& forms, const std::vector<Sign>& pattern) {
  constexpr int kRanges = 32;
  // The ranges' cosine and sine enclosures, computed once.
  static const std::vector<std::pair<Interval, Interval>> cosSinOfRanges = [] {
    RoundingScope rounding;
    std::vector<std::pair<Interval, Interval>> enclosures;
    for (int i = 0; i < kRanges; ++i) {
      enclosures.push_back(cosSinOver(-M_PI + 2 * M_PI * i / kRanges, std::min(M_PI, -M_PI + 2 * M_PI * (i + 1) / kRanges)));
    }
    return enclosures;
  }();
  RoundingScope rounding;
  return std::any_of(cosSinOfRanges.begin(), cosSinOfRanges.end(), [&](const auto& cosSin) {
    const auto& [cosine, sine] = cosSin;
    for (std::size_t k = 0; k < forms.size(); ++k) {
      const std::optional<Sign> sign = certainSign(valueAt(forms[k], cosine, sine));
      if (sign && *sign != pattern[k]) return false;
    }
    return true;
  });
}

std::vector<RadianRange> radianRanges(const AngleSet& set) {
  if (set.fullCircle) return {{-M_PI, M_PI}};
  std::vector<RadianRange> ranges;
  for (const AngleInterval& arc : set.arcs) {
    const double from = HalfAngle{arc.from.chart(), arc.from.lower()}.radians() - kAnglePadding;
    const double to = HalfAngle{arc.to.chart(), arc.to.upper()}.radians() + kAnglePadding;
    if (from <= to) {
      ranges.emplace_back(std::max(from, -M_PI), std::min(to, M_PI));
    } else {
      // Through theta = pi (an arc is less than a full turn).
      ranges.emplace_back(std::max(from, -M_PI), M_PI);
      ranges.emplace_back(-M_PI, std::min(to, M_PI));
    }
  }
  return ranges;
}

std::vector<RadianRange> overlap(const std::vector<RadianRange>& a, const std::vector<RadianRange>& b) {
  std::vector<RadianRange> common;
  for (const auto& [fromA, toA] : a) {
    for (const auto& [fromB, toB] : b) {
      const double from = std::max(fromA, fromB), to = std::min(toA, toB);
      if (from <= to) common.emplace_back(from, to);
    }
  }
  return common;
}

}  // namespace freespace::detail
