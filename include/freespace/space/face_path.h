#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "freespace/topology/slice_faces.h"

namespace freespace {

/// The constrained Delaunay triangulation of a face of a slice (SliceFaces): its
/// loops are the constraints (CGAL, exact predicates, inexact constructions: its paths
/// are certified afterwards), inside a box around them and
/// the points given; a triangle belongs to the face when the number of constraints
/// crossed to reach it from outside is 1 (0 for an unbounded face). In the face's (the
/// construction's) coordinates.
class FaceTriangulation {
 public:
  explicit FaceTriangulation(const SliceFace& face, const std::vector<std::array<double, 2>>& alsoHolding = {});
  ~FaceTriangulation();
  FaceTriangulation(const FaceTriangulation&) = delete;
  FaceTriangulation& operator=(const FaceTriangulation&) = delete;

  /// Straight translations from triangle to triangle across edges that are not on the
  /// face's boundary (breadth first), by the middles of the edges crossed; none when an
  /// end lies outside the face or on its boundary, or no chain of triangles joins them.
  std::optional<std::vector<std::array<double, 2>>> path(const std::array<double, 2>& from,
                                                         const std::array<double, 2>& to) const;
  /// The incentres of the face's triangles (of an unbounded face, those off the box
  /// around it), the widest inscribed circles first: points well inside the face.
  /// With `everyTriangle`, of every triangle off the box, in the face or not (a
  /// triangulation of several faces' loops: each triangle lies inside or outside each).
  std::vector<std::array<double, 2>> roomyPoints(bool everyTriangle = false) const;
  /// The incentre of the face's triangle holding a point (none outside the face): in a
  /// passage, about its middle across.
  std::optional<std::array<double, 2>> incentreAt(const std::array<double, 2>& point) const;
  /// Whether a point lies in one of the face's triangles (located in the
  /// triangulation of its loops as rounded to doubles: far cheaper than the free
  /// space's exact ray, and the same answer but within rounding of the loops).
  bool contains(const std::array<double, 2>& point) const;
  /// Whether a point lies strictly inside the box the triangulation spans (around the
  /// face's loops and the points it was made to hold). Points beyond it lie outside
  /// every triangle: for an unbounded face, path, incentreAt and contains are right
  /// only for points inside it.
  bool boxHolds(const std::array<double, 2>& point) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A path of straight translations inside one face of a slice (SliceFaces), from
/// `from` to `to`: through the constrained Delaunay triangulation of the face's loops,
/// from triangle to triangle across edges that are not on its boundary, by the middles
/// of the edges crossed. Points are in the face's (the construction's) coordinates.
/// None when an end lies outside the face or on its boundary, or no chain of triangles
/// joins them. The face's corners are rounded: certify the motions (MotionChecker).
std::optional<std::vector<std::array<double, 2>>> pathInFace(const SliceFace& face, const std::array<double, 2>& from,
                                                             const std::array<double, 2>& to);

/// A point of a face's boundary and its distance from a point.
struct BoundaryPoint {
  double distance = HUGE_VAL;
  std::array<double, 2> point{};
};

/// The point of a face's loops nearest to `point`, in doubles. The loops are the
/// slice's boundary at the face's angle, so for a point inside the face this is its
/// clearance there (in the construction's units) up to the corners' rounding: an
/// estimate, much cheaper than FreeSpace::clearance, to choose by. At infinity for a
/// face without loops.
BoundaryPoint nearestOnBoundary(const SliceFace& face, const std::array<double, 2>& point);

/// nearestOnBoundary, certifiedClearanceAlong and liesInside (below) for many points
/// of one face: its loops' edges in an R-tree (Boost.Geometry) when they are many (a
/// face of OMPL.app's Maze_planar has 685, where a walk asks thousands of points),
/// each edge in turn otherwise (nothing to build, where a walk asks too few points to
/// repay a tree). Keeps a reference to the face.
class BoundaryDistances {
 public:
  explicit BoundaryDistances(const SliceFace& face);
  ~BoundaryDistances();
  BoundaryDistances(const BoundaryDistances&) = delete;
  BoundaryDistances& operator=(const BoundaryDistances&) = delete;

  /// nearestOnBoundary(face, point), up to the rounding of a tie between edges.
  BoundaryPoint nearest(const std::array<double, 2>& point) const;
  /// certifiedClearanceAlong(face, from, to), from the edges near the motion only.
  std::optional<double> certifiedClearanceAlong(const std::array<double, 2>& from,
                                                const std::array<double, 2>& to) const;
  /// liesInside(face, point), from the edges that meet the ray only.
  bool liesInside(const std::array<double, 2>& point) const;

 private:
  struct Impl;
  struct EdgesMeeting;
  /// Far more than the rounding of a distance between the face's edges and a point.
  double rounding(const std::array<double, 2>& point) const;
  const SliceFace& face_;
  std::unique_ptr<Impl> impl_;  // null: few edges
};

/// Whether a point lies inside the face: an odd number of crossings of a ray from it
/// with a bounded face's loops as rounded, an even number with an unbounded face's
/// (exact predicates on the rounded loops; nearer to them than their rounding, the
/// exact face may say otherwise).
bool liesInside(const SliceFace& face, const std::array<double, 2>& point);

/// A certified lower bound on the clearance (in the face's units) along the straight
/// translation from `from` to `to` (a point when they are equal) at the face's angle:
/// the least distance from the segment to the face's loops, rigorously bounded, less
/// the corners' rounding (SliceFace::cornerError). Only when `from` lies inside the
/// face (the loops' crossings of a ray from it, by exact predicates on the rounded
/// loops: further from them than their rounding, it lies on the same side of the exact
/// ones) and the bound is positive; none otherwise. The face's loops are the slice's
/// boundary there, so this certifies the translation free without FreeSpace::clearance.
std::optional<double> certifiedClearanceAlong(const SliceFace& face, const std::array<double, 2>& from,
                                              const std::array<double, 2>& to);

}  // namespace freespace
