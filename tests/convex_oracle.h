#pragma once

// An independent oracle for tests: do two closed convex polyhedra intersect?
// Separating axis theorem in exact rationals: two closed convex polytopes are
// disjoint exactly when their projections on one of the face normals or on one of
// the cross products of an edge of each are disjoint intervals.

#include <algorithm>
#include <array>
#include <vector>

#include "freespace/geometry/mesh.h"
#include "freespace/numbers/half_angle.h"
#include "freespace/numbers/rational.h"
#include "freespace/problem/planar_problem.h"

namespace freespace::testing {

struct ExactPoint {
  Rational x, y, z;
};

inline ExactPoint minus(const ExactPoint& a, const ExactPoint& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline ExactPoint cross(const ExactPoint& a, const ExactPoint& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Rational dot(const ExactPoint& a, const ExactPoint& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

struct ExactPolytope {
  std::vector<ExactPoint> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

inline ExactPolytope exactWorld(const Mesh& mesh) {
  ExactPolytope polytope;
  for (const Point3& p : mesh.vertices()) polytope.vertices.push_back({Rational(p.x()), Rational(p.y()), Rational(p.z())});
  polytope.triangles = mesh.triangles();
  return polytope;
}

/// The robot placed at `pose` with the same rational rotation the project uses
/// (HalfAngle::fromRadians), computed here directly in rationals.
inline ExactPolytope exactPlacedRobot(const Mesh& mesh, const Pose2& pose) {
  Rational c, s;
  HalfAngle::fromRadians(pose.theta).cosSin(c, s);
  ExactPolytope polytope;
  for (const Point3& p : mesh.vertices()) {
    const Rational px(p.x()), py(p.y());
    polytope.vertices.push_back({c * px - s * py + Rational(pose.x), s * px + c * py + Rational(pose.y), Rational(p.z())});
  }
  polytope.triangles = mesh.triangles();
  return polytope;
}

inline bool separatedAlong(const ExactPoint& axis, const ExactPolytope& a, const ExactPolytope& b) {
  if (axis.x == 0 && axis.y == 0 && axis.z == 0) return false;
  const auto range = [&axis](const ExactPolytope& p) {
    Rational low = dot(axis, p.vertices[0]), high = low;
    for (const ExactPoint& v : p.vertices) {
      const Rational d = dot(axis, v);
      low = std::min(low, d);
      high = std::max(high, d);
    }
    return std::make_pair(low, high);
  };
  const auto [lowA, highA] = range(a);
  const auto [lowB, highB] = range(b);
  return highA < lowB || highB < lowA;
}

inline bool convexPolytopesIntersect(const ExactPolytope& a, const ExactPolytope& b) {
  std::vector<ExactPoint> edgesA, edgesB;
  std::vector<ExactPoint> axes;
  const auto collect = [&axes](const ExactPolytope& p, std::vector<ExactPoint>& edges) {
    for (const auto& t : p.triangles) {
      const ExactPoint e0 = minus(p.vertices[t[1]], p.vertices[t[0]]);
      const ExactPoint e1 = minus(p.vertices[t[2]], p.vertices[t[1]]);
      const ExactPoint e2 = minus(p.vertices[t[0]], p.vertices[t[2]]);
      axes.push_back(cross(e0, e1));
      edges.insert(edges.end(), {e0, e1, e2});
    }
  };
  collect(a, edgesA);
  collect(b, edgesB);
  for (const ExactPoint& ea : edgesA) {
    for (const ExactPoint& eb : edgesB) axes.push_back(cross(ea, eb));
  }
  for (const ExactPoint& axis : axes) {
    if (separatedAlong(axis, a, b)) return false;
  }
  return true;
}

}  // namespace freespace::testing
