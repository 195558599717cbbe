// The angle polynomials of docs/design.md section 4 against their geometric definitions,
// evaluated directly in exact rationals at rational angles: EF and SF equal w times
// the trigonometric form, FFF equals w^2 times the 3x3 determinant of the lines.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "freespace/numbers/angle_polynomial.h"
#include "freespace/numbers/half_angle.h"

using namespace freespace;

namespace {

int uniform(int low, int high) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(low, high)); }

struct ExactAngle {
  int chart;
  Rational t, w, cosine, sine;
};

/// A rational angle with t = n / 16 in [-1, 1], with its exact cos and sin.
ExactAngle randomAngle() {
  ExactAngle angle;
  angle.chart = uniform(0, 2);
  angle.t = Rational(uniform(-16, 17), 16);
  angle.w = 1 + angle.t * angle.t;
  HalfAngle{angle.chart, angle.t.convert_to<double>()}.cosSin(angle.cosine, angle.sine);
  return angle;
}

PatchLine<double> randomLine() {
  PatchLine<double> line;
  for (double* value : {&line.a1x, &line.a1y, &line.a2x, &line.a2y, &line.k1, &line.k2, &line.k3}) {
    *value = uniform(-4, 5) / 2.0;
  }
  return line;
}

struct Vector2 {
  Rational x, y;
};

/// R(theta) v + a, computed directly.
Vector2 rotate(const ExactAngle& angle, const Rational& x, const Rational& y) {
  return {angle.cosine * x - angle.sine * y, angle.sine * x + angle.cosine * y};
}

/// The line's normal n = R a1 + a2 and its constant k1 sin + k2 cos + k3 at the angle.
Vector2 normal(const PatchLine<double>& line, const ExactAngle& angle) {
  const Vector2 rotated = rotate(angle, Rational(line.a1x), Rational(line.a1y));
  return {rotated.x + Rational(line.a2x), rotated.y + Rational(line.a2y)};
}

Rational constant(const PatchLine<double>& line, const ExactAngle& angle) {
  return Rational(line.k1) * angle.sine + Rational(line.k2) * angle.cosine + Rational(line.k3);
}

Rational evaluate(const Polynomial<Rational>& p, const ExactAngle& angle) { return p.evaluate(angle.t); }

}  // namespace

RC_GTEST_PROP(AnglePolynomial, EdgeFacetIsWTimesTheForm, ()) {
  const ExactAngle angle = randomAngle();
  const PatchLine<double> line = randomLine();
  const auto p = tangentPolynomial(edgeFacetForm(Rational(line.k1), Rational(line.k2), Rational(line.k3)), angle.chart);
  RC_ASSERT(evaluate(p, angle) == angle.w * constant(line, angle));
}

RC_GTEST_PROP(AnglePolynomial, SpiralFacetIsWTimesTheLineAtTheSpiralPoint, ()) {
  const ExactAngle angle = randomAngle();
  const PatchLine<double> line = randomLine();
  const double p[3] = {uniform(-4, 5) / 4.0, uniform(-4, 5) / 4.0, uniform(1, 4) / 4.0};
  const double e0[3] = {uniform(-4, 5) / 4.0, uniform(-4, 5) / 4.0, 0.0};
  const double e1[3] = {uniform(-4, 5) / 4.0, uniform(-4, 5) / 4.0, 1.0};
  const bool robotVertex = uniform(0, 2) == 0;
  const Spiral<Rational> spiral =
      robotVertex ? spiralOfRobotVertexOnEdge<Rational>(p, e0, e1) : spiralOfWorldVertexOnEdge<Rational>(p, e0, e1);
  // The spiral point from its definition: the point of the edge at the vertex's
  // height, minus or plus the rotated vertex.
  const Rational along = (Rational(p[2]) - Rational(e0[2])) / (Rational(e1[2]) - Rational(e0[2]));
  const Vector2 onEdge{Rational(e0[0]) + along * (Rational(e1[0]) - Rational(e0[0])),
                       Rational(e0[1]) + along * (Rational(e1[1]) - Rational(e0[1]))};
  Vector2 d;
  if (robotVertex) {
    const Vector2 rotated = rotate(angle, Rational(p[0]), Rational(p[1]));
    d = {onEdge.x - rotated.x, onEdge.y - rotated.y};
  } else {
    const Vector2 rotated = rotate(angle, onEdge.x, onEdge.y);
    d = {Rational(p[0]) - rotated.x, Rational(p[1]) - rotated.y};
  }
  const Vector2 n = normal(line, angle);
  const Rational lineValue = n.x * d.x + n.y * d.y + constant(line, angle);
  const auto polynomial = tangentPolynomial(spiralFacetForm(convertLine<Rational>(line), spiral), angle.chart);
  RC_ASSERT(evaluate(polynomial, angle) == angle.w * lineValue);
}

RC_GTEST_PROP(AnglePolynomial, ThreePatchIsWSquaredTimesTheDeterminant, ()) {
  const ExactAngle angle = randomAngle();
  const PatchLine<double> l1 = randomLine(), l2 = randomLine(), l3 = randomLine();
  const PatchLine<Rational> e1 = convertLine<Rational>(l1), e2 = convertLine<Rational>(l2), e3 = convertLine<Rational>(l3);
  const Vector2 n1 = normal(l1, angle), n2 = normal(l2, angle), n3 = normal(l3, angle);
  const Rational w1 = constant(l1, angle), w2 = constant(l2, angle), w3 = constant(l3, angle);
  const Rational determinant = n1.x * (n2.y * w3 - w2 * n3.y) - n1.y * (n2.x * w3 - w2 * n3.x) +
                               w1 * (n2.x * n3.y - n2.y * n3.x);
  const auto p = threePatchPolynomial(e1, e2, e3, angle.chart);
  RC_ASSERT(p.size() == 5u);
  RC_ASSERT(evaluate(p, angle) == angle.w * angle.w * determinant);
}

TEST(AnglePolynomial, SpiralUsesThePointOfTheEdgeAtTheVertexHeight) {
  const double p[3] = {0, 0, 0.25};
  const double e0[3] = {1, 2, 0};
  const double e1[3] = {3, 6, 1};
  const Spiral<Rational> spiral = spiralOfRobotVertexOnEdge<Rational>(p, e0, e1);
  EXPECT_EQ(spiral.ux, Rational(3, 2));
  EXPECT_EQ(spiral.uy, Rational(3));
}

RC_GTEST_PROP(AnglePolynomial, DirectThreePatchDeterminantMatchesThePolynomial, ()) {
  const ExactAngle angle = randomAngle();
  const PatchLine<double> l1 = randomLine(), l2 = randomLine(), l3 = randomLine();
  const PatchLine<Rational> e1 = convertLine<Rational>(l1), e2 = convertLine<Rational>(l2), e3 = convertLine<Rational>(l3);
  const Rational direct = threePatchDeterminant(e1, e2, e3, angle.cosine, angle.sine);
  RC_ASSERT(evaluate(threePatchPolynomial(e1, e2, e3, angle.chart), angle) == angle.w * angle.w * direct);
}
