// The double interval type against exact rational arithmetic: every result must
// contain the exact result for any points of the operands, and be tight (a few ulps).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "freespace/numbers/interval.h"
#include "freespace/numbers/rational.h"
#include "number_generators.h"

using namespace freespace;
using freespace::testing::anyDouble;

namespace {

Interval anyInterval() {
  const double a = anyDouble(), b = anyDouble();
  return Interval(std::min(a, b), std::max(a, b));
}

/// An interval on one side of zero, for divisors.
Interval nonzeroInterval() {
  const double near = std::fabs(anyDouble()) + 0.125, far = near + std::fabs(anyDouble());
  return *rc::gen::arbitrary<bool>() ? Interval(near, far) : Interval(-far, -near);
}

/// A point of the interval: an end or the midpoint.
Rational pointOf(const Interval& x) {
  switch (*rc::gen::inRange(0, 3)) {
    case 0: return Rational(x.lower());
    case 1: return Rational(x.upper());
    default: return (Rational(x.lower()) + Rational(x.upper())) / 2;
  }
}

bool holds(const Interval& result, const Rational& exact) {
  return Rational(result.lower()) <= exact && exact <= Rational(result.upper());
}

/// Not wider than a few ulps beyond the exact hull of the end-point results.
bool tight(const Interval& result, const Rational& low, const Rational& high) {
  const double slack = 4 * std::numeric_limits<double>::epsilon();
  const auto widen = [slack](const Rational& value) {
    return abs(value) * Rational(slack) + Rational(std::numeric_limits<double>::denorm_min());
  };
  return Rational(result.lower()) >= low - widen(low) && Rational(result.upper()) <= high + widen(high);
}

template <class Operation, class ExactOperation>
void checkOperation(Operation operation, ExactOperation exactOperation, bool division) {
  const Interval a = anyInterval(), b = division ? nonzeroInterval() : anyInterval();
  Interval result;
  {
    RoundingScope rounding;
    result = operation(a, b);
  }
  RC_ASSERT(holds(result, exactOperation(pointOf(a), pointOf(b))));
  Rational low, high;
  bool first = true;
  for (double x : {a.lower(), a.upper()}) {
    for (double y : {b.lower(), b.upper()}) {
      const Rational value = exactOperation(Rational(x), Rational(y));
      if (first || value < low) low = value;
      if (first || value > high) high = value;
      first = false;
    }
  }
  RC_ASSERT(holds(result, low));
  RC_ASSERT(holds(result, high));
  RC_ASSERT(tight(result, low, high));
}

}  // namespace

RC_GTEST_PROP(Interval, SumContainsTheExactSum, ()) {
  checkOperation([](const Interval& a, const Interval& b) { return a + b; },
                 [](const Rational& a, const Rational& b) -> Rational { return a + b; }, false);
}

RC_GTEST_PROP(Interval, DifferenceContainsTheExactDifference, ()) {
  checkOperation([](const Interval& a, const Interval& b) { return a - b; },
                 [](const Rational& a, const Rational& b) -> Rational { return a - b; }, false);
}

RC_GTEST_PROP(Interval, ProductContainsTheExactProduct, ()) {
  checkOperation([](const Interval& a, const Interval& b) { return a * b; },
                 [](const Rational& a, const Rational& b) -> Rational { return a * b; }, false);
}

RC_GTEST_PROP(Interval, QuotientContainsTheExactQuotient, ()) {
  checkOperation([](const Interval& a, const Interval& b) { return a / b; },
                 [](const Rational& a, const Rational& b) -> Rational { return a / b; }, true);
}

RC_GTEST_PROP(Interval, SquareRootBracketsTheRoot, ()) {
  const double value = std::fabs(anyDouble());
  Interval root;
  {
    RoundingScope rounding;
    root = sqrt(Interval(value));
  }
  RC_ASSERT(root.lower() >= 0);
  RC_ASSERT(Rational(root.lower()) * Rational(root.lower()) <= Rational(value));
  RC_ASSERT(Rational(root.upper()) * Rational(root.upper()) >= Rational(value));
}

TEST(Interval, SignsAndSpecialValues) {
  RoundingScope rounding;
  EXPECT_EQ(certainSign(Interval(0.1) * Interval(3.0) - Interval(0.3)), std::nullopt);  // 0.1 * 3 != 0.3
  EXPECT_EQ(certainSign(Interval(2.0) * Interval(3.0) - Interval(6.0)), Sign::Zero);
  EXPECT_EQ(certainSign(Interval(-1, 2) * Interval(0.0)), Sign::Zero);
  const double huge = std::numeric_limits<double>::max();
  const Interval overflow = Interval(huge) * Interval(huge) - Interval(huge) * Interval(huge);
  EXPECT_EQ(certainSign(overflow), std::nullopt);  // inf - inf is NaN: never certain
  EXPECT_EQ(certainSign(overflow * Interval(0.0)), std::nullopt);
  EXPECT_THROW(Interval(1.0) / Interval(-1, 1), std::domain_error);
}

TEST(Interval, RoundingScopeRestoresTheMode) {
  ASSERT_EQ(detail::roundingMode(), FE_TONEAREST);
  {
    RoundingScope outer;
    EXPECT_EQ(detail::roundingMode(), FE_UPWARD);
    {
      RoundingScope inner;
      EXPECT_EQ(detail::roundingMode(), FE_UPWARD);
    }
    EXPECT_EQ(detail::roundingMode(), FE_UPWARD);
  }
  EXPECT_EQ(detail::roundingMode(), FE_TONEAREST);
}
