#pragma once

// Vectors of mesh coordinates in any number type, for the patch formulas of
// docs/design.md section 3.

#include <algorithm>
#include <array>
#include <cstdint>

#include "freespace/geometry/mesh.h"
#include "freespace/numbers/algebraic_angle.h"
#include "freespace/numbers/angle_polynomial.h"

namespace freespace::detail {

template <class T>
struct Vector3T {
  T x, y, z;
};

template <class T>
Vector3T<T> pointOf(const Point3& p) {
  return {T(p.x()), T(p.y()), T(p.z())};
}

template <class T>
Vector3T<T> difference(const Vector3T<T>& a, const Vector3T<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

template <class T>
Vector3T<T> cross(const Vector3T<T>& a, const Vector3T<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class T>
T dot(const Vector3T<T>& a, const Vector3T<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// The vector from vertex `from` to vertex `to` of a mesh.
template <class T>
Vector3T<T> edgeVector(const Mesh& mesh, std::uint32_t from, std::uint32_t to) {
  return difference(pointOf<T>(mesh.vertices()[to]), pointOf<T>(mesh.vertices()[from]));
}

using Corners = std::array<Point3, 3>;

inline Corners cornersOf(const Mesh& mesh, std::uint32_t triangle) {
  const TriangleIndices& t = mesh.triangles()[triangle];
  return {mesh.vertices()[t[0]], mesh.vertices()[t[1]], mesh.vertices()[t[2]]};
}

/// (b - a) x (c - a) for corners (a, b, c).
template <class T>
Vector3T<T> normalOf(const Corners& corners) {
  const Vector3T<T> a = pointOf<T>(corners[0]);
  return cross(difference(pointOf<T>(corners[1]), a), difference(pointOf<T>(corners[2]), a));
}

/// The outward normal of a triangle of a checked mesh.
template <class T>
Vector3T<T> triangleNormal(const Mesh& mesh, std::uint32_t triangle) {
  return normalOf<T>(cornersOf(mesh, triangle));
}

/// (R a) . b = cos (a . b)_xy + sin (a x b)_xy + a_z b_z, as a form in sin and cos.
template <class T>
TrigLinear<T> rotatedDot(const Vector3T<T>& a, const Vector3T<T>& b) {
  return {a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y, a.z * b.z};
}

/// The RootKey of an EF function (docs/design.md section 4): (R (x - y)) . n for a robot
/// vertex pair (x, y) and the normal n of a plane through three environment
/// vertices, or (R m) . (x - y) for an environment pair and a robot plane.
/// Reversing the pair or reordering the plane only changes the function by a
/// constant factor, so the key sorts both.
inline AngleFunction::RootKey edgeFacetKey(bool robotPair, std::uint32_t x, std::uint32_t y,
                                          std::array<std::uint32_t, 3> plane) {
  std::sort(plane.begin(), plane.end());
  return {robotPair ? 0u : 1u, std::min(x, y), std::max(x, y), plane[0], plane[1], plane[2]};
}

/// Whether an EF key names the zero function: a pair of one vertex (x - x = 0) or a
/// plane through a repeated vertex (its normal is zero). Such keys come from SF
/// functions whose spiral lies on the line at every angle.
inline bool namesZeroFunction(const AngleFunction::RootKey& key) {
  const bool edgeFacet = key[0] <= 1;
  return edgeFacet && (key[1] == key[2] || key[3] == key[4] || key[4] == key[5]);
}

}  // namespace freespace::detail
