#pragma once

// Exact rational vectors and rotations for geometric oracles in tests: each is
// computed straight from its definition, independently of the library's formulas.

#include "freespace/geometry/mesh.h"
#include "freespace/geometry/patch_geometry.h"
#include "freespace/numbers/algebraic_angle.h"
#include "freespace/numbers/angle_polynomial.h"
#include "freespace/numbers/half_angle.h"
#include "freespace/numbers/rational.h"

namespace freespace::testing {

struct ExactRotation {
  Rational cosine, sine;
};

inline ExactRotation rotationAt(double theta) {
  ExactRotation rotation;
  HalfAngle::fromRadians(theta).cosSin(rotation.cosine, rotation.sine);
  return rotation;
}

/// The rotation at a rational angle (AlgebraicAngle::isRational), from its chart's
/// tangent parameter t (HalfAngle's formulas).
inline ExactRotation rotationOf(const AlgebraicAngle& rationalAngle) {
  const Rational t = rationalAngle.root().lo, w = 1 + t * t, chartSign(rationalAngle.chart() == 0 ? 1 : -1);
  return {chartSign * (1 - t * t) / w, chartSign * 2 * t / w};
}

inline int signOfRational(const Rational& value) { return value > 0 ? 1 : (value < 0 ? -1 : 0); }

struct ExactPoint2 {
  Rational x, y;
};

/// The sign of the orientation of (a, b, c): +1 counterclockwise.
inline int orientation(const ExactPoint2& a, const ExactPoint2& b, const ExactPoint2& c) {
  return signOfRational((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

struct Exact3 {
  Rational x, y, z;
};

inline Exact3 exactPoint(const Point3& p) { return {Rational(p.x()), Rational(p.y()), Rational(p.z())}; }
inline Exact3 minus(const Exact3& a, const Exact3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Exact3 cross(const Exact3& a, const Exact3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Rational dot(const Exact3& a, const Exact3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Exact3 rotate(const ExactRotation& r, const Exact3& p) {
  return {r.cosine * p.x - r.sine * p.y, r.sine * p.x + r.cosine * p.y, p.z};
}
inline Exact3 normalOf(const Mesh& mesh, std::uint32_t triangle) {
  const TriangleIndices& t = mesh.triangles()[triangle];
  const Exact3 a = exactPoint(mesh.vertices()[t[0]]);
  return cross(minus(exactPoint(mesh.vertices()[t[1]]), a), minus(exactPoint(mesh.vertices()[t[2]]), a));
}

/// The value of a patch line at angle (cosine, sine) and translation d.
inline Rational lineValue(const PatchLine<Rational>& line, const ExactRotation& r, const Exact3& d) {
  const Rational nx = r.cosine * line.a1x - r.sine * line.a1y + line.a2x;
  const Rational ny = r.sine * line.a1x + r.cosine * line.a1y + line.a2y;
  return nx * d.x + ny * d.y + line.k1 * r.sine + line.k2 * r.cosine + line.k3;
}

/// A patch's segment at a rational angle: its exact ends and its line n . d + w = 0.
struct ExactSlice {
  std::array<Rational, 2> end0, end1;
  Rational nx, ny, w;

  Rational valueAt(const std::array<Rational, 2>& point) const { return nx * point[0] + ny * point[1] + w; }
};

inline ExactSlice sliceOf(const PatchGeometry& patch, const ExactRotation& r) {
  const LineAtAngle<Rational> line = lineAtAngle(lineOf<Rational>(patch.line), r.cosine, r.sine);
  return {spiralPoint(spiralOf<Rational>(patch.ends[0]), r.cosine, r.sine),
          spiralPoint(spiralOf<Rational>(patch.ends[1]), r.cosine, r.sine), line.nx, line.ny, line.w};
}

}  // namespace freespace::testing
