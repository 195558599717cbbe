#include "freespace/numbers/exact_polynomial.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace freespace {
namespace {

std::vector<Rational> trimmedCoefficients(const RationalPolynomial& p) {
  const auto& coefficients = p.coefficients();
  return std::vector<Rational>(coefficients.begin(), coefficients.begin() + (degree(p) + 1));
}

RationalPolynomial withoutLeadingZeros(std::vector<Rational> coefficients) {
  while (!coefficients.empty() && coefficients.back().is_zero()) coefficients.pop_back();
  return RationalPolynomial(std::move(coefficients));
}

/// Precondition: p is not zero.
const Rational& leadingCoefficient(const RationalPolynomial& p) { return p.coefficients()[degree(p)]; }

/// factor * p, trimmed. Precondition: factor is not zero.
RationalPolynomial scaled(const RationalPolynomial& p, const Rational& factor) {
  const int pDegree = degree(p);
  std::vector<Rational> coefficients;
  coefficients.reserve(pDegree + 1);
  for (int power = 0; power <= pDegree; ++power) coefficients.emplace_back(p.coefficients()[power] * factor);
  return RationalPolynomial(std::move(coefficients));
}

RationalPolynomial monic(const RationalPolynomial& p) {
  if (isZero(p)) return RationalPolynomial();
  return scaled(p, Rational(1) / leadingCoefficient(p));
}

/// The member after previous and current in a Sturm sequence: -rem(previous, current),
/// scaled by a positive constant so that its leading coefficient is +1 or -1 (only
/// signs matter, and this keeps the rationals small).
RationalPolynomial sturmSuccessor(const RationalPolynomial& previous, const RationalPolynomial& current) {
  const RationalPolynomial remainder = divide(previous, current).remainder;
  if (isZero(remainder)) return remainder;
  return scaled(remainder, Rational(-1) / abs(leadingCoefficient(remainder)));
}

/// Sign changes along the sequence evaluated at x, zeros skipped.
int signVariations(const std::vector<RationalPolynomial>& sequence, const Rational& x) {
  int variations = 0;
  Sign previous = Sign::Zero;
  for (const RationalPolynomial& member : sequence) {
    const Sign current = signAt(member, x);
    if (current == Sign::Zero) continue;
    if (previous != Sign::Zero && current != previous) ++variations;
    previous = current;
  }
  return variations;
}

/// Whether a square-free polynomial has a root in the closed interval [lo, hi].
bool hasRootInClosedInterval(const RationalPolynomial& squareFree, const Rational& lo, const Rational& hi) {
  if (lo > hi || degree(squareFree) < 1) return false;
  return signAt(squareFree, lo) == Sign::Zero || countDistinctRoots(sturmSequence(squareFree), lo, hi) > 0;
}

/// Finds the roots of one polynomial by bisection guided by Sturm counts.
class RootIsolator {
 public:
  explicit RootIsolator(const RationalPolynomial& p)
      : squareFree_(squareFreePart(p)), sturm_(sturmSequence(squareFree_)) {}

  std::vector<IsolatingInterval> isolate(const Rational& lo, const Rational& hi) {
    if (isRoot(lo)) roots_.push_back({lo, lo});
    if (lo < hi) {
      isolateInside(lo, hi, countStrictlyInside(lo, hi));
      if (isRoot(hi)) roots_.push_back({hi, hi});
    }
    return std::move(roots_);
  }

 private:
  bool isRoot(const Rational& t) const { return signAt(squareFree_, t) == Sign::Zero; }

  /// Roots in the open interval (lo, hi), lo < hi.
  int countStrictlyInside(const Rational& lo, const Rational& hi) const {
    return countDistinctRoots(sturm_, lo, hi) - (isRoot(hi) ? 1 : 0);
  }

  /// Appends, in order, the rootsInside roots of the open interval (lo, hi).
  void isolateInside(const Rational& lo, const Rational& hi, int rootsInside) {
    if (rootsInside == 0) return;
    // A single simple root and nonzero ends: the square-free part changes sign once.
    // An end that is a root (only lo or hi of the whole search) needs more halving
    // until a midpoint falls between it and the root inside.
    if (rootsInside == 1 && !isRoot(lo) && !isRoot(hi)) {
      roots_.push_back({lo, hi});
      return;
    }
    const Rational middle = (lo + hi) / 2;
    const int rootsLeft = countStrictlyInside(lo, middle);
    const bool middleIsRoot = isRoot(middle);
    isolateInside(lo, middle, rootsLeft);
    if (middleIsRoot) roots_.push_back({middle, middle});
    isolateInside(middle, hi, rootsInside - rootsLeft - (middleIsRoot ? 1 : 0));
  }

  RationalPolynomial squareFree_;
  std::vector<RationalPolynomial> sturm_;
  std::vector<IsolatingInterval> roots_;
};

}  // namespace

int degree(const RationalPolynomial& p) {
  const auto& coefficients = p.coefficients();
  int result = static_cast<int>(coefficients.size()) - 1;
  while (result >= 0 && coefficients[result].is_zero()) --result;
  return result;
}

RationalPolynomial trimmed(const RationalPolynomial& p) { return RationalPolynomial(trimmedCoefficients(p)); }

bool isZero(const RationalPolynomial& p) { return degree(p) < 0; }

PolynomialDivision divide(const RationalPolynomial& dividend, const RationalPolynomial& divisor) {
  const int divisorDegree = degree(divisor);
  if (divisorDegree < 0) throw std::invalid_argument("divide: division by the zero polynomial");
  const std::vector<Rational>& d = divisor.coefficients();
  std::vector<Rational> remainder = trimmedCoefficients(dividend);
  const int quotientSize = static_cast<int>(remainder.size()) - divisorDegree;
  if (quotientSize <= 0) return {RationalPolynomial(), RationalPolynomial(std::move(remainder))};

  // Long division: each step cancels the current leading term of the remainder.
  std::vector<Rational> quotient(quotientSize);
  for (int shift = quotientSize - 1; shift >= 0; --shift) {
    Rational& term = quotient[shift];
    term = remainder[shift + divisorDegree] / d[divisorDegree];
    for (int power = 0; power < divisorDegree; ++power) remainder[shift + power] -= term * d[power];
  }
  remainder.resize(divisorDegree);  // the cancelled leading terms are exactly zero
  return {RationalPolynomial(std::move(quotient)), withoutLeadingZeros(std::move(remainder))};
}

RationalPolynomial gcd(const RationalPolynomial& a, const RationalPolynomial& b) {
  // Euclid: gcd(a, b) = gcd(b, a mod b). Making each remainder monic changes it only
  // by a constant factor and keeps the coefficients small.
  RationalPolynomial larger = trimmed(a);
  RationalPolynomial smaller = trimmed(b);
  while (!isZero(smaller)) {
    RationalPolynomial remainder = monic(divide(larger, smaller).remainder);
    larger = std::move(smaller);
    smaller = std::move(remainder);
  }
  return monic(larger);
}

RationalPolynomial squareFreePart(const RationalPolynomial& p) {
  if (isZero(p)) return RationalPolynomial();
  // Over the rationals a root of multiplicity m of p is a root of multiplicity m - 1
  // of p', so gcd(p, p') holds each root m - 1 times and the quotient holds it once.
  return monic(divide(p, gcd(p, p.derivative())).quotient);
}

std::vector<RationalPolynomial> sturmSequence(const RationalPolynomial& squareFree) {
  if (isZero(squareFree)) throw std::invalid_argument("sturmSequence: zero polynomial");
  // p0 = p, p1 = p', p(i+1) = -rem(p(i-1), p(i)) until the remainder vanishes. For a
  // square-free p the last member is a nonzero constant (gcd(p, p') = 1).
  std::vector<RationalPolynomial> sequence;
  RationalPolynomial previous = trimmed(squareFree);
  RationalPolynomial current = trimmed(squareFree.derivative());
  while (!isZero(current)) {
    RationalPolynomial next = sturmSuccessor(previous, current);
    sequence.push_back(std::move(previous));
    previous = std::move(current);
    current = std::move(next);
  }
  sequence.push_back(std::move(previous));
  return sequence;
}

int countDistinctRoots(const std::vector<RationalPolynomial>& sturm, const Rational& lo, const Rational& hi) {
  if (lo > hi) throw std::invalid_argument("countDistinctRoots: lo > hi");
  // Sturm's theorem: the number of sign variations V(x) of the sequence drops by one
  // exactly when x passes a root of p (p and p' have opposite signs just before it and
  // the same sign just after), and is unchanged where an inner member vanishes (its
  // neighbours have opposite signs there). V(x) at a root already has the dropped
  // value since zeros are skipped, so V(lo) - V(hi) counts the roots in (lo, hi].
  return signVariations(sturm, lo) - signVariations(sturm, hi);
}

std::vector<IsolatingInterval> isolateRoots(const RationalPolynomial& p, const Rational& lo, const Rational& hi) {
  if (isZero(p)) throw std::invalid_argument("isolateRoots: the zero polynomial has every number as a root");
  if (lo > hi) throw std::invalid_argument("isolateRoots: lo > hi");
  return RootIsolator(p).isolate(lo, hi);
}

void bisect(const RationalPolynomial& squareFree, IsolatingInterval& root) {
  if (root.isExact()) return;
  Rational middle = (root.lo + root.hi) / 2;
  const Sign atMiddle = signAt(squareFree, middle);
  if (atMiddle == Sign::Zero) {
    root.lo = middle;
    root.hi = std::move(middle);
  } else if (atMiddle == signAt(squareFree, root.lo)) {
    root.lo = std::move(middle);  // the sign change is in the upper half
  } else {
    root.hi = std::move(middle);
  }
}

Sign signAt(const RationalPolynomial& p, const Rational& t) { return exactSign(p.evaluate(t)); }

Sign signAtRoot(const RationalPolynomial& f, const RationalPolynomial& g, IsolatingInterval root) {
  if (isZero(g)) throw std::invalid_argument("signAtRoot: g is the zero polynomial");
  if (root.isExact()) return signAt(f, root.lo);
  const RationalPolynomial gSquareFree = squareFreePart(g);
  // f vanishes at the root exactly when the root is a root of gcd(f, g*) (g* the
  // square-free part). That gcd divides g*, whose only root in the closed interval is
  // the isolated one, so it suffices to look for any of its roots there. (A zero f
  // gives gcd = g*, hence Zero.)
  if (hasRootInClosedInterval(gcd(f, gSquareFree), root.lo, root.hi)) return Sign::Zero;
  // Otherwise f is nonzero near the root: shrink the interval until f has no root in
  // (lo, hi]; then f has the same sign at the root and at hi.
  const std::vector<RationalPolynomial> fSturm = sturmSequence(squareFreePart(f));
  while (countDistinctRoots(fSturm, root.lo, root.hi) > 0) bisect(gSquareFree, root);
  return signAt(f, root.hi);
}

int compareRoots(const RationalPolynomial& f, IsolatingInterval a, const RationalPolynomial& g, IsolatingInterval b) {
  if (isZero(f) || isZero(g)) throw std::invalid_argument("compareRoots: zero polynomial");
  const RationalPolynomial fSquareFree = squareFreePart(f);
  const RationalPolynomial gSquareFree = squareFreePart(g);
  // Equal roots are a common root of f and g, i.e. a root of gcd(f*, g*) in both
  // intervals. Conversely such a root is the root isolated by a (gcd divides f*,
  // which has only that root in a) and likewise by b.
  const Rational& overlapLo = std::max(a.lo, b.lo);
  const Rational& overlapHi = std::min(a.hi, b.hi);
  if (hasRootInClosedInterval(gcd(fSquareFree, gSquareFree), overlapLo, overlapHi)) return 0;
  // Different roots: shrink both intervals until they are apart. Intervals touching
  // at one point are apart: the root of a non-exact interval is strictly inside, and
  // two exact intervals at one point would have been equal above.
  while (true) {
    if (a.hi <= b.lo) return -1;
    if (b.hi <= a.lo) return 1;
    bisect(fSquareFree, a);
    bisect(gSquareFree, b);
  }
}

}  // namespace freespace
