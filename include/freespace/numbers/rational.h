#pragma once

#include <boost/multiprecision/gmp.hpp>

#include "freespace/numbers/sign.h"

namespace freespace {

/// Exact rational numbers (GMP). Every double converts exactly.
using Rational = boost::multiprecision::mpq_rational;

inline Sign exactSign(const Rational& value) {
  const int s = value.sign();
  return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}

}  // namespace freespace
