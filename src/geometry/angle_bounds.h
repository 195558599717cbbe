#pragma once

// Conservative double bounds over ranges of angles, for quick rejections in doubles
// and double intervals before any exact work.

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "freespace/numbers/algebraic_angle.h"
#include "freespace/numbers/angle_polynomial.h"
#include "freespace/numbers/interval.h"

namespace freespace::detail {

/// A range of angles in radians, from <= to, inside [-pi, pi].
using RadianRange = std::pair<double, double>;

/// An angle in radians with its cosine and sine from the library (to within an ulp
/// or two).
struct RadianCosSin {
  double angle, cosine, sine;

  static RadianCosSin at(double angle) { return {angle, std::cos(angle), std::sin(angle)}; }
};

/// Enclosures of cos and sin over the angles [from, to] (from.angle <= to.angle),
/// given at the two ends, padded far beyond the error of the library's cos and sin.
/// Needs a RoundingScope.
inline std::pair<Interval, Interval> cosSinOver(const RadianCosSin& start, const RadianCosSin& end) {
  constexpr double kPadding = 1e-9;
  const double from = start.angle, to = end.angle;
  double cosLow = std::min(start.cosine, end.cosine), cosHigh = std::max(start.cosine, end.cosine);
  double sinLow = std::min(start.sine, end.sine), sinHigh = std::max(start.sine, end.sine);
  for (double quarter = std::ceil(from / M_PI_2); quarter * M_PI_2 <= to; quarter += 1) {
    const int which = static_cast<int>(std::fmod(std::fmod(quarter, 4) + 4, 4));
    if (which == 0) cosHigh = 1;
    if (which == 1) sinHigh = 1;
    if (which == 2) cosLow = -1;
    if (which == 3) sinLow = -1;
  }
  return {Interval(cosLow - kPadding, cosHigh + kPadding), Interval(sinLow - kPadding, sinHigh + kPadding)};
}

/// The same over [from, to] in radians (from <= to).
inline std::pair<Interval, Interval> cosSinOver(double from, double to) {
  return cosSinOver(RadianCosSin::at(from), RadianCosSin::at(to));
}

/// Over each of the 64 equal ranges of angles that cover the circle (range i from
/// -pi + i pi / 32): bit i of `positive` is set unless the form is <= 0 on the whole
/// range for certain, bit i of `negative` unless it is >= 0 for certain.
struct SignMasks {
  std::uint64_t positive = 0, negative = 0;
};

/// The sign masks of a trig-linear form, from its value at each range's middle and a
/// bound on its change over the range (plain doubles with a margin for rounding).
SignMasks signMasks(const TrigLinear<Interval>& form);

/// Whether forms with these masks may have the signs `pattern` (Positive or Negative,
/// one per form) together, strictly, at some angle: false only when on each range
/// some form has the opposite sign or zero for certain. Then the closure of the set
/// where they do is empty.
bool signPatternMayHold(const std::vector<SignMasks>& masks, const std::vector<Sign>& pattern);

/// The masks of each form (signMasks).
std::vector<SignMasks> signMasksOf(const std::vector<TrigLinear<Interval>>& forms);

/// Ranges in radians that contain the angle set: each arc from the lower end of its
/// first angle's enclosure to the upper end of its last's (theta grows with t in
/// both charts), padded, and split in two where it passes through theta = pi.
std::vector<RadianRange> radianRanges(const AngleSet& set);

/// The ranges where both lists of ranges overlap.
std::vector<RadianRange> overlap(const std::vector<RadianRange>& a, const std::vector<RadianRange>& b);

}  // namespace freespace::detail
