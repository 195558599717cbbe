#pragma once

#include <boost/numeric/interval.hpp>

#include "freespace/numbers/sign.h"

namespace freespace {

namespace interval_detail {
namespace bi = boost::numeric::interval_lib;
// Upward rounding for everything; lower bounds are computed by negation
// (rounded_arith_opp), so the rounding mode is switched once per scope, not per
// operation.
using Protected = boost::numeric::interval<
    double, bi::policies<bi::save_state<bi::rounded_arith_opp<double>>, bi::checking_no_nan<double>>>;
}  // namespace interval_detail

/// Double interval with outward rounding. Arithmetic on it is only valid while a
/// RoundingScope is alive on the current thread.
using Interval = boost::numeric::interval_lib::unprotect<interval_detail::Protected>::type;

/// Sets the FPU to the rounding mode Interval needs and restores the previous mode
/// on destruction. Keep scopes tight: ordinary double code inside one rounds upward.
using RoundingScope = interval_detail::Protected::traits_type::rounding;

/// Certain sign of an interval, or nothing when it contains zero without being
/// exactly zero.
inline std::optional<Sign> certainSign(const Interval& value) {
  if (value.lower() > 0) return Sign::Positive;
  if (value.upper() < 0) return Sign::Negative;
  if (value.lower() == 0 && value.upper() == 0) return Sign::Zero;
  return std::nullopt;
}

}  // namespace freespace
