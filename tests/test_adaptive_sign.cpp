// The adaptive sign engine against exact rational evaluation, on random and on
// constructed degenerate inputs; the perturbation stream; half-angle conversions.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "freespace/numbers/adaptive_sign.h"
#include "freespace/numbers/half_angle.h"
#include "freespace/numbers/perturbation.h"

using namespace freespace;

namespace {

/// orient2d of three points, written once for every number type.
struct Orientation {
  double ax, ay, bx, by, cx, cy;
  template <class T>
  T operator()(NumberType<T>) const {
    return (T(bx) - T(ax)) * (T(cy) - T(ay)) - (T(by) - T(ay)) * (T(cx) - T(ax));
  }
};

Sign referenceSign(const Orientation& orientation) { return exactSign(orientation(NumberType<Rational>{})); }

double coordinate() {
  // Integer grid values, tiny offsets that cancel only in high precision, and
  // arbitrary doubles.
  switch (*rc::gen::inRange(0, 3)) {
    case 0: return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-8, 9));
    case 1: return 0.1 * *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-8, 9)) + 1e-17 * *rc::gen::inRange(-3, 4);
    default: return *rc::gen::arbitrary<double>() * 1e-300 + *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-100, 100)) / 7.0;
  }
}

}  // namespace

RC_GTEST_PROP(AdaptiveSign, AgreesWithExactEvaluation, ()) {
  Orientation o{coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate()};
  if (*rc::gen::inRange(0, 3) == 0) {
    // Collinear by construction: c = a + k (b - a) with a small integer k.
    const int k = *rc::gen::inRange(-3, 4);
    o.cx = o.ax + k * (o.bx - o.ax);
    o.cy = o.ay + k * (o.by - o.ay);
  }
  RC_PRE(std::isfinite(o.cx) && std::isfinite(o.cy));
  PredicateStatistics statistics;
  AdaptiveSignEngine engine(statistics);
  const Sign sign = engine.sign(PredicateKind::Orientation, o);
  RC_ASSERT(sign == referenceSign(o));
  const auto& counts = statistics.counts(PredicateKind::Orientation);
  RC_ASSERT(counts.total() == 1u);
  RC_ASSERT(counts.identities == (sign == Sign::Zero ? 1u : 0u));
}

TEST(AdaptiveSign, EscalatesOnlyWhenDoublesCannotDecide) {
  PredicateStatistics statistics;
  AdaptiveSignEngine engine(statistics);
  // Clearly positive: decided in doubles.
  EXPECT_EQ(engine.sign(PredicateKind::Orientation, Orientation{0, 0, 1, 0, 0, 1}), Sign::Positive);
  // (1 + e)(1 - e) - 1 * 1 = -e^2 with e = 2^-52: invisible in doubles.
  const double e = std::ldexp(1.0, -52);
  EXPECT_EQ(engine.sign(PredicateKind::Orientation, Orientation{0, 0, 1 + e, 1, 1, 1 - e}), Sign::Negative);
  // 0.1, 0.2, 0.3 (as doubles) on one line through the origin: exactly collinear.
  EXPECT_EQ(engine.sign(PredicateKind::Orientation, Orientation{0, 0, 0.1, 0.3, 0.2, 0.6}), Sign::Zero);
  const auto& counts = statistics.counts(PredicateKind::Orientation);
  EXPECT_EQ(counts.decided[static_cast<int>(PrecisionLevel::DoubleInterval)], 1u);
  EXPECT_EQ(counts.total(), 3u);
  EXPECT_EQ(counts.identities, 1u);
  EXPECT_NEAR(statistics.doubleIntervalFraction(), 1.0 / 3, 1e-12);
  EXPECT_NE(statistics.toText().find("orientation 1 "), std::string::npos) << statistics.toText();
}

TEST(Perturbation, SeededAndBoundedAndSwitchable) {
  Perturbation first({true, 42, 1e-8}, 100.0), second({true, 42, 1e-8}, 100.0), other({true, 43, 1e-8}, 100.0);
  EXPECT_EQ(first.record().absoluteSize, 1e-6);
  bool anyDifferent = false;
  for (int i = 0; i < 1000; ++i) {
    const double a = first.perturb(3.0), b = second.perturb(3.0), c = other.perturb(3.0);
    EXPECT_EQ(a, b);
    EXPECT_LE(std::fabs(a - 3.0), 1e-6);
    EXPECT_NE(a, 3.0);
    anyDifferent = anyDifferent || a != c;
  }
  EXPECT_TRUE(anyDifferent);
  Perturbation off({false, 42, 1e-8}, 100.0);
  EXPECT_EQ(off.perturb(3.0), 3.0);
  EXPECT_EQ(off.record().absoluteSize, 0);
  EXPECT_THROW(Perturbation({true, 1, -1.0}, 1.0), std::invalid_argument);
}

RC_GTEST_PROP(HalfAngle, RationalRotationOfADoubleAngle, ()) {
  const double theta = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-4000000, 4000001)) * 1e-6;
  const HalfAngle angle = HalfAngle::fromRadians(theta);
  RC_ASSERT(std::fabs(angle.t) <= 1.0);
  Rational cosine, sine;
  angle.cosSin(cosine, sine);
  RC_ASSERT(cosine * cosine + sine * sine == 1);  // exactly a rotation
  RC_ASSERT(std::fabs(cosine.convert_to<double>() - std::cos(theta)) < 1e-14);
  RC_ASSERT(std::fabs(sine.convert_to<double>() - std::sin(theta)) < 1e-14);
  RC_ASSERT(std::fabs(std::remainder(angle.radians() - theta, 2 * M_PI)) < 1e-14);
}

TEST(HalfAngle, ChartsAtTheBoundaries) {
  EXPECT_EQ(HalfAngle::fromRadians(0).chart, 0);
  EXPECT_EQ(HalfAngle::fromRadians(M_PI).chart, 1);
  EXPECT_EQ(HalfAngle::fromRadians(M_PI).t, 0.0);
  EXPECT_EQ(HalfAngle::fromRadians(-M_PI).t, 0.0);
  EXPECT_EQ(HalfAngle::fromRadians(M_PI / 2).chart, 0);
  EXPECT_EQ(HalfAngle::fromRadians(-M_PI / 2).chart, 0);
  Rational cosine, sine;
  HalfAngle::fromRadians(M_PI).cosSin(cosine, sine);
  EXPECT_EQ(cosine, -1);
  EXPECT_EQ(sine, 0);
}
