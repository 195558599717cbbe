#pragma once

#include <boost/multiprecision/mpfi.hpp>

#include <optional>

#include "freespace/numbers/double_double_interval.h"
#include "freespace/numbers/interval.h"
#include "freespace/numbers/sign.h"

namespace freespace {

/// MPFI intervals with a precision fixed at compile time (decimal digits). Fixed
/// precisions keep the types thread safe: Boost's variable-precision default is a
/// process-wide setting.
template <unsigned Digits10>
using MultiprecisionInterval = boost::multiprecision::number<boost::multiprecision::mpfi_float_backend<Digits10>>;

/// The ladder the adaptive engine climbs after double intervals: about 107, 213,
/// 426 and 851 bits, each level doubling the precision of the one before.
inline constexpr unsigned kMultiprecisionDigits[] = {32, 64, 128, 256};
inline constexpr int kMultiprecisionLevels = 4;

/// MPFI intervals of the first precision of the ladder (about 108 bits).
using PreciseInterval = MultiprecisionInterval<kMultiprecisionDigits[0]>;

template <unsigned Digits10>
std::optional<Sign> certainSign(const MultiprecisionInterval<Digits10>& value) {
  if (boost::multiprecision::lower(value) > 0) return Sign::Positive;
  if (boost::multiprecision::upper(value) < 0) return Sign::Negative;
  if (boost::multiprecision::lower(value) == 0 && boost::multiprecision::upper(value) == 0) return Sign::Zero;
  return std::nullopt;
}

/// The narrowest double interval holding the MPFI interval.
template <unsigned Digits10>
Interval enclosingInterval(const MultiprecisionInterval<Digits10>& value) {
  const auto* bounds = value.backend().data();
  return Interval(mpfr_get_d(&bounds->left, MPFR_RNDD), mpfr_get_d(&bounds->right, MPFR_RNDU));
}

/// The MPFI interval holding a double-double interval (the sums round outward).
inline PreciseInterval enclosingPreciseInterval(const DoubleDoubleInterval& value) {
  return PreciseInterval(value.high()) + PreciseInterval(value.low()) + PreciseInterval(-value.radius(), value.radius());
}

}  // namespace freespace
