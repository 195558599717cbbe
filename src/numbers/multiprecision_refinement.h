#pragma once

#include <optional>

#include "freespace/numbers/exact_polynomial.h"
#include "freespace/numbers/multiprecision_interval.h"
#include "freespace/numbers/rational.h"

namespace freespace::detail {

/// Bisections tried at each precision before climbing to the next: each level
/// narrows a root by about 2^-24 more, enough for near ties just past the last.
constexpr int kBisectionsPerPrecision = 24;

/// Where an enclosure of a root is split: in the middle, or off it when the sign
/// there is not certain (a root closer to the middle than the arithmetic resolves).
inline constexpr double kSplitFractions[] = {0.5, 0.375, 0.625};

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

/// A root of a polynomial given in MPFI, isolated between two binary points and
/// halved at that precision (no rationals): the step after tight coefficients.
/// A fixed root (a rational angle) is an interval that is not narrowed.
class PreciseRoot {
 public:
  using Number = PreciseInterval;

  /// From an isolating double enclosure: nothing when the signs at its ends are not
  /// certain and opposite.
  static std::optional<PreciseRoot> isolating(const Polynomial<Number>& p, double lower, double upper) {
    PreciseRoot root{Number(lower), Number(upper)};
    const std::optional<Sign> atLow = certainSign(Number(p.evaluate(root.low_)));
    const std::optional<Sign> atHigh = certainSign(Number(p.evaluate(root.high_)));
    if (!atLow || !atHigh || *atLow == Sign::Zero || *atLow != -*atHigh) return std::nullopt;
    root.atLow_ = *atLow;
    return root;
  }

  static PreciseRoot fixed(const Rational& low, const Rational& high) {
    PreciseRoot root(hull<kMultiprecisionDigits[0]>(low, low), hull<kMultiprecisionDigits[0]>(high, high));
    root.fixed_ = true;
    return root;
  }

  /// Narrows once at a binary point inside: the middle, or where the sign there is
  /// not certain (the root within the coefficients' width of it) 3/8 or 5/8 of the
  /// way. False when fixed, or when none of them is inside with a certain sign.
  bool bisect(const Polynomial<Number>& p) {
    if (fixed_) return false;
    for (const double fraction : kSplitFractions) {
      const Number point(boost::multiprecision::lower(Number(low_ + (high_ - low_) * fraction)));
      if (!(boost::multiprecision::upper(low_) < boost::multiprecision::lower(point) &&
            boost::multiprecision::upper(point) < boost::multiprecision::lower(high_))) {
        continue;
      }
      const std::optional<Sign> sign = certainSign(Number(p.evaluate(point)));
      if (!sign) continue;
      if (*sign == Sign::Zero) {
        low_ = high_ = point;
        fixed_ = true;
      } else if (*sign == atLow_) {
        low_ = point;
      } else {
        high_ = point;
      }
      return true;
    }
    return false;
  }

  /// Certainly below the other root.
  bool below(const PreciseRoot& other) const {
    return boost::multiprecision::upper(high_) < boost::multiprecision::lower(other.low_);
  }

  /// A binary point strictly between this root and a root certainly above it,
  /// exactly as a rational; nothing when none is found at this precision.
  std::optional<Rational> pointBelow(const PreciseRoot& above) const {
    const Number middle(boost::multiprecision::lower(
        Number((Number(boost::multiprecision::upper(high_)) + Number(boost::multiprecision::lower(above.low_))) / 2)));
    if (!(boost::multiprecision::upper(high_) < boost::multiprecision::lower(middle) &&
          boost::multiprecision::upper(middle) < boost::multiprecision::lower(above.low_))) {
      return std::nullopt;
    }
    // A double there if there is one (exact arithmetic on it is cheaper).
    const Number nearest(mpfr_get_d(&middle.backend().data()->left, MPFR_RNDN));
    const bool doubleInside = boost::multiprecision::upper(high_) < boost::multiprecision::lower(nearest) &&
                              boost::multiprecision::upper(nearest) < boost::multiprecision::lower(above.low_);
    Rational point;
    mpfr_get_q(point.backend().data(), &(doubleInside ? nearest : middle).backend().data()->left);
    return point;
  }


 private:
  PreciseRoot(Number low, Number high) : low_(std::move(low)), high_(std::move(high)) {}

  Number low_, high_;
  Sign atLow_ = Sign::Zero;
  bool fixed_ = false;
};

}  // namespace freespace::detail
