// Exact polynomial algebra checked on polynomials built from known factors: the
// expected roots, gcds, signs and orders come from the construction (comparisons of
// rationals and of rationals with sqrt(2)), never from the code under test.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <boost/multiprecision/mpfi.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "freespace/numbers/exact_polynomial.h"
#include "freespace/numbers/interval.h"

namespace freespace {
namespace {

// ---------------------------------------------------------------------------------
// Building polynomials (independent of the code under test)

RationalPolynomial times(const RationalPolynomial& a, const RationalPolynomial& b) {
  if (a.size() == 0 || b.size() == 0) return RationalPolynomial();
  std::vector<Rational> product(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) product[i + j] += a.coefficients()[i] * b.coefficients()[j];
  }
  return RationalPolynomial(std::move(product));
}

RationalPolynomial plus(const RationalPolynomial& a, const RationalPolynomial& b) {
  std::vector<Rational> sum(std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < a.size(); ++i) sum[i] += a.coefficients()[i];
  for (std::size_t i = 0; i < b.size(); ++i) sum[i] += b.coefficients()[i];
  return RationalPolynomial(std::move(sum));
}

RationalPolynomial constant(const Rational& c) { return RationalPolynomial({c}); }
RationalPolynomial linearFactor(const Rational& root) { return RationalPolynomial({-root, 1}); }
RationalPolynomial quadratic(const Rational& c) { return RationalPolynomial({c, 0, 1}); }  // t^2 + c

/// Equal as polynomials: missing coefficients count as zero.
bool samePolynomial(const RationalPolynomial& a, const RationalPolynomial& b) {
  const std::size_t size = std::max(a.size(), b.size());
  for (std::size_t i = 0; i < size; ++i) {
    const Rational ai = i < a.size() ? a.coefficients()[i] : Rational(0);
    const Rational bi = i < b.size() ? b.coefficients()[i] : Rational(0);
    if (ai != bi) return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------
// Known real roots: rationals and +-sqrt(2), compared exactly

/// The rational `rational` when sqrtTwoSign is 0, otherwise sqrtTwoSign * sqrt(2).
struct KnownRoot {
  Rational rational;
  int sqrtTwoSign = 0;
};

/// Sign of r - s sqrt(2) for s = +-1, from r^2 < 2 style facts.
int compareWithSqrtTwo(const Rational& r, int s) {
  if (s < 0) return -compareWithSqrtTwo(-r, 1);
  if (r <= 0) return -1;
  return r * r < 2 ? -1 : 1;  // r^2 = 2 has no rational solution
}

template <class T>
int threeWay(const T& a, const T& b) {
  return a < b ? -1 : (b < a ? 1 : 0);
}

int compareKnown(const KnownRoot& x, const KnownRoot& y) {
  if (x.sqrtTwoSign == 0 && y.sqrtTwoSign == 0) return threeWay(x.rational, y.rational);
  if (x.sqrtTwoSign != 0 && y.sqrtTwoSign != 0) return threeWay(x.sqrtTwoSign, y.sqrtTwoSign);
  if (y.sqrtTwoSign != 0) return compareWithSqrtTwo(x.rational, y.sqrtTwoSign);
  return -compareWithSqrtTwo(y.rational, x.sqrtTwoSign);
}

bool contains(const IsolatingInterval& interval, const KnownRoot& x) {
  return compareKnown({interval.lo}, x) <= 0 && compareKnown(x, {interval.hi}) <= 0;
}


/// scale * prod (t - r)^m * (t^2 - 2)^sqrtTwoMultiplicity * (t^2 + positiveOffset if > 0).
struct KnownPolynomial {
  Rational scale{1};
  std::map<Rational, int> linearFactors;  // root -> multiplicity (>= 1)
  int sqrtTwoMultiplicity = 0;
  Rational positiveOffset{0};  // 0: no quadratic factor without real roots

  RationalPolynomial expanded() const {
    RationalPolynomial result = constant(scale);
    for (const auto& [root, multiplicity] : linearFactors) {
      for (int k = 0; k < multiplicity; ++k) result = times(result, linearFactor(root));
    }
    for (int k = 0; k < sqrtTwoMultiplicity; ++k) result = times(result, quadratic(-2));
    if (positiveOffset > 0) result = times(result, quadratic(positiveOffset));
    return result;
  }

  /// Every factor once, scale 1: the monic square-free part.
  KnownPolynomial squareFreeFactors() const {
    KnownPolynomial result = *this;
    result.scale = 1;
    for (auto& factor : result.linearFactors) factor.second = 1;
    result.sqrtTwoMultiplicity = std::min(sqrtTwoMultiplicity, 1);
    return result;
  }

  /// The distinct real roots in [lo, hi], increasing.
  std::vector<KnownRoot> rootsIn(const Rational& lo, const Rational& hi) const {
    std::vector<KnownRoot> all;
    for (const auto& factor : linearFactors) all.push_back({factor.first});
    if (sqrtTwoMultiplicity > 0) {
      all.push_back({0, -1});
      all.push_back({0, 1});
    }
    std::vector<KnownRoot> inside;
    for (const KnownRoot& x : all) {
      if (compareKnown({lo}, x) <= 0 && compareKnown(x, {hi}) <= 0) inside.push_back(x);
    }
    std::sort(inside.begin(), inside.end(),
              [](const KnownRoot& a, const KnownRoot& b) { return compareKnown(a, b) < 0; });
    return inside;
  }

  /// The sign at x as the product of the signs of the factors.
  Sign signAt(const KnownRoot& x) const {
    int result = scale.sign();
    for (const auto& [root, multiplicity] : linearFactors) {
      for (int k = 0; k < multiplicity; ++k) result *= compareKnown(x, {root});
    }
    const int sqrtTwoFactorSign = x.sqrtTwoSign != 0 ? 0 : Rational(x.rational * x.rational - 2).sign();
    for (int k = 0; k < sqrtTwoMultiplicity; ++k) result *= sqrtTwoFactorSign;
    return signOf(result);
  }
};

KnownPolynomial commonFactors(const KnownPolynomial& f, const KnownPolynomial& g) {
  KnownPolynomial common;
  for (const auto& [root, multiplicity] : f.linearFactors) {
    const auto inG = g.linearFactors.find(root);
    if (inG != g.linearFactors.end()) common.linearFactors[root] = std::min(multiplicity, inG->second);
  }
  common.sqrtTwoMultiplicity = std::min(f.sqrtTwoMultiplicity, g.sqrtTwoMultiplicity);
  if (f.positiveOffset == g.positiveOffset) common.positiveOffset = f.positiveOffset;
  return common;
}

/// Valid isolation of a root of known, from the factors: exact, or one root inside
/// with the square-free part nonzero and of opposite signs at the ends.
bool isolatesOneRoot(const IsolatingInterval& interval, const KnownPolynomial& known) {
  if (interval.isExact()) return known.signAt({interval.lo}) == Sign::Zero;
  const KnownPolynomial squareFree = known.squareFreeFactors();
  const Sign atLo = squareFree.signAt({interval.lo});
  const Sign atHi = squareFree.signAt({interval.hi});
  return interval.lo < interval.hi && known.rootsIn(interval.lo, interval.hi).size() == 1 && atLo != Sign::Zero &&
         atHi == -atLo;
}

// ---------------------------------------------------------------------------------
// Generators

Rational drawRational() { return Rational(*rc::gen::inRange(-40, 41), *rc::gen::inRange(1, 9)); }

Rational drawNonzeroRational() {
  const int magnitude = *rc::gen::inRange(1, 41);
  return Rational(*rc::gen::arbitrary<bool>() ? magnitude : -magnitude, *rc::gen::inRange(1, 9));
}

/// Up to four distinct rationals that polynomials drawn together pick their roots from,
/// so that they share roots.
std::vector<Rational> drawRootPool() {
  std::vector<Rational> pool(*rc::gen::inRange(1, 5));
  for (Rational& root : pool) root = drawRational();
  std::sort(pool.begin(), pool.end());
  pool.erase(std::unique(pool.begin(), pool.end()), pool.end());
  return pool;
}

KnownPolynomial drawKnownPolynomial(const std::vector<Rational>& pool) {
  KnownPolynomial known;
  known.scale = drawNonzeroRational();
  for (const Rational& root : pool) {
    const int multiplicity = *rc::gen::inRange(0, 3);
    if (multiplicity > 0) known.linearFactors[root] = multiplicity;
  }
  known.sqrtTwoMultiplicity = *rc::gen::inRange(0, 3);
  known.positiveOffset = *rc::gen::inRange(0, 3);  // t^2 + 1 or t^2 + 2: often shared
  return known;
}

/// An interval whose ends are often roots from the pool.
std::pair<Rational, Rational> drawInterval(const std::vector<Rational>& pool) {
  const auto drawEnd = [&pool]() {
    return *rc::gen::arbitrary<bool>() ? pool[*rc::gen::inRange<std::size_t>(0, pool.size())] : drawRational();
  };
  Rational lo = drawEnd();
  Rational hi = drawEnd();
  if (hi < lo) std::swap(lo, hi);
  return {lo, hi};
}

// Wide enough for every root drawn above.
const Rational kFarLeft(-100);
const Rational kFarRight(100);

// ---------------------------------------------------------------------------------
// Properties

RC_GTEST_PROP(ExactPolynomialProperty, IsolatesExactlyTheKnownRootsInOrder, ()) {
  const std::vector<Rational> pool = drawRootPool();
  const KnownPolynomial known = drawKnownPolynomial(pool);
  const auto [lo, hi] = drawInterval(pool);
  const std::vector<KnownRoot> expected = known.rootsIn(lo, hi);

  const std::vector<IsolatingInterval> roots = isolateRoots(known.expanded(), lo, hi);
  RC_ASSERT(roots.size() == expected.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    RC_ASSERT(contains(roots[i], expected[i]));
    RC_ASSERT(isolatesOneRoot(roots[i], known));
    RC_ASSERT(lo <= roots[i].lo);
    RC_ASSERT(roots[i].hi <= hi);
    if (i > 0) RC_ASSERT(roots[i - 1].hi <= roots[i].lo);
  }
}

RC_GTEST_PROP(ExactPolynomialProperty, SturmCountsTheKnownRootsInTheHalfOpenInterval, ()) {
  const std::vector<Rational> pool = drawRootPool();
  const KnownPolynomial known = drawKnownPolynomial(pool);
  const auto [lo, hi] = drawInterval(pool);
  const std::vector<KnownRoot> inClosed = known.rootsIn(lo, hi);
  const auto expected = std::count_if(inClosed.begin(), inClosed.end(),
                                      [&lo = lo](const KnownRoot& x) { return compareKnown({lo}, x) < 0; });

  const std::vector<RationalPolynomial> sturm = sturmSequence(known.squareFreeFactors().expanded());
  RC_ASSERT(countDistinctRoots(sturm, lo, hi) == expected);
}

RC_GTEST_PROP(ExactPolynomialProperty, SquareFreePartKeepsEachRootOnce, ()) {
  const KnownPolynomial known = drawKnownPolynomial(drawRootPool());
  RC_ASSERT(squareFreePart(known.expanded()).coefficients() == known.squareFreeFactors().expanded().coefficients());
}

RC_GTEST_PROP(ExactPolynomialProperty, GcdIsTheMonicProductOfTheSharedFactors, ()) {
  const std::vector<Rational> pool = drawRootPool();
  const KnownPolynomial f = drawKnownPolynomial(pool);
  const KnownPolynomial g = drawKnownPolynomial(pool);
  const RationalPolynomial expected = commonFactors(f, g).expanded();
  RC_ASSERT(gcd(f.expanded(), g.expanded()).coefficients() == expected.coefficients());
  RC_ASSERT(gcd(g.expanded(), f.expanded()).coefficients() == expected.coefficients());

  KnownPolynomial fMonic = f;
  fMonic.scale = 1;
  RC_ASSERT(gcd(f.expanded(), RationalPolynomial()).coefficients() == fMonic.expanded().coefficients());
}

RC_GTEST_PROP(ExactPolynomialProperty, DivisionGivesTheConstructedQuotientAndRemainder, ()) {
  const auto drawPolynomial = [](int size) {
    std::vector<Rational> coefficients(size);
    for (Rational& c : coefficients) c = drawRational();
    return coefficients;
  };
  std::vector<Rational> divisorCoefficients = drawPolynomial(*rc::gen::inRange(1, 6));
  divisorCoefficients.back() = drawNonzeroRational();
  const RationalPolynomial divisor(std::move(divisorCoefficients));
  std::vector<Rational> quotientCoefficients = drawPolynomial(*rc::gen::inRange(1, 5));
  quotientCoefficients.back() = drawNonzeroRational();
  const RationalPolynomial quotient(std::move(quotientCoefficients));
  const RationalPolynomial remainder(drawPolynomial(static_cast<int>(divisor.size()) - 1));  // may end in zeros

  const PolynomialDivision division = divide(plus(times(quotient, divisor), remainder), divisor);
  RC_ASSERT(division.quotient.coefficients() == quotient.coefficients());
  RC_ASSERT(samePolynomial(division.remainder, remainder));
  const bool remainderIsTrimmed = division.remainder.size() == 0 || division.remainder.coefficients().back() != 0;
  RC_ASSERT(remainderIsTrimmed);
}

RC_GTEST_PROP(ExactPolynomialProperty, BisectKeepsTheRootAndHalvesTheInterval, ()) {
  const KnownPolynomial known = drawKnownPolynomial(drawRootPool());
  const std::vector<KnownRoot> expected = known.rootsIn(kFarLeft, kFarRight);
  const std::vector<IsolatingInterval> roots = isolateRoots(known.expanded(), kFarLeft, kFarRight);
  RC_ASSERT(roots.size() == expected.size());
  const RationalPolynomial squareFree = known.squareFreeFactors().expanded();
  for (std::size_t i = 0; i < roots.size(); ++i) {
    IsolatingInterval halved = roots[i];
    bisect(squareFree, halved);
    RC_ASSERT(contains(halved, expected[i]));
    RC_ASSERT(isolatesOneRoot(halved, known));
    if (!roots[i].isExact() && !halved.isExact()) RC_ASSERT(halved.hi - halved.lo == (roots[i].hi - roots[i].lo) / 2);
  }
}

RC_GTEST_PROP(ExactPolynomialProperty, SignAtRootIsTheSignAtTheKnownRoot, ()) {
  const std::vector<Rational> pool = drawRootPool();
  const KnownPolynomial f = drawKnownPolynomial(pool);
  const KnownPolynomial g = drawKnownPolynomial(pool);
  const std::vector<KnownRoot> gRoots = g.rootsIn(kFarLeft, kFarRight);
  const std::vector<IsolatingInterval> intervals = isolateRoots(g.expanded(), kFarLeft, kFarRight);
  RC_ASSERT(intervals.size() == gRoots.size());
  for (std::size_t i = 0; i < gRoots.size(); ++i) {
    RC_ASSERT(signAtRoot(f.expanded(), g.expanded(), intervals[i]) == f.signAt(gRoots[i]));
  }
}

RC_GTEST_PROP(ExactPolynomialProperty, CompareRootsMatchesTheKnownOrder, ()) {
  const std::vector<Rational> pool = drawRootPool();
  const KnownPolynomial f = drawKnownPolynomial(pool);
  const KnownPolynomial g = drawKnownPolynomial(pool);
  const std::vector<KnownRoot> fRoots = f.rootsIn(kFarLeft, kFarRight);
  const std::vector<KnownRoot> gRoots = g.rootsIn(kFarLeft, kFarRight);
  // Narrower search intervals than g's make f's isolating intervals differ from g's.
  const std::vector<IsolatingInterval> fIntervals = isolateRoots(f.expanded(), Rational(-50), Rational(50));
  const std::vector<IsolatingInterval> gIntervals = isolateRoots(g.expanded(), kFarLeft, kFarRight);
  RC_ASSERT(fIntervals.size() == fRoots.size());
  RC_ASSERT(gIntervals.size() == gRoots.size());
  for (std::size_t i = 0; i < fRoots.size(); ++i) {
    for (std::size_t j = 0; j < gRoots.size(); ++j) {
      RC_ASSERT(compareRoots(f.expanded(), fIntervals[i], g.expanded(), gIntervals[j]) ==
                compareKnown(fRoots[i], gRoots[j]));
    }
  }
}

// ---------------------------------------------------------------------------------
// Unit tests

TEST(ExactPolynomial, ZeroPolynomial) {
  const RationalPolynomial zero;
  const RationalPolynomial zeros({0, 0, 0});
  EXPECT_EQ(degree(zero), -1);
  EXPECT_EQ(degree(zeros), -1);
  EXPECT_TRUE(isZero(zeros));
  EXPECT_EQ(trimmed(zeros).size(), 0u);
  EXPECT_EQ(zeros.evaluate(Rational(3)), 0);
  EXPECT_EQ(signAt(zero, Rational(1, 3)), Sign::Zero);
  EXPECT_EQ(zeros.derivative().size(), 2u);
  EXPECT_EQ(zero.derivative().size(), 0u);
  EXPECT_TRUE(isZero(gcd(zero, zeros)));
  EXPECT_TRUE(isZero(squareFreePart(zeros)));
  EXPECT_THROW(isolateRoots(zeros, -1, 1), std::invalid_argument);
  EXPECT_THROW(sturmSequence(zero), std::invalid_argument);
  EXPECT_THROW(divide(linearFactor(1), zeros), std::invalid_argument);

  // The zero polynomial vanishes at every root; a zero g or f has no roots to compare.
  const RationalPolynomial g = quadratic(-2);
  const IsolatingInterval sqrtTwo{1, 2};
  EXPECT_EQ(signAtRoot(zeros, g, sqrtTwo), Sign::Zero);
  EXPECT_THROW(signAtRoot(g, zeros, sqrtTwo), std::invalid_argument);
  EXPECT_THROW(compareRoots(zeros, sqrtTwo, g, sqrtTwo), std::invalid_argument);
}

TEST(ExactPolynomial, ConstantPolynomials) {
  const RationalPolynomial minusSeven({-7, 0});
  EXPECT_EQ(degree(minusSeven), 0);
  EXPECT_EQ(trimmed(minusSeven).coefficients(), std::vector<Rational>{-7});
  EXPECT_EQ(signAt(minusSeven, Rational(5)), Sign::Negative);
  EXPECT_EQ(squareFreePart(minusSeven).coefficients(), std::vector<Rational>{1});
  EXPECT_EQ(gcd(minusSeven, RationalPolynomial()).coefficients(), std::vector<Rational>{1});
  EXPECT_EQ(gcd(minusSeven, linearFactor(3)).coefficients(), std::vector<Rational>{1});
  EXPECT_TRUE(isolateRoots(minusSeven, -10, 10).empty());
  EXPECT_EQ(countDistinctRoots(sturmSequence(minusSeven), -10, 10), 0);

  const PolynomialDivision division = divide(RationalPolynomial({1, 2, 3}), minusSeven);
  EXPECT_EQ(division.quotient.coefficients(),
            (std::vector<Rational>{Rational(-1, 7), Rational(-2, 7), Rational(-3, 7)}));
  EXPECT_TRUE(isZero(division.remainder));

  const IsolatingInterval sqrtTwo{1, 2};
  EXPECT_EQ(signAtRoot(minusSeven, quadratic(-2), sqrtTwo), Sign::Negative);
}

TEST(ExactPolynomial, SturmCountsOverHalfOpenIntervals) {
  const std::vector<RationalPolynomial> sturm = sturmSequence(times(linearFactor(0), linearFactor(1)));  // roots 0, 1
  EXPECT_EQ(countDistinctRoots(sturm, -1, 1), 2);
  EXPECT_EQ(countDistinctRoots(sturm, 0, 1), 1);   // 1 but not 0
  EXPECT_EQ(countDistinctRoots(sturm, -1, 0), 1);  // 0
  EXPECT_EQ(countDistinctRoots(sturm, 0, 0), 0);
  EXPECT_EQ(countDistinctRoots(sturm, Rational(1, 3), Rational(2, 3)), 0);
  EXPECT_THROW(countDistinctRoots(sturm, 1, 0), std::invalid_argument);
}

TEST(ExactPolynomial, IsolatesFourRootsAThousandthApart) {
  const std::vector<Rational> knownRoots{Rational(1, 2), Rational(501, 1000), Rational(502, 1000), Rational(503, 1000)};
  RationalPolynomial p = constant(Rational(-3, 5));
  for (const Rational& root : knownRoots) p = times(p, linearFactor(root));

  const std::vector<IsolatingInterval> roots = isolateRoots(p, 0, 1);
  ASSERT_EQ(roots.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_LE(roots[i].lo, knownRoots[i]);
    EXPECT_LE(knownRoots[i], roots[i].hi);
    if (!roots[i].isExact()) {
      // Only this root in between.
      for (const Rational& other : knownRoots) {
        if (other != knownRoots[i]) {
          EXPECT_TRUE(other <= roots[i].lo || roots[i].hi <= other);
        }
      }
    }
    if (i > 0) {
      EXPECT_EQ(compareRoots(p, roots[i - 1], p, roots[i]), -1);
    }
    EXPECT_EQ(compareRoots(p, roots[i], linearFactor(knownRoots[i]), {knownRoots[i], knownRoots[i]}), 0);
    EXPECT_EQ(signAtRoot(linearFactor(Rational(5005, 10000)), p, roots[i]), i == 0 ? Sign::Negative : Sign::Positive);
  }
}

TEST(ExactPolynomial, SeparatesSqrtTwoFromRationalsAThousandthAway) {
  // 1.414 < sqrt(2) = 1.41421... < 1.415, all roots of one quartic.
  const RationalPolynomial p =
      times(times(linearFactor(Rational(1414, 1000)), linearFactor(Rational(1415, 1000))), quadratic(-2));
  const std::vector<IsolatingInterval> roots = isolateRoots(p, 0, 2);
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_TRUE(contains(roots[0], {Rational(1414, 1000)}));
  EXPECT_TRUE(contains(roots[1], {0, 1}));
  EXPECT_TRUE(contains(roots[2], {Rational(1415, 1000)}));

  // The same irrational root isolated in another polynomial, by a different interval.
  const RationalPolynomial q = times(quadratic(-2), linearFactor(7));
  const IsolatingInterval sqrtTwoOfQ{1, 2};
  EXPECT_EQ(compareRoots(p, roots[1], q, sqrtTwoOfQ), 0);
  EXPECT_EQ(compareRoots(p, roots[0], q, sqrtTwoOfQ), -1);
  EXPECT_EQ(compareRoots(q, sqrtTwoOfQ, p, roots[2]), -1);
  EXPECT_EQ(signAtRoot(q, p, roots[1]), Sign::Zero);
  EXPECT_EQ(signAtRoot(linearFactor(Rational(14142, 10000)), p, roots[1]), Sign::Positive);
  EXPECT_EQ(signAtRoot(linearFactor(Rational(14143, 10000)), p, roots[1]), Sign::Negative);
}

TEST(ExactPolynomial, BisectHalvesOrLandsOnTheRoot) {
  const RationalPolynomial sqrtTwo = quadratic(-2);
  IsolatingInterval root{1, 2};
  bisect(sqrtTwo, root);  // 1.5^2 > 2
  EXPECT_EQ(root.lo, 1);
  EXPECT_EQ(root.hi, Rational(3, 2));
  bisect(sqrtTwo, root);  // 1.25^2 < 2
  EXPECT_EQ(root.lo, Rational(5, 4));
  EXPECT_EQ(root.hi, Rational(3, 2));

  const RationalPolynomial threeHalves = linearFactor(Rational(3, 2));
  IsolatingInterval exact{1, 2};
  bisect(threeHalves, exact);
  EXPECT_TRUE(exact.isExact());
  EXPECT_EQ(exact.lo, Rational(3, 2));
  bisect(threeHalves, exact);
  EXPECT_EQ(exact.lo, Rational(3, 2));
  EXPECT_EQ(exact.hi, Rational(3, 2));
}

TEST(ExactPolynomial, RootsAtTheEndsOfTheSearchAreExact) {
  // (t + 1)^2 (t - 1) t: roots -1 and 1 at the ends, 0 at the first midpoint.
  const RationalPolynomial p =
      times(times(times(linearFactor(-1), linearFactor(-1)), linearFactor(1)), linearFactor(0));
  const std::vector<IsolatingInterval> roots = isolateRoots(p, -1, 1);
  ASSERT_EQ(roots.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(roots[i].isExact());
    EXPECT_EQ(roots[i].lo, static_cast<int>(i) - 1);
  }
  const std::vector<IsolatingInterval> single = isolateRoots(p, 1, 1);
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].lo, 1);
  EXPECT_TRUE(isolateRoots(p, Rational(1, 2), Rational(1, 2)).empty());
  EXPECT_THROW(isolateRoots(p, 1, -1), std::invalid_argument);
}

TEST(ExactPolynomial, EvaluatesAndDifferentiates) {
  const RationalPolynomial p({1, -3, 0, 2});  // 2t^3 - 3t + 1
  EXPECT_EQ(p.size(), 4u);
  EXPECT_EQ(p.evaluate(Rational(1, 2)), Rational(-1, 4));
  EXPECT_EQ(p.derivative().coefficients(), (std::vector<Rational>{-3, 0, 6}));
}

TEST(ExactPolynomial, EvaluatesGenericallyInIntervalTypes) {
  {
    const RoundingScope rounding;
    const Polynomial<Interval> p({Interval(-2), Interval(0), Interval(1)});  // t^2 - 2
    const Interval nearSqrtTwo(1.41421, 1.41422);
    const Interval atSqrtTwo = p.evaluate(nearSqrtTwo);
    EXPECT_LT(atSqrtTwo.lower(), 0);
    EXPECT_GT(atSqrtTwo.upper(), 0);
    EXPECT_EQ(certainSign(p.evaluate(Interval(3))), Sign::Positive);
    const Polynomial<Interval> derivative = p.derivative();
    ASSERT_EQ(derivative.size(), 2u);
    EXPECT_EQ(derivative.coefficients()[1].lower(), 2);
    EXPECT_EQ(derivative.coefficients()[1].upper(), 2);

    const Polynomial<double> q({-2, 0, 1});  // double coefficients at an interval
    EXPECT_EQ(certainSign(q.evaluate(Interval(1.5))), Sign::Positive);
    EXPECT_EQ(certainSign(q.evaluate(Interval(1.25, 1.375))), Sign::Negative);
  }
  using Mpfi = boost::multiprecision::number<boost::multiprecision::mpfi_float_backend<50>>;
  const Polynomial<Mpfi> p({Mpfi(-2), Mpfi(0), Mpfi(1)});
  const Mpfi atSqrtTwo = p.evaluate(sqrt(Mpfi(2)));
  EXPECT_LE(lower(atSqrtTwo), 0);
  EXPECT_GE(upper(atSqrtTwo), 0);
  EXPECT_LT(upper(atSqrtTwo) - lower(atSqrtTwo), 1e-40);
  const Polynomial<Rational> exact({-2, 0, 1});  // rational coefficients at an MPFI interval
  EXPECT_GT(lower(exact.evaluate(Mpfi(3, 4))), 6);
}

}  // namespace
}  // namespace freespace
