#pragma once

#include <vector>

#include "freespace/numbers/polynomial.h"
#include "freespace/numbers/rational.h"
#include "freespace/numbers/sign.h"

namespace freespace {

/// Exact algebra on angle polynomials with rational coefficients (docs/design.md section 5,
/// step 4): square-free parts, gcds, Sturm sequences, root isolation, and the signs
/// and orders that the predicates ask for at real algebraic roots.
///
/// Every function accepts untrimmed input (zero leading coefficients) and returns
/// trimmed polynomials. Conventions:
///   - countDistinctRoots counts over the half-open interval (lo, hi];
///   - isolateRoots searches the closed interval [lo, hi];
///   - "monic" means leading coefficient 1; the zero polynomial stays zero.
using RationalPolynomial = Polynomial<Rational>;

/// -1 for the zero polynomial.
int degree(const RationalPolynomial& p);
/// p without zero leading coefficients (no coefficients at all for zero).
RationalPolynomial trimmed(const RationalPolynomial& p);
bool isZero(const RationalPolynomial& p);

struct PolynomialDivision {
  RationalPolynomial quotient;
  RationalPolynomial remainder;  // degree(remainder) < degree(divisor)
};
/// dividend = quotient * divisor + remainder. Throws std::invalid_argument when the
/// divisor is zero.
PolynomialDivision divide(const RationalPolynomial& dividend, const RationalPolynomial& divisor);

/// Monic greatest common divisor; gcd(0, 0) = 0.
RationalPolynomial gcd(const RationalPolynomial& a, const RationalPolynomial& b);

/// p / gcd(p, p'), monic: the same distinct roots, each simple. Zero stays zero and
/// a nonzero constant gives 1.
RationalPolynomial squareFreePart(const RationalPolynomial& p);

/// The Sturm sequence p, p', -rem(p, p'), ... of a square-free p (each member scaled by
/// a positive constant, which leaves all signs unchanged). Throws std::invalid_argument
/// for the zero polynomial.
std::vector<RationalPolynomial> sturmSequence(const RationalPolynomial& squareFree);

/// The number of distinct real roots in the half-open interval (lo, hi] of the
/// polynomial whose Sturm sequence is given. Throws std::invalid_argument if lo > hi.
int countDistinctRoots(const std::vector<RationalPolynomial>& sturm, const Rational& lo, const Rational& hi);

/// One real root of a polynomial p, isolated: either lo == hi and the root is that
/// rational, or lo < hi, the square-free part of p has exactly one root strictly
/// inside (lo, hi), none at lo or hi, and takes opposite signs at lo and hi.
struct IsolatingInterval {
  Rational lo;
  Rational hi;

  bool isExact() const { return lo == hi; }
};

/// All distinct real roots of p in the closed interval [lo, hi], in increasing order
/// (consecutive intervals may share an endpoint). A root found exactly (at lo, at hi
/// or at a bisection midpoint) is returned as an exact interval. Throws
/// std::invalid_argument when p is zero or lo > hi.
std::vector<IsolatingInterval> isolateRoots(const RationalPolynomial& p, const Rational& lo, const Rational& hi);

/// Halves a non-exact isolating interval of a root of squareFree, keeping the root;
/// if the midpoint is the root the interval becomes exact. Exact intervals are left
/// as they are.
void bisect(const RationalPolynomial& squareFree, IsolatingInterval& root);

Sign signAt(const RationalPolynomial& p, const Rational& t);

/// The exact sign of f at the root of g isolated by root. Throws std::invalid_argument
/// when g is zero.
Sign signAtRoot(const RationalPolynomial& f, const RationalPolynomial& g, IsolatingInterval root);

/// -1, 0 or +1 as the root of f isolated by a is less than, equal to or greater than
/// the root of g isolated by b. Equal roots of different polynomials are recognised
/// exactly, also when irrational. Throws std::invalid_argument when f or g is zero.
int compareRoots(const RationalPolynomial& f, IsolatingInterval a, const RationalPolynomial& g, IsolatingInterval b);

}  // namespace freespace
