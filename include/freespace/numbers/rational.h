#pragma once

#include <boost/multiprecision/gmp.hpp>
#include <cmath>
#include <limits>

#include "freespace/numbers/interval.h"
#include "freespace/numbers/sign.h"

namespace freespace {

/// Exact rational numbers (GMP). Every double converts exactly.
using Rational = boost::multiprecision::mpq_rational;

inline Sign exactSign(const Rational& value) { return signOf(value.sign()); }

/// 2^-bits, exactly.
inline Rational powerOfHalf(unsigned bits) {
  boost::multiprecision::mpz_int denominator(1);
  denominator <<= bits;
  return Rational(boost::multiprecision::mpz_int(1), denominator);
}

/// value times a power of two, exactly: the product in doubles when it is finite and
/// above the least normal double (the exact product then is a normal double too: a
/// power of two only moves the exponent; one rounded up to the least normal double is
/// not), else in rationals.
inline Rational timesPowerOfTwo(double value, double powerOfTwo) {
  const double product = value * powerOfTwo;
  if (value == 0 || (std::isfinite(product) && std::fabs(product) > std::numeric_limits<double>::min())) {
    return Rational(product);
  }
  return Rational(value) * Rational(powerOfTwo);
}

/// A double less than an ulp from a rational (GMP's, truncated toward zero: many times
/// faster than Boost's correctly rounded conversion, which the rays and boundary
/// distances of every query would otherwise spend a tenth of their time in). Boost's
/// where the result would leave the normal doubles, where GMP's is not specified.
inline double nearDouble(const Rational& value) {
  const double near = mpq_get_d(value.backend().data());
  if (std::isfinite(near) && (std::fabs(near) >= std::numeric_limits<double>::min() || value == 0)) return near;
  return value.convert_to<double>();
}

/// The double interval one ulp around a rational's double: it holds the rational
/// (the conversion is off by less than an ulp).
inline Interval enclosingInterval(const Rational& value) {
  const double near = nearDouble(value);
  return {std::nextafter(near, -HUGE_VAL), std::nextafter(near, HUGE_VAL)};
}

}  // namespace freespace
