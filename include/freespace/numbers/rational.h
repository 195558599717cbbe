#pragma once

#include <boost/multiprecision/gmp.hpp>

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

/// The double interval one ulp around a rational's double: it holds the rational
/// (the conversion is off by less than an ulp).
inline Interval enclosingInterval(const Rational& value) {
  const double near = value.convert_to<double>();
  return {std::nextafter(near, -HUGE_VAL), std::nextafter(near, HUGE_VAL)};
}

}  // namespace freespace
