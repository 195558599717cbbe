#pragma once

#include <optional>

#include "freespace/numbers/exact_polynomial.h"
#include "freespace/numbers/multiprecision_interval.h"
#include "freespace/numbers/rational.h"

namespace freespace::detail {

/// Bisections tried at each precision before climbing to the next: each level
/// narrows a root by about 2^-24 more, enough for near ties just past the last.
constexpr int kBisectionsPerPrecision = 24;

/// The smallest MPFI interval holding the rationals [low, high].
template <unsigned Digits10>
MultiprecisionInterval<Digits10> hull(const Rational& low, const Rational& high) {
  MultiprecisionInterval<Digits10> result;
  mpfi_interv_q(result.backend().data(), low.backend().data(), high.backend().data());
  return result;
}

template <unsigned Digits10>
Polynomial<MultiprecisionInterval<Digits10>> enclosePolynomial(const RationalPolynomial& p) {
  std::vector<MultiprecisionInterval<Digits10>> coefficients;
  for (const Rational& c : p.coefficients()) coefficients.push_back(hull<Digits10>(c, c));
  return Polynomial<MultiprecisionInterval<Digits10>>(std::move(coefficients));
}

/// Narrows an isolating interval of a root of `squareFree` by bisection at
/// multiprecision: a step is taken only when the sign at the midpoint and the sign
/// change across the interval are certain. Returns false when no step was possible.
template <unsigned Digits10>
bool bisectInPrecision(const Polynomial<MultiprecisionInterval<Digits10>>& squareFree, IsolatingInterval& root) {
  if (root.lo == root.hi) return false;
  const Rational middle = (root.lo + root.hi) / 2;
  const auto atLow = certainSign(MultiprecisionInterval<Digits10>(squareFree.evaluate(hull<Digits10>(root.lo, root.lo))));
  const auto atHigh = certainSign(MultiprecisionInterval<Digits10>(squareFree.evaluate(hull<Digits10>(root.hi, root.hi))));
  const auto atMiddle = certainSign(MultiprecisionInterval<Digits10>(squareFree.evaluate(hull<Digits10>(middle, middle))));
  if (!atLow || !atHigh || !atMiddle || *atLow == Sign::Zero || *atLow != -*atHigh) return false;
  if (*atMiddle == Sign::Zero) {
    root = {middle, middle};
  } else if (*atMiddle == *atLow) {
    root.lo = middle;
  } else {
    root.hi = middle;
  }
  return true;
}

/// Sign of f at the root of `squareFree` isolated by `root`, at one precision:
/// evaluates f on the interval and bisects while f's sign is uncertain, up to the
/// precision's worth of steps.
template <unsigned Digits10>
std::optional<Sign> signAtRootInPrecision(const RationalPolynomial& f, const RationalPolynomial& squareFree,
                                          IsolatingInterval& root) {
  using T = MultiprecisionInterval<Digits10>;
  const Polynomial<T> fEnclosed = enclosePolynomial<Digits10>(f);
  const Polynomial<T> gEnclosed = enclosePolynomial<Digits10>(squareFree);
  for (int step = 0; step < kBisectionsPerPrecision; ++step) {
    if (const std::optional<Sign> sign = certainSign(T(fEnclosed.evaluate(hull<Digits10>(root.lo, root.hi))))) {
      return sign;
    }
    if (!bisectInPrecision(gEnclosed, root)) return std::nullopt;
  }
  return std::nullopt;
}

/// Order of two roots at one precision: bisects both until their intervals are
/// disjoint. Nothing when they stay overlapping (equal roots end here).
template <unsigned Digits10>
std::optional<int> compareRootsInPrecision(const RationalPolynomial& f, IsolatingInterval& a,
                                           const RationalPolynomial& g, IsolatingInterval& b) {
  const auto fEnclosed = enclosePolynomial<Digits10>(f);
  const auto gEnclosed = enclosePolynomial<Digits10>(g);
  for (int step = 0; step < kBisectionsPerPrecision; ++step) {
    if (a.hi < b.lo) return -1;
    if (b.hi < a.lo) return 1;
    const bool movedA = bisectInPrecision(fEnclosed, a);
    const bool movedB = bisectInPrecision(gEnclosed, b);
    if (!movedA && !movedB) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace freespace::detail
