#pragma once

// Seams of a triangle soup: planar faces a modelling tool cut into triangles
// (docs/design.md section 9). Refinement triangulates the two triangles of a seam
// together, without the seam, and leaves out the points where other triangles cross
// the seam unless something else needs them: those points exist only because of the
// cut, and their coordinates are rationals that doubles cannot hold, which makes
// every degenerate predicate on them an exact evaluation.

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "freespace/geometry/mesh.h"

namespace freespace::detail {

class VertexPredicates;

/// Edges along which two triangles of a soup, and no other, continue one another in
/// one plane (on either side of the edge). Only triangles that `candidate` accepts
/// (refined soup triangles on the soup's vertices) are sides of a seam; every
/// triangle counts as a user of its edges.
class Seams {
 public:
  using Edge = std::pair<std::uint32_t, std::uint32_t>;   // smaller index first
  using Sides = std::pair<std::uint32_t, std::uint32_t>;  // the two triangles

  Seams(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
        const std::vector<bool>& candidate);

  /// The triangles on either side of the edge between vertices a and b, or nullptr
  /// if it is not a seam.
  const Sides* sides(std::uint32_t a, std::uint32_t b) const;
  const std::map<Edge, Sides>& all() const { return sides_; }

 private:
  std::map<Edge, Sides> sides_;
};

/// Which new points on seams refinement leaves out. A point may go when it lies on
/// one seam, nothing touches there, and in every cluster whose constraint segments
/// end at it, they lie on one line (their other triangles lie in one plane) and come
/// from both sides of the seam: each segment from one side is joined to each from the
/// other, and no triangulation needs the point.
class SeamPoints {
 public:
  using Edge = Seams::Edge;
  /// The other ends of a point's segments in a cluster, from the seam's first and
  /// second triangle.
  using Around = std::array<std::vector<std::uint32_t>, 2>;
  /// For each cluster, each point left out there with what is around it.
  using Joins = std::map<std::uint32_t, std::map<std::uint32_t, Around>>;

  SeamPoints(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles, const Seams& seams)
      : vertices_(vertices), triangles_(triangles), seams_(seams) {}

  /// The new point `point` is known to lie on the edge between vertices a and b
  /// (only seams matter: a point on two seams is kept).
  void liesOn(std::uint32_t point, std::uint32_t a, std::uint32_t b);
  /// The point is needed (something touches there, or it was made without a name).
  void keep(std::uint32_t point) { kept_.insert(point); }
  /// A constraint segment of cluster `cluster`, where triangle `own` (in the
  /// cluster) meets triangle `other`.
  void addSegment(std::uint32_t cluster, std::uint32_t own, std::uint32_t other, Edge segment);

  /// The points to leave out, by cluster.
  Joins joins() const;

  /// A cluster's `segments` without the points it leaves out (`around`, from joins):
  /// each segment of such a point from one side joined to each from the other;
  /// repeated segments once.
  static std::vector<Edge> joined(const std::vector<Edge>& segments, std::map<std::uint32_t, Around> around);

 private:
  struct End {
    std::uint32_t cluster;
    Edge segment;  // smaller index first
    int side;      // 0 or 1: from the seam's first or second triangle; -1 neither
    std::uint32_t other;
  };

  bool aroundInEveryCluster(std::uint32_t point, const std::vector<End>& ends, VertexPredicates& predicates,
                            std::map<std::uint32_t, Around>& byCluster) const;
  bool inOnePlane(std::uint32_t first, std::uint32_t second, VertexPredicates& predicates) const;

  const std::vector<Point3>& vertices_;
  const std::vector<TriangleIndices>& triangles_;
  const Seams& seams_;
  std::map<std::uint32_t, Edge> seamOf_;
  std::set<std::uint32_t> kept_;
  std::map<std::uint32_t, std::vector<End>> ends_;  // point -> the segments that end there
};

}  // namespace freespace::detail
