#pragma once

// An independent oracle for tests: is a point strictly inside a closed mesh? Ray
// parity in double precision along a fixed irrational-looking direction, reliable
// only for points clearly away from the surface (callers make sure of that).

#include <Eigen/Geometry>

#include "freespace/geometry/mesh.h"

namespace freespace::testing {

inline bool rayHitsTriangle(const Point3& origin, const Point3& direction, const Point3& a, const Point3& b,
                            const Point3& c) {
  // Moller-Trumbore: solve origin + s direction = a + u (b - a) + v (c - a).
  const Point3 edge1 = b - a, edge2 = c - a;
  const Point3 p = direction.cross(edge2);
  const double determinant = edge1.dot(p);
  if (determinant == 0) return false;
  const Point3 offset = origin - a;
  const double u = offset.dot(p) / determinant;
  if (u < 0 || u > 1) return false;
  const Point3 q = offset.cross(edge1);
  const double v = direction.dot(q) / determinant;
  if (v < 0 || u + v > 1) return false;
  return edge2.dot(q) / determinant > 0;
}

/// Whether `point` lies inside component `component` of `mesh`.
inline bool insideComponent(const Mesh& mesh, std::uint32_t component, const Point3& point) {
  const Point3 direction = Point3(1, 0.1414213562373095, 0.1732050807568877).normalized();
  int crossings = 0;
  for (std::size_t i = 0; i < mesh.triangles().size(); ++i) {
    if (mesh.triangleComponents()[i] != component) continue;
    const TriangleIndices& t = mesh.triangles()[i];
    crossings += rayHitsTriangle(point, direction, mesh.vertices()[t[0]], mesh.vertices()[t[1]], mesh.vertices()[t[2]]);
  }
  return crossings % 2 == 1;
}

inline bool insideMesh(const Mesh& mesh, const Point3& point) {
  for (std::uint32_t component = 0; component < mesh.componentCount(); ++component) {
    if (mesh.componentBounds()[component].contains(point) && insideComponent(mesh, component, point)) return true;
  }
  return false;
}

}  // namespace freespace::testing
