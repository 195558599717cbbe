#pragma once

#include <boost/multiprecision/gmp.hpp>

#include "freespace/numbers/sign.h"

namespace freespace {

/// Exact rational numbers (GMP). Every double converts exactly.
using Rational = boost::multiprecision::mpq_rational;

inline Sign exactSign(const Rational& value) { return signOf(value.sign()); }

}  // namespace freespace
