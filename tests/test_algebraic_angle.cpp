// Algebraic angles: roots of angle functions, their order and the sign of another
// function at them, against closed-form trigonometry (well away from degeneracy)
// and against constructed degeneracies whose answers are known by construction:
// shared roots, double roots, roots at the chart boundaries and at theta = pi,
// functions that vanish identically, integer inputs.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <type_traits>

#include "freespace/numbers/algebraic_angle.h"
#include "freespace/numbers/angle_polynomial.h"

using namespace freespace;

namespace {

int uniform(int low, int high) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(low, high)); }

/// k1 sin + k2 cos + k3.
struct Form {
  double k1, k2, k3;
  long double at(long double theta) const { return k1 * std::sin(theta) + k2 * std::cos(theta) + k3; }
};

/// The product of forms as an angle function.
std::shared_ptr<const AngleFunction> productOf(const std::vector<Form>& forms) {
  return std::make_shared<AngleFunction>([forms](auto type, int chart) {
    using T = typename decltype(type)::type;
    Polynomial<T> product({T(1)});
    for (const Form& form : forms) product = product * tangentPolynomial(edgeFacetForm(T(form.k1), T(form.k2), T(form.k3)), chart);
    return product;
  });
}

Form randomForm(int range) {
  return {static_cast<double>(uniform(-range, range + 1)), static_cast<double>(uniform(-range, range + 1)),
          static_cast<double>(uniform(-range, range + 1))};
}

/// Closed-form roots of k1 sin + k2 cos + k3 = 0: R cos(theta - phi) = -k3.
std::vector<long double> referenceRoots(const Form& form) {
  const long double radius = std::hypot(static_cast<long double>(form.k1), static_cast<long double>(form.k2));
  const long double phi = std::atan2(static_cast<long double>(form.k1), static_cast<long double>(form.k2));
  const long double spread = std::acos(-form.k3 / radius);
  return {phi - spread, phi + spread};
}

long double angularDistance(long double a, long double b) {
  return std::fabs(std::remainder(a - b, 2 * static_cast<long double>(M_PI)));
}

}  // namespace

RC_GTEST_PROP(AlgebraicAngle, RootsOfAFormMatchClosedFormTrigonometry, ()) {
  const Form form = randomForm(8);
  const long double radius = std::hypot(form.k1, form.k2);
  RC_PRE(radius > 0 && std::fabs(std::fabs(form.k3) - radius) > 1e-6);  // not tangent
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const std::vector<AlgebraicAngle> roots = algebra.roots(productOf({form}), PredicateKind::EdgeFacet);
  if (std::fabs(form.k3) > radius) {
    RC_ASSERT(roots.empty());
    return;
  }
  RC_ASSERT(roots.size() == 2u);
  for (const AlgebraicAngle& root : roots) {
    const auto reference = referenceRoots(form);
    RC_ASSERT(std::min(angularDistance(root.radians(), reference[0]), angularDistance(root.radians(), reference[1])) <
              1e-9);
  }
  RC_ASSERT(algebra.compare(roots[0], roots[1]) == -1);
  RC_ASSERT(algebra.compare(roots[1], roots[0]) == 1);
  RC_ASSERT(algebra.compare(roots[0], roots[0]) == 0);
}

RC_GTEST_PROP(AlgebraicAngle, SharedRootsCompareEqualAndVanish, ()) {
  const Form shared = randomForm(6), second = randomForm(6), third = randomForm(6);
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const auto sharedFunction = productOf({shared});
  RC_PRE(!sharedFunction->isIdenticallyZero() && !productOf({second})->isIdenticallyZero() &&
         !productOf({third})->isIdenticallyZero());
  const auto f = productOf({shared, second});
  const auto g = productOf({third, shared});
  const std::vector<AlgebraicAngle> fRoots = algebra.roots(f, PredicateKind::ThreePatch);
  const std::vector<AlgebraicAngle> gRoots = algebra.roots(g, PredicateKind::ThreePatch);
  for (const AlgebraicAngle& root : algebra.roots(sharedFunction, PredicateKind::EdgeFacet)) {
    // The shared root appears among the roots of f and of g, exactly once each.
    int inF = 0, inG = 0;
    for (const AlgebraicAngle& other : fRoots) inF += algebra.compare(root, other) == 0;
    for (const AlgebraicAngle& other : gRoots) inG += algebra.compare(root, other) == 0;
    RC_ASSERT(inF == 1);
    RC_ASSERT(inG == 1);
    RC_ASSERT(algebra.signAt(*f, root) == Sign::Zero);
    RC_ASSERT(algebra.signAt(*g, root) == Sign::Zero);
  }
  // f and g roots are distinct within each list and sorted.
  for (std::size_t i = 1; i < fRoots.size(); ++i) RC_ASSERT(algebra.compare(fRoots[i - 1], fRoots[i]) == -1);
}

RC_GTEST_PROP(AlgebraicAngle, SignAtRootMatchesTrigonometryAwayFromZero, ()) {
  const Form form = randomForm(8), other = randomForm(8);
  const long double radius = std::hypot(form.k1, form.k2);
  RC_PRE(radius > 0 && std::fabs(form.k3) < radius - 1e-6);
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const auto otherFunction = productOf({other});
  RC_PRE(!otherFunction->isIdenticallyZero());
  for (const AlgebraicAngle& root : algebra.roots(productOf({form}), PredicateKind::EdgeFacet)) {
    const long double value = other.at(root.radians());
    if (std::fabs(value) < 1e-6) continue;  // too close to call for the reference
    RC_ASSERT(algebra.signAt(*otherFunction, root) == (value > 0 ? Sign::Positive : Sign::Negative));
  }
}

RC_GTEST_PROP(AlgebraicAngle, DoubleRootsAreFoundOnce, ()) {
  const Form form = randomForm(6);
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const auto single = productOf({form});
  RC_PRE(!single->isIdenticallyZero());
  const std::vector<AlgebraicAngle> simple = algebra.roots(single, PredicateKind::EdgeFacet);
  const std::vector<AlgebraicAngle> doubled = algebra.roots(productOf({form, form}), PredicateKind::ThreePatch);
  RC_ASSERT(simple.size() == doubled.size());
  for (std::size_t i = 0; i < simple.size(); ++i) RC_ASSERT(algebra.compare(simple[i], doubled[i]) == 0);
}

TEST(AlgebraicAngle, RootsAtChartBoundariesAndAtPi) {
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  // sin = 0 at theta = 0 (chart 0, t = 0) and theta = pi (chart 1, t = 0).
  const auto sine = algebra.roots(productOf({{1, 0, 0}}), PredicateKind::EdgeFacet);
  ASSERT_EQ(sine.size(), 2u);
  EXPECT_EQ(algebra.compare(sine[0], AlgebraicAngle::rational(HalfAngle::fromRadians(0))), 0);
  EXPECT_EQ(algebra.compare(sine[1], AlgebraicAngle::rational(HalfAngle::fromRadians(M_PI))), 0);
  EXPECT_EQ(algebra.compare(sine[1], AlgebraicAngle::rational(HalfAngle::fromRadians(-M_PI))), 0);
  // cos = 0 at theta = -pi/2 and pi/2: chart 0, t = -1 and 1, not repeated in chart 1.
  const auto cosine = algebra.roots(productOf({{0, 1, 0}}), PredicateKind::EdgeFacet);
  ASSERT_EQ(cosine.size(), 2u);
  EXPECT_EQ(cosine[0].chart(), 0);
  EXPECT_EQ(cosine[0].root().lo, -1);
  EXPECT_EQ(cosine[1].root().hi, 1);
  // cos + 1 = 0 touches zero at theta = pi only: one (double) root.
  const auto touching = algebra.roots(productOf({{0, 1, 1}}), PredicateKind::EdgeFacet);
  ASSERT_EQ(touching.size(), 1u);
  EXPECT_EQ(algebra.compare(touching[0], AlgebraicAngle::rational(HalfAngle::fromRadians(M_PI))), 0);
  EXPECT_EQ(algebra.signAt(*productOf({{1, 0, 0}}), touching[0]), Sign::Zero);
  // 3 sin + 4 cos = 5 touches at one irrational angle; it vanishes there and the
  // sign of 3 sin + 4 cos - 5 + 1e-9 there is positive.
  const auto tangent = algebra.roots(productOf({{3, 4, -5}}), PredicateKind::EdgeFacet);
  ASSERT_EQ(tangent.size(), 1u);
  EXPECT_NEAR(tangent[0].radians(), std::atan2(3.0, 4.0), 1e-12);
  EXPECT_EQ(algebra.signAt(*productOf({{3, 4, -5}}), tangent[0]), Sign::Zero);
  EXPECT_EQ(algebra.signAt(*productOf({{3, 4, -5 + 1e-9}}), tangent[0]), Sign::Positive);
  EXPECT_THROW(algebra.roots(productOf({{0, 0, 0}}), PredicateKind::EdgeFacet), std::invalid_argument);
  EXPECT_GT(statistics.counts(PredicateKind::SignAtRoot).identities, 0u);
  // The double root and the vanishing signs left double intervals: their time counts.
  EXPECT_GT(statistics.counts(PredicateKind::EdgeFacet).escalatedSeconds, 0.0);
  EXPECT_GT(statistics.counts(PredicateKind::SignAtRoot).escalatedSeconds, 0.0);
}

TEST(AlgebraicAngle, ArcsWrapThroughTheCut) {
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const auto at = [](double theta) { return AlgebraicAngle::rational(HalfAngle::fromRadians(theta)); };
  const AngleInterval throughPi{at(3 * M_PI / 4), at(-3 * M_PI / 4)};
  EXPECT_TRUE(algebra.contains(throughPi, at(M_PI)));
  EXPECT_TRUE(algebra.contains(throughPi, at(-0.9 * M_PI)));
  EXPECT_FALSE(algebra.contains(throughPi, at(0)));
  const AngleInterval throughCut{at(-M_PI / 4), at(-3 * M_PI / 4)};  // almost the whole circle
  EXPECT_TRUE(algebra.contains(throughCut, at(M_PI)));
  EXPECT_TRUE(algebra.contains(throughCut, at(0)));
  EXPECT_FALSE(algebra.contains(throughCut, at(-M_PI / 2)));
  EXPECT_TRUE(algebra.contains(throughCut, at(-M_PI / 4)));
}

RC_GTEST_PROP(AlgebraicAngle, QuarticRootsAreTheMergedRootsOfItsFactors, ()) {
  const Form first = randomForm(9), second = randomForm(9);
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const auto firstFunction = productOf({first}), secondFunction = productOf({second});
  RC_PRE(!firstFunction->isIdenticallyZero() && !secondFunction->isIdenticallyZero());
  std::vector<AlgebraicAngle> expected = algebra.roots(firstFunction, PredicateKind::EdgeFacet);
  for (const AlgebraicAngle& root : algebra.roots(secondFunction, PredicateKind::EdgeFacet)) {
    bool known = false;
    for (const AlgebraicAngle& other : expected) known = known || algebra.compare(root, other) == 0;
    if (!known) expected.push_back(root);
  }
  std::sort(expected.begin(), expected.end(),
            [&algebra](const AlgebraicAngle& a, const AlgebraicAngle& b) { return algebra.compare(a, b) < 0; });
  const std::vector<AlgebraicAngle> found = algebra.roots(productOf({first, second}), PredicateKind::ThreePatch);
  RC_ASSERT(found.size() == expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) RC_ASSERT(algebra.compare(found[i], expected[i]) == 0);
}

TEST(AlgebraicAngle, GenericQuarticsAreIsolatedInDoubles) {
  // Products of two forms with arbitrary (non-grid) coefficients: no degeneracy, so
  // doubles must decide every isolation.
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  std::size_t roots = 0;
  for (int i = 0; i < 200; ++i) {
    const Form a{std::sin(i + 0.1), std::cos(3.0 * i), 0.3 * std::sin(7.0 * i)};
    const Form b{std::cos(i + 0.7), 0.9 * std::sin(5.0 * i), 0.5 * std::cos(11.0 * i)};
    roots += algebra.roots(productOf({a, b}), PredicateKind::ThreePatch).size();
  }
  const auto& counts = statistics.counts(PredicateKind::ThreePatch);
  EXPECT_EQ(counts.decided[static_cast<int>(PrecisionLevel::DoubleInterval)], 400u);  // two charts each
  EXPECT_GT(roots, 400u);
}

namespace {

/// alpha = 1/sqrt(2), the root of 2 t^2 - 1 in chart 0, against a rational
/// d = high + low (a double-word) close to it: the sign of t - d at alpha and the
/// order of alpha and d, with the level that decided each. Exactly,
/// sign(alpha - d) = sign(1/2 - d^2) since both are positive.
void checkNearTie(double high, double low, PrecisionLevel expectedLevel) {
  const Rational d = Rational(high) + Rational(low);
  const Sign expected = exactSign(Rational(1, 2) - d * d);
  ASSERT_NE(expected, Sign::Zero);
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const auto halfSquare = std::make_shared<AngleFunction>([](auto type, int) {
    using T = typename decltype(type)::type;
    return Polynomial<T>({T(-1), T(0), T(2)});
  });
  const auto minusD = std::make_shared<AngleFunction>([high, low](auto type, int) {
    using T = typename decltype(type)::type;
    return Polynomial<T>({-(T(high) + T(low)), T(1)});
  });
  const std::vector<AlgebraicAngle> roots = algebra.roots(halfSquare, PredicateKind::Other);
  ASSERT_EQ(roots.size(), 4u);  // +-1/sqrt(2) in each chart
  const AlgebraicAngle& alpha = roots[1];
  ASSERT_EQ(alpha.chart(), 0);
  ASSERT_GT(alpha.lower(), 0);
  EXPECT_EQ(algebra.signAt(*minusD, alpha), expected);
  EXPECT_EQ(algebra.compare(alpha, AlgebraicAngle::rational(0, d)), static_cast<int>(expected));
  // Decided at the expected level (any of the MPFI precisions for Multiprecision).
  const int low = static_cast<int>(expectedLevel);
  const int high = expectedLevel == PrecisionLevel::Multiprecision ? static_cast<int>(PrecisionLevel::Exact) : low + 1;
  for (const PredicateKind kind : {PredicateKind::SignAtRoot, PredicateKind::RootOrder}) {
    const auto& decided = statistics.counts(kind).decided;
    EXPECT_EQ(std::accumulate(decided.begin() + low, decided.begin() + high, std::uint64_t{0}), 1u) << statistics.toText();
  }
}

}  // namespace

TEST(AlgebraicAngle, NearTiesBeyondDoublesAreDecidedInDoubleDoubles) {
  // d the double nearest to alpha: closer than doubles resolve (about 2^-54 away).
  checkNearTie(std::sqrt(0.5), 0.0, PrecisionLevel::DoubleDouble);
}

TEST(AlgebraicAngle, NearTiesBeyondDoubleDoublesAreDecidedInMultiprecision) {
  // d the double-word nearest to alpha: about 2^-107 away, past double-doubles.
  const double high = std::sqrt(0.5);
  const Rational rest = Rational(1, 2) - Rational(high) * Rational(high);  // (alpha - high)(alpha + high)
  const double low = (rest / (2 * Rational(high))).convert_to<double>();
  checkNearTie(high, low, PrecisionLevel::Multiprecision);
}

TEST(AlgebraicAngle, RootsNearAChartEndBeyondDoublesAreIsolatedInDoubleDoubles) {
  // (t - r)(t - 1/2) in chart 0 with r = -1 + 2^-60, just inside the chart's end:
  // its value at t = -1 is 1.5 * 2^-60, which double intervals (tight ones too)
  // cannot tell from zero, so Descartes' rule cannot start in doubles; in
  // double-double intervals every coefficient is exact. Chart 1 is 1 + t^2, with no
  // root (positive at both shared ends, as chart 0 is there). Exact coefficients
  // throw: the roots must be found without them.
  static constexpr double kOffset = 0x1p-60;
  const auto nearEnd = std::make_shared<AngleFunction>([](auto type, int chart) {
    using T = typename decltype(type)::type;
    if constexpr (std::is_same_v<T, Rational>) throw std::logic_error("exact coefficients asked for");
    if (chart == 1) return Polynomial<T>({T(1), T(0), T(1)});
    const T r = T(-1) + T(kOffset);
    return Polynomial<T>({r * T(0.5), -(r + T(0.5)), T(1)});
  });
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const std::vector<AlgebraicAngle> roots = algebra.roots(nearEnd, PredicateKind::Other);
  ASSERT_EQ(roots.size(), 2u);
  const Rational r = Rational(-1) + Rational(kOffset);
  for (const auto& [root, expected] : {std::pair{roots[0], r}, std::pair{roots[1], Rational(1, 2)}}) {
    EXPECT_EQ(root.chart(), 0);
    EXPECT_LE(Rational(root.lower()), expected);
    EXPECT_GE(Rational(root.upper()), expected);
  }
  EXPECT_LT(roots[0].upper(), roots[1].lower());
  // Narrowed in double-doubles too: doubles cannot refine the root next to the end.
  for (const AlgebraicAngle& root : roots) EXPECT_LE(root.upper() - root.lower(), 0x1p-40);
  const auto& decided = statistics.counts(PredicateKind::Other).decided;
  EXPECT_EQ(decided[static_cast<int>(PrecisionLevel::DoubleInterval)], 1u) << statistics.toText();  // chart 1
  EXPECT_EQ(decided[static_cast<int>(PrecisionLevel::DoubleDouble)], 1u);  // chart 0
  EXPECT_EQ(decided[static_cast<int>(PrecisionLevel::Exact)], 0u);
}

TEST(AlgebraicAngle, CosSinEnclosuresOfAWideEnclosureHoldTheWholeRange) {
  // A root known only to lie somewhere in chart 0 (t in [-1, 1], theta in
  // [-pi/2, pi/2]): cos in [0, 1] and sin in [-1, 1] there, and t^2 is not negative.
  const auto function = std::make_shared<AngleFunction>([](auto type, int) {
    using T = typename decltype(type)::type;
    return Polynomial<T>({T(0), T(1)});
  });
  const AlgebraicAngle wide(function, 0, -1.0, 1.0, 0);
  RoundingScope rounding;
  const auto [cosine, sine] = cosSinEnclosure(wide);
  EXPECT_LE(cosine.lower(), 0.0);
  EXPECT_GE(cosine.upper(), 1.0);
  EXPECT_LE(sine.lower(), -1.0);
  EXPECT_GE(sine.upper(), 1.0);
}

TEST(AlgebraicAngle, RootsApartByAFewUlpsAreToldApartByTightCoefficients) {
  // t - a and t - b with b 64 ulps above a, each coefficient computed as
  // (1000 + a) - 1000: in double intervals about 1e-13 wide, which hides the order;
  // in double-double intervals exact, so the tight coefficients decide without
  // rationals (the exact coefficients throw).
  const double a = 0.3, b = a + 64 * (std::nextafter(a, 1.0) - a);
  const auto rootAt = [](double value) {
    return std::make_shared<AngleFunction>([value](auto type, int) {
      using T = typename decltype(type)::type;
      if constexpr (std::is_same_v<T, Rational>) throw std::logic_error("exact coefficients asked for");
      return Polynomial<T>({T(1000) - (T(1000) + T(value)), T(1)});
    });
  };
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const std::vector<AlgebraicAngle> rootsA = algebra.roots(rootAt(a), PredicateKind::Other);
  const std::vector<AlgebraicAngle> rootsB = algebra.roots(rootAt(b), PredicateKind::Other);
  ASSERT_EQ(rootsA.size(), 2u);  // one in each chart
  ASSERT_EQ(rootsB.size(), 2u);
  ASSERT_GT(rootsA[0].upper(), rootsB[0].lower());  // the double enclosures overlap
  EXPECT_EQ(algebra.compare(rootsA[0], rootsB[0]), -1);
  EXPECT_EQ(algebra.compare(rootsB[0], rootsA[0]), 1);
  const AlgebraicAngle between = algebra.rationalBetween(rootsA[0], rootsB[0]);
  EXPECT_EQ(algebra.compare(rootsA[0], between), -1);
  EXPECT_EQ(algebra.compare(between, rootsB[0]), -1);
  // The first comparison needs the tight coefficients; the enclosures it narrowed
  // are remembered by the functions, so the later ones start from them and are
  // decided in doubles.
  const auto& decided = statistics.counts(PredicateKind::RootOrder).decided;
  EXPECT_EQ(decided[static_cast<int>(PrecisionLevel::DoubleDouble)], 1u);
  EXPECT_EQ(decided[static_cast<int>(PrecisionLevel::Exact)], 0u);
  const std::optional<AngleFunction::NarrowEnclosure> remembered =
      rootsA[0].function()->rememberedEnclosure(0, rootsA[0].index());
  ASSERT_TRUE(remembered.has_value());
  EXPECT_LT(remembered->upper - remembered->lower, rootsA[0].upper() - rootsA[0].lower());
  EXPECT_LT(remembered->upper, b);  // narrowed until apart from b's root
}

TEST(AlgebraicAngle, RootsOneUlpApartAreToldApartWithoutRationals) {
  // t - a and t - b with b the double after a: no double enclosure separates them,
  // double-doubles do, without exact coefficients (they throw).
  const double a = 0.3, b = std::nextafter(a, 1.0);
  const auto rootAt = [](double value) {
    return std::make_shared<AngleFunction>([value](auto type, int) {
      using T = typename decltype(type)::type;
      if constexpr (std::is_same_v<T, Rational>) throw std::logic_error("exact coefficients asked for");
      return Polynomial<T>({(T(1000) - T(value)) - T(1000), T(1)});
    });
  };
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const AlgebraicAngle rootA = algebra.roots(rootAt(a), PredicateKind::Other).at(0);
  const AlgebraicAngle rootB = algebra.roots(rootAt(b), PredicateKind::Other).at(0);
  EXPECT_EQ(algebra.compare(rootA, rootB), -1);
  EXPECT_EQ(algebra.compare(rootB, rootA), 1);
  const AlgebraicAngle between = algebra.rationalBetween(rootA, rootB);
  ASSERT_TRUE(between.isRational());
  EXPECT_GT(between.root().lo, Rational(a));
  EXPECT_LT(between.root().lo, Rational(b));
  EXPECT_EQ(statistics.counts(PredicateKind::RootOrder).decided[static_cast<int>(PrecisionLevel::Exact)], 0u);
}

TEST(AlgebraicAngle, TinyFunctionsAreNotIdenticallyZeroWithoutRationals) {
  // (1 + c) - 1 for c = 1e-20: every double interval coefficient holds zero (the sum
  // rounds to 1), the double-doubles hold c exactly; no exact coefficients are needed
  // (they throw). The same with c = 0 vanishes identically, which only exact
  // coefficients can prove; the oracle is the exact polynomial.
  const auto constant = [](double c, bool exactAllowed) {
    return std::make_shared<AngleFunction>([c, exactAllowed](auto type, int) {
      using T = typename decltype(type)::type;
      if constexpr (std::is_same_v<T, Rational>) {
        if (!exactAllowed) throw std::logic_error("exact coefficients asked for");
      }
      return Polynomial<T>({(T(1) + T(c)) - T(1), (T(2) + T(c)) - T(2)});
    });
  };
  const auto tiny = constant(1e-20, false);
  for (const Interval& coefficient : tiny->approximate(0).coefficients()) {
    ASSERT_TRUE(coefficient.lower() <= 0 && coefficient.upper() >= 0);
  }
  EXPECT_FALSE(tiny->isIdenticallyZero());
  EXPECT_FALSE(isZero(constant(1e-20, true)->exact(0)));
  const auto zero = constant(0, true);
  EXPECT_TRUE(isZero(zero->exact(0)));
  EXPECT_TRUE(zero->isIdenticallyZero());
}

RC_GTEST_PROP(AlgebraicAngle, PositiveSetMatchesSampledTrigonometry, ()) {
  std::vector<Form> forms;
  const int count = *rc::gen::inRange(1, 4);
  for (int i = 0; i < count; ++i) forms.push_back(randomForm(5));
  std::vector<std::shared_ptr<const AngleFunction>> functions;
  for (const Form& form : forms) {
    functions.push_back(productOf({form}));
    RC_PRE(!functions.back()->isIdenticallyZero());
  }
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const AngleSet set = algebra.positiveSet(functions, PredicateKind::EdgeFacet);
  int decided = 0;
  for (int i = 0; i < 360; ++i) {
    const double theta = -M_PI + (i + 0.37) * (2 * M_PI / 360);
    long double smallest = 1e300L;
    bool allPositive = true;
    for (const Form& form : forms) {
      const long double value = form.at(theta);
      smallest = std::min(smallest, std::fabs(value));
      allPositive = allPositive && value > 0;
    }
    if (smallest < 1e-9) continue;  // too close to a boundary for the reference
    ++decided;
    RC_ASSERT(algebra.contains(set, AlgebraicAngle::rational(HalfAngle::fromRadians(theta))) == allPositive);
  }
  RC_ASSERT(decided > 300);
}

TEST(AlgebraicAngle, PositiveSetsAtTheirExtremes) {
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const auto at = [](double theta) { return AlgebraicAngle::rational(HalfAngle::fromRadians(theta)); };
  // Exactly +-pi/2 (t = +-1 in chart 0); the doubles M_PI / 2 are not.
  const AlgebraicAngle quarterTurn = AlgebraicAngle::rational(0, Rational(1));
  const AlgebraicAngle minusQuarterTurn = AlgebraicAngle::rational(0, Rational(-1));
  // cos + 2 > 0 everywhere; cos - 2 > 0 nowhere.
  EXPECT_TRUE(algebra.positiveSet({productOf({{0, 1, 2}})}, PredicateKind::EdgeFacet).fullCircle);
  EXPECT_TRUE(algebra.positiveSet({productOf({{0, 1, -2}})}, PredicateKind::EdgeFacet).empty());
  // cos + 1 > 0 everywhere but at pi: its closure is the full circle.
  EXPECT_TRUE(algebra.positiveSet({productOf({{0, 1, 1}})}, PredicateKind::EdgeFacet).fullCircle);
  // sin > 0 and cos > 0: the closed first quadrant [0, pi/2].
  const AngleSet quadrant = algebra.positiveSet({productOf({{1, 0, 0}}), productOf({{0, 1, 0}})}, PredicateKind::EdgeFacet);
  ASSERT_EQ(quadrant.arcs.size(), 1u);
  EXPECT_EQ(algebra.compare(quadrant.arcs[0].from, at(0)), 0);
  EXPECT_EQ(algebra.compare(quadrant.arcs[0].to, quarterTurn), 0);
  // -cos > 0: the arc from pi/2 through pi to -pi/2, which crosses theta = pi.
  const AngleSet back = algebra.positiveSet({productOf({{0, -1, 0}})}, PredicateKind::EdgeFacet);
  ASSERT_EQ(back.arcs.size(), 1u);
  EXPECT_TRUE(algebra.contains(back, at(M_PI)));
  EXPECT_TRUE(algebra.contains(back, minusQuarterTurn));
  EXPECT_TRUE(algebra.contains(back, quarterTurn));
  EXPECT_FALSE(algebra.contains(back, at(-M_PI / 2)));  // just past -pi/2, where cos > 0
  EXPECT_FALSE(algebra.contains(back, at(0)));
  // The open arcs: their ends are exactly excluded, inner angles stay.
  const auto open = AngleAlgebra::Boundary::Excluded;
  EXPECT_FALSE(algebra.contains(quadrant, at(0), open));
  EXPECT_FALSE(algebra.contains(quadrant, quarterTurn, open));
  EXPECT_TRUE(algebra.contains(quadrant, at(M_PI / 4), open));
  EXPECT_FALSE(algebra.contains(back, quarterTurn, open));
  EXPECT_FALSE(algebra.contains(back, minusQuarterTurn, open));
  EXPECT_TRUE(algebra.contains(back, at(M_PI), open));
  EXPECT_TRUE(algebra.contains(back, at(-0.51 * M_PI), open));
  EXPECT_TRUE(algebra.contains(algebra.positiveSet({productOf({{0, 1, 2}})}, PredicateKind::EdgeFacet), at(0), open));
  // A function that vanishes identically is positive nowhere.
  EXPECT_TRUE(algebra.positiveSet({productOf({{0, 1, 2}}), productOf({{0, 0, 0}})}, PredicateKind::EdgeFacet).empty());
  // cos > 0 and -cos > 0 share their boundary points only: empty.
  EXPECT_TRUE(algebra.positiveSet({productOf({{0, 1, 0}}), productOf({{0, -1, 0}})}, PredicateKind::EdgeFacet).empty());
}

TEST(AlgebraicAngle, RationalBetweenSeparatesCloseAndWrappingAngles) {
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const auto roots = algebra.roots(productOf({{3, 4, -5 + 1e-12}}), PredicateKind::EdgeFacet);  // two close roots
  ASSERT_EQ(roots.size(), 2u);
  const AlgebraicAngle inside = algebra.rationalBetween(roots[0], roots[1]);
  EXPECT_EQ(algebra.compare(roots[0], inside), -1);
  EXPECT_EQ(algebra.compare(inside, roots[1]), -1);
  // From the later root around the circle to the earlier one: outside both.
  const AlgebraicAngle around = algebra.rationalBetween(roots[1], roots[0]);
  EXPECT_TRUE(algebra.compare(around, roots[0]) < 0 || algebra.compare(around, roots[1]) > 0);
  EXPECT_THROW(algebra.rationalBetween(roots[0], roots[0]), std::invalid_argument);
}

RC_GTEST_PROP(AlgebraicAngle, FunctionsWithOneKeyShareTheirRootsByIndex, ()) {
  // A form and its negation, keyed alike: every pair of their roots compares as the
  // exact comparison (without the key) does, and equal roots are identities.
  const Form form = randomForm(1000);
  const Form negated{-form.k1, -form.k2, -form.k3};
  RC_PRE(form.k1 != 0 || form.k2 != 0);
  const AngleFunction::RootKey key{7, 1, 2, 3, 4, 5};
  const auto keyed = [&key](const Form& f) {
    return std::make_shared<AngleFunction>([f](auto type, int chart) {
      using T = typename decltype(type)::type;
      return tangentPolynomial(edgeFacetForm(T(f.k1), T(f.k2), T(f.k3)), chart);
    }, key);
  };
  PredicateStatistics keyedStatistics, plainStatistics;
  AngleAlgebra keyedAlgebra(keyedStatistics), plainAlgebra(plainStatistics);
  const auto first = keyedAlgebra.roots(keyed(form), PredicateKind::Other);
  const auto second = keyedAlgebra.roots(keyed(negated), PredicateKind::Other);
  const auto plainFirst = plainAlgebra.roots(productOf({form}), PredicateKind::Other);
  const auto plainSecond = plainAlgebra.roots(productOf({negated}), PredicateKind::Other);
  RC_ASSERT(first.size() == second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    for (std::size_t j = 0; j < second.size(); ++j) {
      RC_ASSERT(keyedAlgebra.compare(first[i], second[j]) == plainAlgebra.compare(plainFirst[i], plainSecond[j]));
    }
  }
  RC_ASSERT(keyedStatistics.counts(PredicateKind::RootOrder).identities >= first.size());
  // A keyed function vanishes at the roots of its own key, as the exact test finds.
  const double escalated = keyedStatistics.counts(PredicateKind::SignAtRoot).escalatedSeconds;
  for (std::size_t i = 0; i < first.size(); ++i) {
    RC_ASSERT(keyedAlgebra.signAt(*keyed(negated), first[i]) == Sign::Zero);
    RC_ASSERT(keyedAlgebra.signAt(*first[i].function(), first[i]) == Sign::Zero);
    RC_ASSERT(plainAlgebra.signAt(*productOf({negated}), plainFirst[i]) == Sign::Zero);
  }
  RC_ASSERT(keyedStatistics.counts(PredicateKind::SignAtRoot).escalatedSeconds == escalated);
}

/// Whether the root's double-double parameter, if it has one, holds the root: the
/// exact polynomial has opposite signs at the ends of its part inside the root's
/// isolating enclosure; and its radius is at most `maxRadius`. Returns whether it had
/// one.
bool checkDoubleDoubleParameter(const AngleFunction& function, const AlgebraicAngle& root, double maxRadius) {
  const std::optional<DoubleDoubleInterval> t = doubleDoubleParameter(root);
  if (!t) return false;  // a double root, say
  const Rational middle = Rational(t->high()) + Rational(t->low());
  const Rational low = std::max(middle - Rational(t->radius()), Rational(root.lower()));
  const Rational high = std::min(middle + Rational(t->radius()), Rational(root.upper()));
  RC_ASSERT(low < high);
  const RationalPolynomial& exact = function.exact(root.chart());
  const Sign atLow = signAt(exact, low), atHigh = signAt(exact, high);
  RC_ASSERT(atLow != Sign::Zero);
  RC_ASSERT(atLow == -atHigh);
  RC_ASSERT(t->radius() <= maxRadius);
  return true;
}

RC_GTEST_PROP(AlgebraicAngle, DoubleDoubleParametersHoldTheRootTightly, ()) {
  // Products of two forms with arbitrary coefficients (quartics, as FFF): each
  // simple root's parameter, refined in double-doubles to about 2^-78.
  const double scale = std::ldexp(1.0, uniform(-20, 21));
  const Form a{scale * uniform(-1000, 1001) / 7.0, scale * uniform(-1000, 1001) / 3.0, scale * uniform(-500, 501) / 11.0};
  const Form b{uniform(-1000, 1001) / 13.0, uniform(-1000, 1001) / 5.0, uniform(-500, 501) / 9.0};
  const auto function = productOf({a, b});
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  int refined = 0;
  for (const AlgebraicAngle& root : algebra.roots(function, PredicateKind::ThreePatch)) {
    refined += checkDoubleDoubleParameter(*function, root, 0x1p-78);
  }
  RC_TAG(refined > 0 ? "refined" : "none refined");
}

RC_GTEST_PROP(AlgebraicAngle, DoubleDoubleParametersHoldRootsWithANeighbourVeryNear, ()) {
  // A form times the same form moved by 2^-k (k from 30 to 60) of its constant: roots
  // in pairs, as close as doubles resolve, where Newton's iteration from the middle
  // of an enclosure may not settle and the parameter comes from bisection, as narrow
  // as the product's double-double values allow (never wider than the enclosure).
  const Form a{uniform(-1000, 1001) / 7.0, uniform(-1000, 1001) / 3.0, uniform(-500, 501) / 11.0};
  const Form b{a.k1, a.k2, a.k3 + std::ldexp(std::fabs(a.k3) + 1, -uniform(30, 61))};
  const auto function = productOf({a, b});
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  int refined = 0, roots = 0;
  for (const AlgebraicAngle& root : algebra.roots(function, PredicateKind::ThreePatch)) {
    ++roots;
    refined += checkDoubleDoubleParameter(*function, root, 0.5 * (root.upper() - root.lower()) * (1 + 0x1p-40));
  }
  RC_TAG(refined == roots ? "all refined" : "some not refined");
}

TEST(AlgebraicAngle, DoubleDoubleParametersOfRationalAnglesAreExact) {
  const DoubleDoubleInterval half = *doubleDoubleParameter(AlgebraicAngle::rational(0, 0.5));
  EXPECT_EQ(half.high(), 0.5);
  EXPECT_EQ(half.radius(), 0.0);
  const DoubleDoubleInterval third = *doubleDoubleParameter(AlgebraicAngle::rational(1, Rational(1, 3)));
  EXPECT_LE(Rational(third.high()) + Rational(third.low()) - Rational(third.radius()), Rational(1, 3));
  EXPECT_GE(Rational(third.high()) + Rational(third.low()) + Rational(third.radius()), Rational(1, 3));
}

// exactOnce gives the chart's exact polynomial, the one exact keeps: in chart 0, its
// sign at t is the sign of the forms' product at theta = 2 atan t.
TEST(AlgebraicAngle, ExactOnceIsTheExactPolynomial) {
  const std::vector<Form> forms{{3, 4, -5 + 1e-3}, {1, -2, 0.5}};
  const auto function = productOf(forms);
  const RationalPolynomial once = function->exactOnce(0);
  for (const double t : {-2.0, -0.75, -0.125, 0.0, 0.3, 0.9, 4.0}) {
    const long double theta = 2 * std::atan(static_cast<long double>(t));
    long double product = 1;
    for (const Form& form : forms) product *= form.at(theta);
    const Rational value = once.evaluate(Rational(t));
    EXPECT_EQ(value > 0, product > 0) << "t = " << t;
    EXPECT_EQ(value < 0, product < 0) << "t = " << t;
  }
  for (int chart = 0; chart < 2; ++chart) {
    EXPECT_EQ(function->exactOnce(chart).coefficients(), function->exact(chart).coefficients());
    EXPECT_EQ(function->exactOnce(chart).coefficients(), function->exact(chart).coefficients());  // kept now
  }
}
