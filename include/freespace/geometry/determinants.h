#pragma once

namespace freespace {

/// A point in any number type (double, Interval, Rational): predicates are written
/// once over it and evaluated at rising precision.
template <class T>
struct Vec3T {
  T x, y, z;

  const T& operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
};

/// det[b - a, c - a, d - a]: positive when d lies on the side of the plane (a, b, c)
/// that the normal (b - a) x (c - a) points to.
template <class T>
T orient3dDeterminant(const Vec3T<T>& a, const Vec3T<T>& b, const Vec3T<T>& c, const Vec3T<T>& d) {
  const T bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
  const T cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
  const T dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
  return bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
}

/// The orientation of (a, b, c) projected along `droppedAxis` onto the plane of the
/// two other axes (taken in cyclic order, so that dropping z gives the usual xy
/// orientation and the sign equals that of the normal's `droppedAxis` component).
template <class T>
T orient2dDeterminant(const Vec3T<T>& a, const Vec3T<T>& b, const Vec3T<T>& c, int droppedAxis) {
  const int u = (droppedAxis + 1) % 3, v = (droppedAxis + 2) % 3;
  return (b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]);
}

/// (a - b) . (a - c) in the projection along `droppedAxis`: not positive exactly when
/// a, known to be collinear with b and c, lies on the closed segment bc.
template <class T>
T projectedBetweenDeterminant(const Vec3T<T>& a, const Vec3T<T>& b, const Vec3T<T>& c,
                              int droppedAxis) {
  const int u = (droppedAxis + 1) % 3, v = (droppedAxis + 2) % 3;
  return (a[u] - b[u]) * (a[u] - c[u]) + (a[v] - b[v]) * (a[v] - c[v]);
}

}  // namespace freespace
