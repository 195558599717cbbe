// The sign masks of the patch filters (src/geometry/angle_bounds.h) against the exact
// sign of the trigonometric form at rational angles: a range's bit may be missing
// only where the form cannot have that sign anywhere on the range.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "freespace/numbers/half_angle.h"
#include "geometry/angle_bounds.h"

using namespace freespace;

namespace {

int uniform(int low, int high) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(low, high)); }

/// The range of the masks that holds an angle in radians, when the angle is not
/// within a hair of a range's end (where either range would do).
std::optional<int> rangeOf(double theta) {
  const double position = (theta + M_PI) / (2 * M_PI / 64);
  const double nearest = std::round(position);
  if (std::fabs(position - nearest) < 1e-6) return std::nullopt;
  return static_cast<int>(std::floor(position)) % 64;
}

}  // namespace

RC_GTEST_PROP(AngleBounds, SignMasksHoldEverySignTheFormTakes, ()) {
  // Small integer s and c, and k near +-hypot(s, c) half the time, where the form
  // only touches zero (the hardest case for a bound over a range).
  const double s = uniform(-8, 9), c = uniform(-8, 9);
  const bool tangent = uniform(0, 2) == 1;
  const double k = tangent ? (uniform(0, 2) == 1 ? 1 : -1) * std::hypot(s, c) * (1 + uniform(-4, 5) * 1e-7)
                           : uniform(-12, 13) / 2.0;
  // Coefficients as intervals around them, of width 0 or 2^-30.
  const double width = uniform(0, 2) == 1 ? std::ldexp(1.0, -30) : 0.0;
  const TrigLinear<Interval> form{Interval(s - width, s + width), Interval(c - width, c + width),
                                  Interval(k - width, k + width)};
  const detail::SignMasks masks = detail::signMasks(form);
  for (int sample = 0; sample < 64; ++sample) {
    const HalfAngle angle{uniform(0, 2), uniform(-4096, 4097) / 4096.0};
    const std::optional<int> range = rangeOf(angle.radians());
    if (!range) continue;
    Rational cosine, sine;
    angle.cosSin(cosine, sine);
    // Each end of the coefficients' intervals is a form the masks must cover.
    for (const double shift : {-width, width}) {
      const Rational value = Rational(s + shift) * sine + Rational(c + shift) * cosine + Rational(k + shift);
      const std::uint64_t bit = std::uint64_t{1} << *range;
      if (value > 0) RC_ASSERT((masks.positive & bit) != 0);
      if (value < 0) RC_ASSERT((masks.negative & bit) != 0);
    }
  }
}

TEST(AngleBounds, SignMasksRejectSignsAFormNeverTakes) {
  // 2 + sin + cos >= 2 - sqrt(2) > 0 everywhere: never negative, positive everywhere.
  const detail::SignMasks positive = detail::signMasks({Interval(1), Interval(1), Interval(2)});
  EXPECT_EQ(positive.negative, 0u);
  EXPECT_EQ(positive.positive, ~std::uint64_t{0});
  // sin theta: positive on (0, pi) only, so some ranges have no positive bit.
  const detail::SignMasks sine = detail::signMasks({Interval(1), Interval(0), Interval(0)});
  EXPECT_NE(sine.positive, ~std::uint64_t{0});
  EXPECT_NE(sine.negative, ~std::uint64_t{0});
  // sin > 0.9 (theta in (1.12, 2.02)) and cos > 0.9 (theta in (-0.45, 0.45)): never
  // together, and apart by many ranges. sin > 0 and cos > 0: in the first quadrant.
  const detail::SignMasks highSine = detail::signMasks({Interval(1), Interval(0), Interval(-0.9)});
  const detail::SignMasks highCosine = detail::signMasks({Interval(0), Interval(1), Interval(-0.9)});
  EXPECT_FALSE(detail::signPatternMayHold({highSine, highCosine}, {Sign::Positive, Sign::Positive}));
  EXPECT_FALSE(detail::signPatternMayHold({positive, sine}, {Sign::Negative, Sign::Positive}));
  const detail::SignMasks cosine = detail::signMasks({Interval(0), Interval(1), Interval(0)});
  EXPECT_TRUE(detail::signPatternMayHold({sine, cosine}, {Sign::Positive, Sign::Positive}));
}

TEST(AngleBounds, SignMasksOfUnboundedFormsAllowEverySign) {
  const double infinity = std::numeric_limits<double>::infinity();
  const detail::SignMasks masks = detail::signMasks({Interval(-infinity, infinity), Interval(1), Interval(0)});
  EXPECT_EQ(masks.positive, ~std::uint64_t{0});
  EXPECT_EQ(masks.negative, ~std::uint64_t{0});
}
