#pragma once

#include <optional>
#include <vector>

#include "freespace/numbers/double_double_interval.h"
#include "freespace/numbers/interval.h"
#include "freespace/numbers/polynomial.h"

namespace freespace::detail {

/// Isolates the real roots of p in the open interval (low, high) in double interval
/// arithmetic by Descartes' rule of signs with bisection (the Vincent-Collins-Akritas
/// method): on a subinterval (a, b), q(x) = (x + 1)^n p((a x + b) / (x + 1)) has as
/// many positive roots as p has in (a, b), up to an even number, and no more than
/// its number of coefficient sign variations. Zero variations: no root; one: exactly
/// one root, simple.
///
/// Returns disjoint enclosures in increasing order, each holding exactly one root at
/// which p changes sign (certain signs of p at both ends), or nothing when doubles
/// cannot decide: an uncertain coefficient sign, p possibly zero at an end or
/// midpoint, a multiple root, or too deep a bisection. Must run in a RoundingScope.
std::optional<std::vector<Interval>> isolateRootsInDoubles(const Polynomial<Interval>& p, double low, double high);

/// The same in double-double interval arithmetic (about 106 bits: roots near the
/// ends of the interval, or coefficients that double intervals blur), with the same
/// double bisection points; must run in a NearestRoundingScope.
std::optional<std::vector<Interval>> isolateRootsInDoubleDoubles(const Polynomial<DoubleDoubleInterval>& p, double low,
                                                                 double high);

}  // namespace freespace::detail
