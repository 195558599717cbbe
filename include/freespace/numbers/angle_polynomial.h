#pragma once

#include <array>

#include "freespace/numbers/adaptive_sign.h"
#include "freespace/numbers/polynomial.h"

namespace freespace {

/// A linear form in (sin theta, cos theta, 1): s * sin + c * cos + k.
template <class T>
struct TrigLinear {
  T s, c, k;
};

/// The form's value at an angle given by its cosine and sine.
template <class T>
T valueAt(const TrigLinear<T>& form, const T& cosine, const T& sine) {
  return form.s * sine + form.c * cosine + form.k;
}

/// The polynomial in the tangent half-angle t of `chart` whose value is
/// w(t) * form(theta), w = 1 + t^2 > 0 (so its sign is the form's sign):
///   chart 0: sin = 2t / w,  cos = (1 - t^2) / w  ->  (k + c) + 2 s t + (k - c) t^2
///   chart 1: sin = -2t / w, cos = -(1 - t^2) / w ->  (k - c) - 2 s t + (k + c) t^2
template <class T>
Polynomial<T> tangentPolynomial(const TrigLinear<T>& form, int chart) {
  const T twoS = form.s + form.s;
  if (chart == 0) return Polynomial<T>({form.k + form.c, twoS, form.k - form.c});
  return Polynomial<T>({form.k - form.c, -twoS, form.k + form.c});
}

/// tangentPolynomial in both charts.
template <class T>
std::array<Polynomial<T>, 2> tangentPolynomials(const TrigLinear<T>& form) {
  return {tangentPolynomial(form, 0), tangentPolynomial(form, 1)};
}

template <class T>
Polynomial<T> operator*(const Polynomial<T>& a, const Polynomial<T>& b) {
  std::vector<T> product(a.size() + b.size() - 1, T(0));
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) product[i + j] += a.coefficients()[i] * b.coefficients()[j];
  }
  return Polynomial<T>(std::move(product));
}

template <class T>
Polynomial<T> operator+(const Polynomial<T>& a, const Polynomial<T>& b) {
  std::vector<T> sum(std::max(a.size(), b.size()), T(0));
  for (std::size_t i = 0; i < a.size(); ++i) sum[i] += a.coefficients()[i];
  for (std::size_t i = 0; i < b.size(); ++i) sum[i] += b.coefficients()[i];
  return Polynomial<T>(std::move(sum));
}

/// A patch's line at angle theta (docs/design.md section 3):
///   (R(theta) a1 + a2) . d + k1 sin + k2 cos + k3 = 0.
/// The coefficients are polynomials in the input coordinates, computed in the number
/// type T of the evaluation (see geometry/patch.h), never rounded in between.
template <class T>
struct PatchLine {
  T a1x, a1y, a2x, a2y;
  T k1, k2, k3;
};

/// The same line with its coefficients converted to another number type.
template <class T, class S>
PatchLine<T> convertLine(const PatchLine<S>& line) {
  return {T(line.a1x), T(line.a1y), T(line.a2x), T(line.a2y), T(line.k1), T(line.k2), T(line.k3)};
}

/// A point of the plane moving with theta as d(theta) = u + R(theta) v: the spiral
/// end points of patches (docs/design.md section 3), where u and v are given exactly by
/// input points; see spiralOfRobotVertexOnEdge and spiralOfWorldVertexOnEdge.
template <class T>
struct Spiral {
  T ux, uy, vx, vy;
};

/// Robot vertex p on environment edge (e0, e1): d = e(p_z)_xy - R p_xy, where e(z) is
/// the point of the edge at height z (e0_z != e1_z).
template <class T>
Spiral<T> spiralOfRobotVertexOnEdge(const double p[3], const double e0[3], const double e1[3]) {
  const T along = (T(p[2]) - T(e0[2])) / (T(e1[2]) - T(e0[2]));
  return {T(e0[0]) + along * (T(e1[0]) - T(e0[0])), T(e0[1]) + along * (T(e1[1]) - T(e0[1])), -T(p[0]), -T(p[1])};
}

/// Environment vertex q on robot edge (f0, f1): d = q_xy - R f(q_z)_xy.
template <class T>
Spiral<T> spiralOfWorldVertexOnEdge(const double q[3], const double f0[3], const double f1[3]) {
  const T along = (T(q[2]) - T(f0[2])) / (T(f1[2]) - T(f0[2]));
  return {T(q[0]), T(q[1]), -(T(f0[0]) + along * (T(f1[0]) - T(f0[0]))), -(T(f0[1]) + along * (T(f1[1]) - T(f0[1])))};
}

/// EF: k1 sin + k2 cos + k3 (a compatibility condition or a patch interval end).
template <class T>
TrigLinear<T> edgeFacetForm(const T& k1, const T& k2, const T& k3) {
  return {k1, k2, k3};
}

/// SF: the line of `line` evaluated at the spiral point, using
/// (R a) . b = cos (a . b) + sin (a x b) and (R a) . (R b) = a . b.
template <class T>
TrigLinear<T> spiralFacetForm(const PatchLine<T>& line, const Spiral<T>& spiral) {
  const T &a1x = line.a1x, &a1y = line.a1y, &a2x = line.a2x, &a2y = line.a2y;
  const T a1CrossU = a1x * spiral.uy - a1y * spiral.ux, a1DotU = a1x * spiral.ux + a1y * spiral.uy;
  const T vCrossA2 = spiral.vx * a2y - spiral.vy * a2x, vDotA2 = spiral.vx * a2x + spiral.vy * a2y;
  return {a1CrossU + vCrossA2 + line.k1, a1DotU + vDotA2 + line.k2,
          a1x * spiral.vx + a1y * spiral.vy + a2x * spiral.ux + a2y * spiral.uy + line.k3};
}

/// n_j x n_k for n = R a1 + a2, linear in sin and cos because
/// (R a) x b = cos (a x b) - sin (a . b) and (R a) x (R b) = a x b.
template <class T>
TrigLinear<T> normalCrossForm(const PatchLine<T>& j, const PatchLine<T>& k) {
  const auto cross = [](const T& ax, const T& ay, const T& bx, const T& by) { return ax * by - ay * bx; };
  const auto dot = [](const T& ax, const T& ay, const T& bx, const T& by) { return ax * bx + ay * by; };
  return {dot(j.a2x, j.a2y, k.a1x, k.a1y) - dot(j.a1x, j.a1y, k.a2x, k.a2y),
          cross(j.a1x, j.a1y, k.a2x, k.a2y) + cross(j.a2x, j.a2y, k.a1x, k.a1y),
          cross(j.a1x, j.a1y, k.a1x, k.a1y) + cross(j.a2x, j.a2y, k.a2x, k.a2y)};
}

/// FFF: the three lines are concurrent where det[n_i, w_i] = sum over cyclic (i, j, k)
/// of w_i (n_j x n_k) vanishes; a quartic in t.
template <class T>
Polynomial<T> threePatchPolynomial(const PatchLine<T>& l1, const PatchLine<T>& l2, const PatchLine<T>& l3, int chart) {
  const auto term = [chart](const PatchLine<T>& i, const PatchLine<T>& j, const PatchLine<T>& k) {
    return tangentPolynomial(edgeFacetForm(i.k1, i.k2, i.k3), chart) * tangentPolynomial(normalCrossForm(j, k), chart);
  };
  return term(l1, l2, l3) + term(l2, l3, l1) + term(l3, l1, l2);
}

/// A patch line at one angle: n = R a1 + a2 and w = k1 sin + k2 cos + k3.
template <class T>
struct LineAtAngle {
  T nx, ny, w;
};

template <class T>
LineAtAngle<T> lineAtAngle(const PatchLine<T>& line, const T& cosine, const T& sine) {
  return {cosine * line.a1x - sine * line.a1y + line.a2x, sine * line.a1x + cosine * line.a1y + line.a2y,
          line.k1 * sine + line.k2 * cosine + line.k3};
}

/// The FFF determinant det[n_i, w_i] at one angle, evaluated directly (no
/// polynomial is built): the sign predicate "on which side of concurrency are three
/// patch lines at this angle".
template <class T>
T threePatchDeterminant(const PatchLine<T>& l1, const PatchLine<T>& l2, const PatchLine<T>& l3, const T& cosine,
                        const T& sine) {
  const LineAtAngle<T> a = lineAtAngle(l1, cosine, sine), b = lineAtAngle(l2, cosine, sine),
                       c = lineAtAngle(l3, cosine, sine);
  return a.w * (b.nx * c.ny - b.ny * c.nx) + b.w * (c.nx * a.ny - c.ny * a.nx) + c.w * (a.nx * b.ny - a.ny * b.nx);
}

}  // namespace freespace

namespace freespace {

// The double-interval FFF determinant is the hottest predicate: it is compiled once
// in the library (src/numbers/angle_polynomial.cpp), where the compiler inlines its
// interval arithmetic fully, instead of in every caller's translation unit.
extern template Interval threePatchDeterminant<Interval>(const PatchLine<Interval>&, const PatchLine<Interval>&,
                                                         const PatchLine<Interval>&, const Interval&, const Interval&);

}  // namespace freespace
