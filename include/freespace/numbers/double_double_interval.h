#pragma once

#include <cfenv>
#include <optional>

#include "freespace/numbers/interval.h"
#include "freespace/numbers/rational.h"
#include "freespace/numbers/sign.h"

namespace freespace {

/// A real number known to about 106 bits: a double-double midpoint (high + low, the
/// low part below half an ulp of the high one) and a double radius, the whole
/// interval [mid - radius, mid + radius] holding the exact value. It is the step
/// between double intervals and MPFI (docs/design.md section 5, step 3): as precise as
/// 108-bit MPFI and, with no allocation, about fifty times faster.
///
/// The midpoint is computed with the error-free transformations of double-word
/// arithmetic (TwoSum, TwoProd through fma) and the radius grows by a proven bound
/// of each operation's relative error (Joldes, Muller and Popescu, "Tight and
/// rigorous error bounds for basic building blocks of double-word arithmetic", ACM
/// TOMS 2017: at most 3u^2 for the sum and 5u^2 for the product of two double-words,
/// u = 2^-53; the bounds used here are larger) plus an absolute term far above any
/// underflow. A quotient is certified by its residual, whatever its midpoint's
/// accuracy. Arithmetic needs the FPU to round to nearest (NearestRoundingScope).
/// An overflow or a NaN makes the radius infinite or NaN: no sign is then certain.
class DoubleDoubleInterval {
 public:
  DoubleDoubleInterval() = default;
  DoubleDoubleInterval(double value) : high_(value) {}                         // NOLINT: implicit, like a number
  DoubleDoubleInterval(int value) : high_(static_cast<double>(value)) {}       // NOLINT
  /// The enclosure of a rational: its nearest double-word and a radius for the rest.
  explicit DoubleDoubleInterval(const Rational& value);

  double high() const { return high_; }
  double low() const { return low_; }
  double radius() const { return radius_; }

  /// The midpoint alone, as an exact number (radius zero).
  DoubleDoubleInterval midpoint() const { return {high_, low_, 0}; }
  /// The interval around this one's midpoint widened by `radius` more.
  DoubleDoubleInterval widened(double radius) const;

  friend DoubleDoubleInterval operator+(const DoubleDoubleInterval& a, const DoubleDoubleInterval& b);
  friend DoubleDoubleInterval operator-(const DoubleDoubleInterval& a, const DoubleDoubleInterval& b);
  friend DoubleDoubleInterval operator-(const DoubleDoubleInterval& a) { return {-a.high_, -a.low_, a.radius_}; }
  friend DoubleDoubleInterval operator*(const DoubleDoubleInterval& a, const DoubleDoubleInterval& b);
  /// Division by an interval that may contain zero throws std::domain_error, as for
  /// Interval: no formula divides by something that may vanish.
  friend DoubleDoubleInterval operator/(const DoubleDoubleInterval& a, const DoubleDoubleInterval& b);

  DoubleDoubleInterval& operator+=(const DoubleDoubleInterval& other) { return *this = *this + other; }
  DoubleDoubleInterval& operator-=(const DoubleDoubleInterval& other) { return *this = *this - other; }
  DoubleDoubleInterval& operator*=(const DoubleDoubleInterval& other) { return *this = *this * other; }

 private:
  DoubleDoubleInterval(double high, double low, double radius) : high_(high), low_(low), radius_(radius) {}

  double high_ = 0;
  double low_ = 0;
  double radius_ = 0;
};

/// The narrowest double interval (within an ulp) holding it.
Interval enclosingInterval(const DoubleDoubleInterval& value);

/// Certain sign, or nothing when the interval holds zero without being exactly zero.
std::optional<Sign> certainSign(const DoubleDoubleInterval& value);

/// Rounding to nearest, as DoubleDoubleInterval needs (inside Interval's upward
/// rounding, say).
using NearestRoundingScope = ScopedRounding<FE_TONEAREST>;

}  // namespace freespace
