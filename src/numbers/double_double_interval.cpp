#include "freespace/numbers/double_double_interval.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace freespace {

namespace {

/// Unit roundoff of doubles, u = 2^-53.
constexpr double kUnit = 0x1p-53;
/// Relative error of AccurateDWPlusDW, at most 3u^2 / (1 - 4u) (Joldes, Muller and
/// Popescu 2017); twice that is used.
constexpr double kSumError = 8 * kUnit * kUnit;
/// A radius computed in round to nearest by a few operations on non-negative doubles
/// is off by at most (1 + u)^6 - 1 < 8u relative: it is scaled by 1 + 8u.
constexpr double kRadiusScale = 1 + 8 * kUnit;
/// An absolute term added to the radius whenever an operation may have underflowed
/// (a product of nonzero terms, a nonzero result below kSmall): far above the error
/// of any underflowing operation (2^-1074), far below any value of interest.
constexpr double kTiny = 0x1p-1000;
constexpr double kSmall = 0x1p-900;

double inflated(double radius) { return radius * kRadiusScale; }

struct DoubleWord {
  double high, low;
};

/// Exact: a + b = high + low (Knuth's TwoSum).
DoubleWord twoSum(double a, double b) {
  const double sum = a + b;
  const double aPart = sum - b;
  const double bPart = sum - aPart;
  return {sum, (a - aPart) + (b - bPart)};
}

/// Exact when a's exponent is not below b's (Dekker's Fast2Sum).
DoubleWord fastTwoSum(double a, double b) {
  const double sum = a + b;
  return {sum, b - (sum - a)};
}

/// Exact: a * b = high + low (one fused multiply-add).
DoubleWord twoProduct(double a, double b) {
  const double product = a * b;
  return {product, std::fma(a, b, -product)};
}

/// AccurateDWPlusDW (Joldes, Muller and Popescu 2017, algorithm 6).
DoubleWord sum(DoubleWord x, DoubleWord y) {
  const DoubleWord s = twoSum(x.high, y.high);
  const DoubleWord t = twoSum(x.low, y.low);
  const DoubleWord v = fastTwoSum(s.high, s.low + t.high);
  return fastTwoSum(v.high, t.low + v.low);
}

/// A double-word product and a bound of its error.
struct Product {
  DoubleWord value;
  double error;
};

/// xh yh exactly (TwoProd), plus the cross terms xh yl + xl yh; xl yl is dropped. The
/// error is at most u |xh yl| and u |xl yh| for the cross products, u times their
/// sum, u |pl + cross| for the last addition when cross is not zero, and |xl yl|:
/// zero for two doubles, at most about 6u^2 |xy| otherwise.
Product product(DoubleWord x, DoubleWord y) {
  const DoubleWord p = twoProduct(x.high, y.high);
  const double first = x.high * y.low, second = x.low * y.high;
  const double cross = first + second;
  const double last = p.low + cross;
  double error = 2 * kUnit * (std::fabs(first) + std::fabs(second)) + std::fabs(x.low) * std::fabs(y.low);
  if (cross != 0) error += kUnit * std::fabs(last);
  const bool mayUnderflow = first != 0 || second != 0 || (p.high != 0 && std::fabs(p.high) < kSmall);
  return {fastTwoSum(p.high, last), inflated(error) + (mayUnderflow ? kTiny : 0)};
}

/// An upper bound of the absolute value of a double-word.
double magnitude(DoubleWord x) { return std::fabs(x.high) + std::fabs(x.low); }

}  // namespace

DoubleDoubleInterval::DoubleDoubleInterval(const Rational& value) {
  // Each part is off by less than an ulp (nearDouble).
  const double high = nearDouble(value);
  if (!std::isfinite(high)) {
    // Beyond doubles: an interval that decides nothing.
    high_ = 0;
    radius_ = std::numeric_limits<double>::infinity();
    return;
  }
  const Rational rest = value - Rational(high);
  const double low = nearDouble(rest);
  const Rational remainderExactly = abs(Rational(rest - Rational(low)));
  const double remainder = nearDouble(remainderExactly);
  const DoubleWord normalized = fastTwoSum(high, low);
  high_ = normalized.high;
  low_ = normalized.low;
  radius_ = inflated(remainder * kRadiusScale) + (remainderExactly != 0 ? kTiny : 0);
}

DoubleDoubleInterval DoubleDoubleInterval::widened(double radius) const {
  return {high_, low_, inflated(radius_ + radius)};
}

DoubleDoubleInterval operator+(const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) {
  const DoubleWord z = sum({a.high_, a.low_}, {b.high_, b.low_});
  // The sum of two doubles is exact (TwoSum, then two exact Fast2Sums).
  const bool exact = a.low_ == 0 && b.low_ == 0;
  const double error = exact ? 0 : kSumError * std::fabs(z.high) + (std::fabs(z.high) < kSmall ? kTiny : 0);
  return {z.high, z.low, inflated(a.radius_ + b.radius_ + error)};
}

DoubleDoubleInterval operator-(const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) { return a + (-b); }

DoubleDoubleInterval operator*(const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) {
  const DoubleWord x{a.high_, a.low_}, y{b.high_, b.low_};
  const Product z = product(x, y);
  // |x' y' - x y| <= |x| rb + |y| ra + ra rb for x' within ra of x, y' within rb of y.
  const bool spreads = a.radius_ != 0 || b.radius_ != 0;
  const double spread = spreads ? magnitude(x) * b.radius_ + magnitude(y) * a.radius_ + a.radius_ * b.radius_ + kTiny : 0;
  return {z.value.high, z.value.low, inflated(spread + z.error)};
}

DoubleDoubleInterval operator/(const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) {
  const DoubleWord x{a.high_, a.low_}, y{b.high_, b.low_};
  // |y'| >= |y| - rb for every y' of b, bounded below with margin.
  const double divisorFloor = (std::fabs(y.high) - inflated(std::fabs(y.low) + b.radius_)) * (1 - 8 * kUnit);
  if (!(divisorFloor > 0)) throw std::domain_error("double-double division by an interval that may contain zero");
  // A quotient q to about 2^-106: one correction step from the high parts.
  const double first = x.high / y.high;
  const DoubleWord firstTimesY = product(y, {first, 0}).value;
  const DoubleWord rest = sum(x, {-firstTimesY.high, -firstTimesY.low});
  const DoubleWord q = fastTwoSum(first, rest.high / y.high);
  // Certified by the residual: x' / y' - q = (x' - q y') / y' and
  // |x' - q y'| <= |x - q y| + ra + |q| rb, with x - q y enclosed in the ball below.
  const DoubleDoubleInterval residual =
      DoubleDoubleInterval(x.high, x.low, 0) - DoubleDoubleInterval(q.high, q.low, 0) * DoubleDoubleInterval(y.high, y.low, 0);
  const double numerator = inflated(magnitude({residual.high_, residual.low_}) + residual.radius_ + a.radius_ +
                                    magnitude(q) * b.radius_ + kTiny);
  return {q.high, q.low, inflated(numerator / divisorFloor) + kTiny};
}

Interval enclosingInterval(const DoubleDoubleInterval& value) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (!std::isfinite(value.high()) || !std::isfinite(value.low()) || !std::isfinite(value.radius())) {
    return Interval(-kInfinity, kInfinity);
  }
  // Rounded upward, both bounds are outward.
  RoundingScope rounding;
  const double upper = value.high() + (value.low() + value.radius());
  const double negatedLower = -value.high() + (-value.low() + value.radius());
  return Interval(-negatedLower, upper);
}

std::optional<Sign> certainSign(const DoubleDoubleInterval& value) { return certainSign(enclosingInterval(value)); }

}  // namespace freespace
