#pragma once

#include <algorithm>
#include <array>
#include <vector>

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

  /// A point where two triangles meet on the boundary of either, named by the
  /// features that make it: a corner of either (`edge` twice that corner), or where
  /// the edge `edge` of one crosses the plane of the other (`plane`) strictly
  /// between its ends. Equal keys name one point, whichever triangle it is found from.
  struct BoundaryPoint {
    std::array<Id, 2> edge;
    Triangle plane;
    std::array<Id, 4> key;  // a corner (c, c, c, c); an edge (a, b, a, b); two edges (a, b, c, d)

    /// A crossing of an edge of each triangle, which its key names by both edges.
    bool onTwoEdges() const { return key[0] != key[2] || key[1] != key[3]; }
  };

  /// Where closed triangles P and Q, which do not lie in one plane, meet on the
  /// boundary of either, each point once. Their intersection lies on the line where
  /// their planes cross; it is convex, so it is the point or segment these points span.
  std::vector<BoundaryPoint> boundaryMeetingPoints(const Triangle& P, const Triangle& Q) {
    std::vector<BoundaryPoint> points;
    addBoundaryPoints(P, Q, points);
    addBoundaryPoints(Q, P, points);
    return points;
  }

  /// Whether closed triangles in one plane share interior points (their intersection
  /// has an area): no edge of either has the other on its line or beyond it.
  bool coplanarInteriorsOverlap(const Triangle& P, const Triangle& Q) {
    const int axis = projectionAxis(P);
    return !separatedByAnEdge(P, Q, axis, Sign::Zero) && !separatedByAnEdge(Q, P, axis, Sign::Zero);
  }

  bool inPlaneOf(const Triangle& plane, const Triangle& T) {
    for (Id corner : T) {
      if (p_.orient3d(plane[0], plane[1], plane[2], corner) != Sign::Zero) return false;
    }
    return true;
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

  /// The corners of T that lie in `other`, and the points where T's edges cross
  /// `other`'s plane inside it (closed), added to `points` unless their key is there.
  void addBoundaryPoints(const Triangle& T, const Triangle& other, std::vector<BoundaryPoint>& points) {
    const auto add = [&](const BoundaryPoint& point) {
      const auto same = [&](const BoundaryPoint& known) { return known.key == point.key; };
      if (std::none_of(points.begin(), points.end(), same)) points.push_back(point);
    };
    std::array<Sign, 3> side;
    for (int i = 0; i < 3; ++i) side[i] = p_.orient3d(other[0], other[1], other[2], T[i]);
    for (int i = 0; i < 3; ++i) {
      const Id a = T[i], b = T[(i + 1) % 3];
      if (side[i] == Sign::Zero && insideClosedTriangle(a, other, projectionAxis(other))) {
        add({{a, a}, other, {a, a, a, a}});
      }
      if (side[i] == Sign::Zero || side[(i + 1) % 3] != -side[i]) continue;
      // The line ab crosses the plane at a point of the closed triangle unless it
      // passes two edges on opposite sides; on one edge's line (a zero), the point is
      // on that edge, and found again from the other triangle; on two, it is their corner.
      std::array<Sign, 3> around;
      for (int k = 0; k < 3; ++k) around[k] = p_.orient3d(a, b, other[k], other[(k + 1) % 3]);
      if (mixedSigns(around[0], around[1], around[2])) continue;
      const auto zeros = std::count(around.begin(), around.end(), Sign::Zero);
      if (zeros > 1) continue;  // a corner of `other`, which lies in T
      const std::array<Id, 2> edge{std::min(a, b), std::max(a, b)};
      std::array<Id, 2> crossed = edge;
      for (int k = 0; k < 3; ++k) {
        if (around[k] != Sign::Zero) continue;
        crossed = {std::min(other[k], other[(k + 1) % 3]), std::max(other[k], other[(k + 1) % 3])};
      }
      const auto& [low, high] = std::minmax(edge, crossed);
      add({{a, b}, other, {low[0], low[1], high[0], high[1]}});
    }
  }

  /// Closed triangles in one plane are apart exactly when an edge of one has the
  /// other strictly beyond its line (the separating axis theorem for convex polygons:
  /// an axis normal to an edge suffices), in a projection in which P is not
  /// degenerate (nor then Q).
  bool coplanarTrianglesIntersect(const Triangle& P, const Triangle& Q) {
    const int axis = projectionAxis(P);
    return !separatedByAnEdge(P, Q, axis, Sign::Negative) && !separatedByAnEdge(Q, P, axis, Sign::Negative);
  }

  /// Whether an edge of T has every corner of `other` on its outer side, or also on
  /// its line when `lowestSide` is Zero (with T's corners seen turning positively;
  /// Negative: strictly outside).
  bool separatedByAnEdge(const Triangle& T, const Triangle& other, int axis, Sign lowestSide) {
    for (int i = 0; i < 3; ++i) {
      const Id from = T[i], to = T[(i + 1) % 3];
      const Sign turn = p_.orient2d(from, to, T[(i + 2) % 3], axis);
      const auto beyond = [&](Id corner) { return turn * p_.orient2d(from, to, corner, axis) <= lowestSide; };
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
