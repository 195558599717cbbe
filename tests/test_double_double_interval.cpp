// The double-double interval type against exact rational arithmetic: every result
// must hold the exact result for any points of the operands, and on exact operands
// be about 2^-100 wide relative to the result.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <functional>

#include "freespace/numbers/double_double_interval.h"
#include "freespace/numbers/rational.h"
#include "number_generators.h"

using namespace freespace;
using freespace::testing::anyDouble;

namespace {

/// A rational that is not a double-word: a double, a much smaller double and a third.
Rational anyRational() {
  return Rational(anyDouble()) + Rational(anyDouble()) * powerOfHalf(70) / 3;
}

Rational lowerOf(const DoubleDoubleInterval& x) { return Rational(x.high()) + Rational(x.low()) - Rational(x.radius()); }
Rational upperOf(const DoubleDoubleInterval& x) { return Rational(x.high()) + Rational(x.low()) + Rational(x.radius()); }

bool holds(const DoubleDoubleInterval& x, const Rational& value) { return lowerOf(x) <= value && value <= upperOf(x); }

/// An operand: an exact rational's enclosure, widened by adding and subtracting
/// other rationals' enclosures (which leaves the exact value alone and grows the
/// radius), with the exact rational it encloses.
struct Operand {
  DoubleDoubleInterval value;
  Rational exact;
};

/// Away from zero by at least 1/8, for divisors.
Rational nonzeroRational() {
  const Rational value = anyRational();
  return value + (value < 0 ? Rational(-1, 8) : Rational(1, 8));
}

Operand anyOperand(bool nonzero = false) {
  const Rational exact = nonzero ? nonzeroRational() : anyRational();
  DoubleDoubleInterval value(exact);
  NearestRoundingScope rounding;
  for (int widen = *rc::gen::inRange(0, 3); widen > 0; --widen) {
    const Rational other = anyRational();
    value = value + DoubleDoubleInterval(other) - DoubleDoubleInterval(other);
  }
  return {value, exact};
}

/// A point of the operand's interval: an end or the exact value it was made from.
Rational pointOf(const Operand& x) {
  switch (*rc::gen::inRange(0, 3)) {
    case 0: return lowerOf(x.value);
    case 1: return upperOf(x.value);
    default: return x.exact;
  }
}

using Operation = std::function<DoubleDoubleInterval(const DoubleDoubleInterval&, const DoubleDoubleInterval&)>;
using ExactOperation = std::function<Rational(const Rational&, const Rational&)>;

void checkOperation(const Operation& operation, const ExactOperation& exactOperation, bool division) {
  const Operand a = anyOperand(), b = anyOperand(division);
  DoubleDoubleInterval result;
  {
    NearestRoundingScope rounding;
    result = operation(a.value, b.value);
  }
  RC_ASSERT(holds(result, exactOperation(pointOf(a), pointOf(b))));
  RC_ASSERT(holds(result, exactOperation(a.exact, b.exact)));
}

/// On operands that are exact doubles the result is exact to about 2^-100.
void checkTightness(const Operation& operation, const ExactOperation& exactOperation, bool division) {
  const double a = anyDouble(), b = division ? nonzeroRational().convert_to<double>() : anyDouble();
  DoubleDoubleInterval result;
  {
    NearestRoundingScope rounding;
    result = operation(a, b);
  }
  const Rational exact = exactOperation(Rational(a), Rational(b));
  RC_ASSERT(holds(result, exact));
  RC_ASSERT(Rational(result.radius()) <= abs(exact) * powerOfHalf(100) + powerOfHalf(990));
}

const Operation kSum = [](const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) { return a + b; };
const Operation kDifference = [](const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) { return a - b; };
const Operation kProduct = [](const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) { return a * b; };
const Operation kQuotient = [](const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) { return a / b; };
const ExactOperation kExactSum = [](const Rational& a, const Rational& b) -> Rational { return a + b; };
const ExactOperation kExactDifference = [](const Rational& a, const Rational& b) -> Rational { return a - b; };
const ExactOperation kExactProduct = [](const Rational& a, const Rational& b) -> Rational { return a * b; };
const ExactOperation kExactQuotient = [](const Rational& a, const Rational& b) -> Rational { return a / b; };

}  // namespace

RC_GTEST_PROP(DoubleDoubleInterval, SumHoldsTheExactSum, ()) { checkOperation(kSum, kExactSum, false); }
RC_GTEST_PROP(DoubleDoubleInterval, DifferenceHoldsTheExactDifference, ()) {
  checkOperation(kDifference, kExactDifference, false);
}
RC_GTEST_PROP(DoubleDoubleInterval, ProductHoldsTheExactProduct, ()) { checkOperation(kProduct, kExactProduct, false); }
RC_GTEST_PROP(DoubleDoubleInterval, QuotientHoldsTheExactQuotient, ()) {
  checkOperation(kQuotient, kExactQuotient, true);
}

RC_GTEST_PROP(DoubleDoubleInterval, OperationsOnDoublesAreTight, ()) {
  checkTightness(kSum, kExactSum, false);
  checkTightness(kDifference, kExactDifference, false);
  checkTightness(kProduct, kExactProduct, false);
  checkTightness(kQuotient, kExactQuotient, true);
}

/// A chain of operations as in the patch formulas (cross products of differences,
/// a quotient of heights): the exact result stays inside.
RC_GTEST_PROP(DoubleDoubleInterval, ChainsHoldTheExactResult, ()) {
  std::vector<Operand> values;
  for (int i = 0; i < 4; ++i) values.push_back(anyOperand());
  const std::vector<std::pair<Operation, ExactOperation>> operations{
      {kSum, kExactSum}, {kDifference, kExactDifference}, {kProduct, kExactProduct}};
  for (int step = 0; step < 12; ++step) {
    const auto& [operation, exact] = operations[*rc::gen::inRange<std::size_t>(0, operations.size())];
    const Operand& a = values[*rc::gen::inRange<std::size_t>(0, values.size())];
    const Operand& b = values[*rc::gen::inRange<std::size_t>(0, values.size())];
    NearestRoundingScope rounding;
    values.push_back({operation(a.value, b.value), exact(a.exact, b.exact)});
  }
  for (const Operand& value : values) RC_ASSERT(holds(value.value, value.exact));
}

RC_GTEST_PROP(DoubleDoubleInterval, RationalsAreEnclosedTightly, ()) {
  const Rational value = anyRational();
  const DoubleDoubleInterval enclosure(value);
  RC_ASSERT(holds(enclosure, value));
  RC_ASSERT(Rational(enclosure.radius()) <= abs(value) * powerOfHalf(100) + powerOfHalf(990));
  const Interval doubles = enclosingInterval(enclosure);
  RC_ASSERT(Rational(doubles.lower()) <= value && value <= Rational(doubles.upper()));
}

/// Whether `near` lies less than an ulp from `value`: value strictly between the
/// doubles on either side of it.
bool withinAnUlp(double near, const Rational& value) {
  return Rational(std::nextafter(near, -HUGE_VAL)) < value && value < Rational(std::nextafter(near, HUGE_VAL));
}

// GMP's conversion is not rounded to nearest, but never an ulp off, subnormal results
// included (values below 2^960 here: infinities have no rational to compare with).
RC_GTEST_PROP(NearDouble, IsLessThanAnUlpOff, ()) {
  const int exponent = *rc::gen::inRange(-1070, 880);
  const Rational value = anyRational() * Rational(std::ldexp(1.0, exponent)) / 7;
  const bool zero = value == 0;
  RC_ASSERT((zero ? nearDouble(value) == 0 : withinAnUlp(nearDouble(value), value)));
  const Interval enclosure = enclosingInterval(value);
  RC_ASSERT(Rational(enclosure.lower()) <= value && value <= Rational(enclosure.upper()));
}

// A double times a power of two: the rationals' product, whether the doubles' is exact
// or not (subnormal, rounded up to the least normal double, beyond the largest).
RC_GTEST_PROP(TimesPowerOfTwo, IsTheExactProduct, ()) {
  const double value = std::ldexp(*rc::gen::inRange(-(1 << 20), 1 << 20) + 0.5, *rc::gen::inRange(-1080, 1000));
  const double power = std::ldexp(1.0, *rc::gen::inRange(-60, 60));
  RC_ASSERT(timesPowerOfTwo(value, power) == Rational(value) * Rational(power));
}

TEST(TimesPowerOfTwo, AtTheEndsOfTheDoubles) {
  const double least = std::numeric_limits<double>::min(), largest = std::numeric_limits<double>::max();
  for (const double value : {std::nextafter(2 * least, 0.0), -std::nextafter(2 * least, 0.0), least, 3 * least,
                             std::numeric_limits<double>::denorm_min(), largest, -largest, 0.0, -0.0}) {
    for (const double power : {0.5, 0.25, 2.0, 1.0}) {
      EXPECT_EQ(timesPowerOfTwo(value, power), Rational(value) * Rational(power)) << value << " times " << power;
    }
  }
}

// Subnormal values within an ulp, values below the least subnormal within one of 0,
// values beyond the largest double infinite.
TEST(NearDouble, AtTheEndsOfTheDoubles) {
  const Rational subnormal = Rational(1, 3) * powerOfHalf(1060), tiny = powerOfHalf(1200) / 3;
  EXPECT_TRUE(withinAnUlp(nearDouble(subnormal), subnormal));
  EXPECT_TRUE(withinAnUlp(nearDouble(-subnormal), -subnormal));
  EXPECT_TRUE(withinAnUlp(nearDouble(tiny), tiny));
  const Rational huge = Rational(1) / (powerOfHalf(1100) * 3);
  EXPECT_EQ(nearDouble(huge), HUGE_VAL);
  EXPECT_EQ(nearDouble(-huge), -HUGE_VAL);
  EXPECT_EQ(nearDouble(Rational(0)), 0.0);
}

TEST(DoubleDoubleInterval, DecidesSignsThatDoubleIntervalsCannot) {
  NearestRoundingScope rounding;
  // 0.1 * 3 - 0.3 in doubles is 2^-54 and in double intervals of unknown sign; the
  // double-double value of the double products is exact.
  EXPECT_EQ(certainSign(DoubleDoubleInterval(0.1) * 3.0 - DoubleDoubleInterval(0.3)), Sign::Positive);
  // 1 + 2^-60 is no double; its square less one is about 2^-59.
  const DoubleDoubleInterval x = DoubleDoubleInterval(1.0) + DoubleDoubleInterval(0x1p-60);
  EXPECT_EQ(certainSign(x - 1.0), Sign::Positive);
  EXPECT_EQ(certainSign(x * x - 1.0 - 0x1p-58), Sign::Negative);
  EXPECT_EQ(certainSign(DoubleDoubleInterval(2.0) * 3.0 - 6.0), Sign::Zero);
  const double huge = std::numeric_limits<double>::max();
  EXPECT_EQ(certainSign(DoubleDoubleInterval(huge) * huge - DoubleDoubleInterval(huge) * huge), std::nullopt);
  EXPECT_THROW(DoubleDoubleInterval(1.0) / (DoubleDoubleInterval(1.0) - 1.0), std::domain_error);
  // A rational beyond doubles decides nothing.
  const Rational beyond = boost::multiprecision::pow(boost::multiprecision::mpz_int(10), 400);
  EXPECT_EQ(certainSign(DoubleDoubleInterval(beyond)), std::nullopt);
  EXPECT_EQ(certainSign(DoubleDoubleInterval(Rational(-beyond)) * 2.0), std::nullopt);
}

TEST(DoubleDoubleInterval, NearestRoundingScopeRestoresTheMode) {
  RoundingScope upward;
  {
    NearestRoundingScope nearest;
    EXPECT_EQ(detail::roundingMode(), FE_TONEAREST);
  }
  EXPECT_EQ(detail::roundingMode(), FE_UPWARD);
}
