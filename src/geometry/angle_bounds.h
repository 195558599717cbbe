#pragma once

// Conservative double bounds over ranges of angles, for quick rejections in double
// intervals before any exact work.

#include <cmath>
#include <utility>
#include <vector>

#include "freespace/numbers/algebraic_angle.h"
#include "freespace/numbers/angle_polynomial.h"
#include "freespace/numbers/interval.h"

namespace freespace::detail {

/// A range of angles in radians, from <= to, inside [-pi, pi].
using RadianRange = std::pair<double, double>;

/// Enclosures of cos and sin over the angles [from, to] (radians, from <= to),
/// padded far beyond the error of the library's cos and sin. Needs a RoundingScope.
inline std::pair<Interval, Interval> cosSinOver(double from, double to) {
  constexpr double kPadding = 1e-9;
  double cosLow = std::min(std::cos(from), std::cos(to)), cosHigh = std::max(std::cos(from), std::cos(to));
  double sinLow = std::min(std::sin(from), std::sin(to)), sinHigh = std::max(std::sin(from), std::sin(to));
  for (double quarter = std::ceil(from / M_PI_2); quarter * M_PI_2 <= to; quarter += 1) {
    const int which = static_cast<int>(std::fmod(std::fmod(quarter, 4) + 4, 4));
    if (which == 0) cosHigh = 1;
    if (which == 1) sinHigh = 1;
    if (which == 2) cosLow = -1;
    if (which == 3) sinLow = -1;
  }
  return {Interval(cosLow - kPadding, cosHigh + kPadding), Interval(sinLow - kPadding, sinHigh + kPadding)};
}

/// Whether the trig-linear forms may have the signs `pattern` (Positive or Negative,
/// one per form) together, strictly, at some angle: false only when on each of 32
/// ranges that cover the circle some form has the opposite sign or zero for
/// certain (double intervals). Then the closure of the set where they do is empty.
bool signPatternMayHold(const std::vector<TrigLinear<Interval>>& forms, const std::vector<Sign>& pattern);

/// Ranges in radians that contain the angle set: each arc from the lower end of its
/// first angle's enclosure to the upper end of its last's (theta grows with t in
/// both charts), padded, and split in two where it passes through theta = pi.
std::vector<RadianRange> radianRanges(const AngleSet& set);

/// The ranges where both lists of ranges overlap.
std::vector<RadianRange> overlap(const std::vector<RadianRange>& a, const std::vector<RadianRange>& b);

}  // namespace freespace::detail
