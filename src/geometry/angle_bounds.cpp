#include "angle_bounds.h"

#include <algorithm>
#include <array>

#include "freespace/numbers/half_angle.h"

namespace freespace::detail {

namespace {

/// Far above the error of atan on an enclosure's ends.
constexpr double kAnglePadding = 1e-9;

}  // namespace

namespace {

constexpr int kSignRanges = 64;

/// Cosine and sine of each range's middle angle.
struct RangeMiddles {
  std::array<double, kSignRanges> cosine, sine;
};

const RangeMiddles& rangeMiddles() {
  static const RangeMiddles middles = [] {
    RangeMiddles m;
    for (int i = 0; i < kSignRanges; ++i) {
      const double angle = -M_PI + (i + 0.5) * (2 * M_PI / kSignRanges);
      m.cosine[i] = std::cos(angle);
      m.sine[i] = std::sin(angle);
    }
    return m;
  }();
  return middles;
}

/// At least the distance of the middle from either end.
double widthOf(const Interval& x) { return x.upper() - x.lower(); }

}  // namespace

SignMasks signMasks(const TrigLinear<Interval>& form) {
  // With s, c, k the coefficients' middles, f(theta) = s sin + c cos + k differs from
  // its value at a range's middle by at most sqrt(s^2 + c^2) times the half-width
  // (the derivative's bound), and from the form's by at most the coefficients'
  // widths (|sin|, |cos| <= 1). The last term covers rounding, the half-width is
  // padded for the middles' own error. A NaN or infinite margin sets every bit.
  const double s = form.s.midpoint(), c = form.c.midpoint(), k = form.k.midpoint();
  const double halfWidth = (M_PI / kSignRanges) * (1 + 1e-9);
  const double widths = widthOf(form.s) + widthOf(form.c) + widthOf(form.k);
  const double margin =
      (std::sqrt(s * s + c * c) * halfWidth + widths + 1e-14 * (std::fabs(s) + std::fabs(c) + std::fabs(k))) * (1 + 1e-12);
  const RangeMiddles& middles = rangeMiddles();
  SignMasks masks;
  for (int i = 0; i < kSignRanges; ++i) {
    const double value = s * middles.sine[i] + c * middles.cosine[i] + k;
    const std::uint64_t bit = std::uint64_t{1} << i;
    if (!(value + margin <= 0)) masks.positive |= bit;
    if (!(value - margin >= 0)) masks.negative |= bit;
  }
  return masks;
}

std::vector<SignMasks> signMasksOf(const std::vector<TrigLinear<Interval>>& forms) {
  std::vector<SignMasks> masks;
  masks.reserve(forms.size());
  for (const TrigLinear<Interval>& form : forms) masks.push_back(signMasks(form));
  return masks;
}

bool signPatternMayHold(const std::vector<SignMasks>& masks, const std::vector<Sign>& pattern) {
  std::uint64_t possible = ~std::uint64_t{0};
  for (std::size_t k = 0; k < masks.size(); ++k) {
    possible &= pattern[k] == Sign::Positive ? masks[k].positive : masks[k].negative;
  }
  return possible != 0;
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
