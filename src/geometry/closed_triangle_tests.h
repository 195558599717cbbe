#pragma once

#include <array>

#include "freespace/numbers/sign.h"

namespace freespace::detail {

/// Intersection tests on closed triangles in 3D, decided only by signs of
/// determinants. `Predicates` evaluates those signs exactly on points named by
/// `Id`; it provides
///   Sign orient3d(Id a, Id b, Id c, Id d)
///   Sign orient2d(Id a, Id b, Id c, int droppedAxis)
///   Sign between(Id a, Id b, Id c, int droppedAxis)   // see projectedBetweenDeterminant
///   Sign compare(Id a, Id b, int axis)                 // sign of a[axis] - b[axis]
/// Triangles are non-degenerate (checked when meshes are loaded).
template <class Predicates, class Id>
class ClosedTriangleTests {
 public:
  using Triangle = std::array<Id, 3>;

  explicit ClosedTriangleTests(Predicates& predicates) : p_(predicates) {}

  /// Closed triangles P and Q intersect exactly when an edge of one meets the
  /// other: their intersection, if not empty, is convex and its extreme points lie
  /// on edges.
  bool trianglesIntersect(const Triangle& P, const Triangle& Q) {
    if (allOnOneSide(P, Q) || allOnOneSide(Q, P)) return false;
    if (inPlaneOf(P, Q)) return coplanarTrianglesIntersect(P, Q);
    for (int i = 0; i < 3; ++i) {
      if (segmentIntersectsTriangle(P[i], P[(i + 1) % 3], Q)) return true;
      if (segmentIntersectsTriangle(Q[i], Q[(i + 1) % 3], P)) return true;
    }
    return false;
  }

  bool segmentIntersectsTriangle(Id a, Id b, const Triangle& T) {
    const Sign sa = p_.orient3d(T[0], T[1], T[2], a);
    const Sign sb = p_.orient3d(T[0], T[1], T[2], b);
    if (sameStrictSign(sa, sb)) return false;
    if (sa == Sign::Zero && sb == Sign::Zero) return coplanarSegmentIntersectsTriangle(a, b, T);
    // The line ab crosses the plane of T at one point of the closed segment; that
    // point is in the closed triangle unless ab passes two edges on opposite sides.
    return !mixedSigns(p_.orient3d(a, b, T[0], T[1]), p_.orient3d(a, b, T[1], T[2]),
                       p_.orient3d(a, b, T[2], T[0]));
  }

  /// Contribution of triangle T to the winding number of point q, counted along the
  /// ray from q in direction +x. The ray's start is perturbed symbolically to
  /// (q.y + eps, q.z + eps^2) so that it never meets an edge; triangles parallel to
  /// x contribute nothing. Sets `onSurface` when q lies on T itself.
  int rayCrossing(Id q, const Triangle& T, bool& onSurface) {
    const Sign normalX = p_.orient2d(T[0], T[1], T[2], 0);
    if (normalX == Sign::Zero) return 0;
    for (int i = 0; i < 3; ++i) {
      if (perturbedSideOfEdge(T[i], T[(i + 1) % 3], q) != normalX) return 0;
    }
    // The ray meets the plane at parameter -orient3d(T, q) / normal.x.
    const Sign side = p_.orient3d(T[0], T[1], T[2], q);
    if (side == Sign::Zero) {
      onSurface = true;
      return 0;
    }
    if (side == normalX) return 0;  // the crossing is behind q
    return static_cast<int>(normalX);
  }

  /// An axis along which T's projection is not degenerate (nor that of anything in
  /// its plane).
  int projectionAxis(const Triangle& T) {
    for (int axis = 2; axis > 0; --axis) {
      if (p_.orient2d(T[0], T[1], T[2], axis) != Sign::Zero) return axis;
    }
    return 0;
  }

 private:
  bool allOnOneSide(const Triangle& plane, const Triangle& T) {
    const Sign s0 = p_.orient3d(plane[0], plane[1], plane[2], T[0]);
    return s0 != Sign::Zero && s0 == p_.orient3d(plane[0], plane[1], plane[2], T[1]) &&
           s0 == p_.orient3d(plane[0], plane[1], plane[2], T[2]);
  }

  bool inPlaneOf(const Triangle& plane, const Triangle& T) {
    for (Id corner : T) {
      if (p_.orient3d(plane[0], plane[1], plane[2], corner) != Sign::Zero) return false;
    }
    return true;
  }

  /// Closed triangles in one plane are apart exactly when an edge of one has the
  /// other strictly beyond its line (the separating axis theorem for convex polygons:
  /// an axis normal to an edge suffices), in a projection in which P is not
  /// degenerate (nor then Q).
  bool coplanarTrianglesIntersect(const Triangle& P, const Triangle& Q) {
    const int axis = projectionAxis(P);
    return !separatedByAnEdge(P, Q, axis) && !separatedByAnEdge(Q, P, axis);
  }

  bool separatedByAnEdge(const Triangle& T, const Triangle& other, int axis) {
    for (int i = 0; i < 3; ++i) {
      const Id from = T[i], to = T[(i + 1) % 3];
      const Sign outside = -p_.orient2d(from, to, T[(i + 2) % 3], axis);
      const auto beyond = [&](Id corner) { return p_.orient2d(from, to, corner, axis) == outside; };
      if (beyond(other[0]) && beyond(other[1]) && beyond(other[2])) return true;
    }
    return false;
  }

  /// Both a and b lie in T's plane: work in a coordinate projection in which T is
  /// not degenerate.
  bool coplanarSegmentIntersectsTriangle(Id a, Id b, const Triangle& T) {
    const int axis = projectionAxis(T);
    if (insideClosedTriangle(a, T, axis) || insideClosedTriangle(b, T, axis)) return true;
    for (int i = 0; i < 3; ++i) {
      if (closedSegmentsIntersect(a, b, T[i], T[(i + 1) % 3], axis)) return true;
    }
    return false;
  }

  bool insideClosedTriangle(Id q, const Triangle& T, int axis) {
    return !mixedSigns(p_.orient2d(T[0], T[1], q, axis), p_.orient2d(T[1], T[2], q, axis),
                       p_.orient2d(T[2], T[0], q, axis));
  }

  bool closedSegmentsIntersect(Id a, Id b, Id c, Id d, int axis) {
    const Sign d1 = p_.orient2d(c, d, a, axis), d2 = p_.orient2d(c, d, b, axis);
    const Sign d3 = p_.orient2d(a, b, c, axis), d4 = p_.orient2d(a, b, d, axis);
    if (d1 == -d2 && d1 != Sign::Zero && d3 == -d4 && d3 != Sign::Zero) return true;
    return (d1 == Sign::Zero && onSegment(a, c, d, axis)) ||
           (d2 == Sign::Zero && onSegment(b, c, d, axis)) ||
           (d3 == Sign::Zero && onSegment(c, a, b, axis)) ||
           (d4 == Sign::Zero && onSegment(d, a, b, axis));
  }

  bool onSegment(Id q, Id from, Id to, int axis) {
    return p_.between(q, from, to, axis) != Sign::Positive;
  }

  /// Side of the perturbed ray start q' of the projected edge (e0, e1), dropping x.
  /// orient2d(e0, e1, q') = orient2d(e0, e1, q) + (e0.z - e1.z) eps + (e1.y - e0.y) eps^2.
  Sign perturbedSideOfEdge(Id e0, Id e1, Id q) {
    const Sign exact = p_.orient2d(e0, e1, q, 0);
    if (exact != Sign::Zero) return exact;
    const Sign firstOrder = p_.compare(e0, e1, 2);
    if (firstOrder != Sign::Zero) return firstOrder;
    return p_.compare(e1, e0, 1);
  }

  Predicates& p_;
};

}  // namespace freespace::detail
