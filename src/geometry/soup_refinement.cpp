// Refinement of a soup's triangles along their intersections (soup_complex.h).

#include <map>
#include <optional>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/intersections.h>

#include "disjoint_sets.h"
#include "soup_complex.h"

namespace freespace::detail {

namespace {

using Index = std::uint32_t;
using ExactSegment = ExactKernel::Segment_3;
using ExactTriangle = ExactKernel::Triangle_3;
// A point, a segment, a triangle or a polygon (the last two: coplanar overlaps).
using TriangleIntersection =
    decltype(CGAL::intersection(std::declval<ExactTriangle>(), std::declval<ExactTriangle>()))::value_type;

// What a cluster of coplanar triangles must be split along: segments and points where
// other triangles meet them.
struct Constraints {
  std::vector<ExactSegment> segments;
  std::vector<ExactPoint> points;
};

struct LessXyz {
  bool operator()(const ExactPoint& a, const ExactPoint& b) const { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; }
};

// The points of a complex, each once: the triangles' points keep their indices.
class PointIndex {
 public:
  explicit PointIndex(const std::vector<ExactPoint>& points) : points_(points) {}

  // Only points of refined triangles are looked up, so the map holds just those.
  void addSoupVertex(Index vertex) { index_.emplace(points_[vertex], vertex); }

  Index indexOf(const ExactPoint& point) {
    const auto [found, inserted] = index_.emplace(point, static_cast<Index>(points_.size()));
    if (inserted) points_.push_back(point);
    return found->second;
  }

  std::vector<ExactPoint> release() { return std::move(points_); }
  const ExactPoint& operator[](Index index) const { return points_[index]; }

 private:
  std::vector<ExactPoint> points_;
  std::map<ExactPoint, Index, LessXyz> index_;
};

ExactTriangle exactTriangle(const PointIndex& points, const TriangleIndices& triangle) {
  return {points[triangle[0]], points[triangle[1]], points[triangle[2]]};
}

// A coplanar intersection with area: the two triangles are triangulated together.
bool hasArea(const TriangleIntersection& intersection) {
  return boost::get<ExactTriangle>(&intersection) != nullptr ||
         boost::get<std::vector<ExactPoint>>(&intersection) != nullptr;
}

void addIntersection(const TriangleIntersection& intersection, Constraints& constraints) {
  if (const auto* point = boost::get<ExactPoint>(&intersection)) constraints.points.push_back(*point);
  if (const auto* segment = boost::get<ExactSegment>(&intersection)) constraints.segments.push_back(*segment);
}

// The axis to drop so that the plane's projection keeps its area: the normal's
// largest component (nonzero for a triangle that has an area).
int droppedAxis(const ExactTriangle& triangle) {
  const auto normal = CGAL::normal(triangle[0], triangle[1], triangle[2]);
  const double x = std::abs(CGAL::to_double(normal.x())), y = std::abs(CGAL::to_double(normal.y())),
               z = std::abs(CGAL::to_double(normal.z()));
  return x >= y && x >= z ? 0 : (y >= z ? 1 : 2);
}

// A cluster's plane seen in the coordinate plane that keeps its area: points are
// projected once (dropping one coordinate) and the triangulation runs on plane
// points, whose predicates CGAL filters directly; a new point is lifted back onto
// the plane exactly (solving the plane's equation for the dropped coordinate).
class ClusterPlane {
 public:
  using Point2 = ExactKernel::Point_2;

  explicit ClusterPlane(const ExactTriangle& triangle)
      : plane_(triangle[0], triangle[1], triangle[2]), dropped_(droppedAxis(triangle)) {}

  Point2 project(const ExactPoint& p) const {
    switch (dropped_) {
      case 0:
        return {p.y(), p.z()};
      case 1:
        return {p.z(), p.x()};
      default:
        return {p.x(), p.y()};
    }
  }

  ExactPoint lift(const Point2& q) const {
    const ExactKernel::FT a = plane_.a(), b = plane_.b(), c = plane_.c(), d = plane_.d();
    switch (dropped_) {
      case 0:
        return {-(b * q.x() + c * q.y() + d) / a, q.x(), q.y()};
      case 1:
        return {q.y(), -(a * q.y() + c * q.x() + d) / b, q.x()};
      default:
        return {q.x(), q.y(), -(a * q.x() + b * q.y() + d) / c};
    }
  }

 private:
  ExactKernel::Plane_3 plane_;
  int dropped_;
};

// Triangulates the union of a cluster's coplanar triangles with its constraints and
// appends the faces inside the triangles (each vertex of the soup keeps its index).
void triangulateCluster(const std::vector<Index>& members, const std::vector<TriangleIndices>& triangles,
                        const Constraints& constraints, PointIndex& points, SoupComplex& complex) {
  using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::optional<Index>, ExactKernel>;
  using FaceBase = CGAL::Constrained_triangulation_face_base_2<ExactKernel>;
  using Triangulation = CGAL::Constrained_Delaunay_triangulation_2<
      ExactKernel, CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>, CGAL::Exact_intersections_tag>;
  const ClusterPlane plane(exactTriangle(points, triangles[members.front()]));
  Triangulation triangulation;
  std::map<Index, ClusterPlane::Point2> projected;  // the members' corners
  const auto corner = [&](Index vertex) {
    const auto [found, inserted] = projected.try_emplace(vertex);
    if (inserted) found->second = plane.project(points[vertex]);
    return found->second;
  };
  const auto insertCorner = [&](Index vertex) {
    const auto handle = triangulation.insert(corner(vertex));
    handle->info() = vertex;
    return handle;
  };
  for (Index t : members) {
    for (int k = 0; k < 3; ++k) {
      triangulation.insert_constraint(insertCorner(triangles[t][k]), insertCorner(triangles[t][(k + 1) % 3]));
    }
  }
  for (const ExactSegment& segment : constraints.segments) {
    if (segment.is_degenerate()) {
      triangulation.insert(plane.project(segment.source()));
    } else {
      triangulation.insert_constraint(plane.project(segment.source()), plane.project(segment.target()));
    }
  }
  for (const ExactPoint& point : constraints.points) triangulation.insert(plane.project(point));

  const auto inside = [&](Index t, const ClusterPlane::Point2& point) {
    const ClusterPlane::Point2 &a = corner(triangles[t][0]), &b = corner(triangles[t][1]), &c = corner(triangles[t][2]);
    const CGAL::Orientation turn = CGAL::orientation(a, b, c);
    return CGAL::orientation(a, b, point) == turn && CGAL::orientation(b, c, point) == turn &&
           CGAL::orientation(c, a, point) == turn;
  };
  // A new vertex is lifted and looked up once (its faces share it): the lookup
  // compares equal points, which makes CGAL evaluate them exactly.
  const auto indexOf = [&](const typename Triangulation::Vertex_handle& vertex) {
    if (!vertex->info()) vertex->info() = points.indexOf(plane.lift(vertex->point()));
    return *vertex->info();
  };
  for (auto face = triangulation.finite_faces_begin(); face != triangulation.finite_faces_end(); ++face) {
    const ClusterPlane::Point2 centre =
        CGAL::centroid(face->vertex(0)->point(), face->vertex(1)->point(), face->vertex(2)->point());
    const auto source = std::find_if(members.begin(), members.end(), [&](Index t) { return inside(t, centre); });
    if (source == members.end()) continue;  // in the convex hull of the triangles, outside them
    complex.faces.push_back({indexOf(face->vertex(0)), indexOf(face->vertex(1)), indexOf(face->vertex(2))});
    complex.sourceTriangle.push_back(*source);
  }
}

// Whether two triangles meet anywhere but in the vertices they share and the edge
// between two shared vertices.
bool meetBeyondSharedFeatures(const std::vector<ExactPoint>& points, const TriangleIndices& first,
                              const TriangleIndices& second) {
  std::vector<Index> shared;
  for (Index vertex : first) {
    if (std::find(second.begin(), second.end(), vertex) != second.end()) shared.push_back(vertex);
  }
  const ExactTriangle a(points[first[0]], points[first[1]], points[first[2]]);
  const ExactTriangle b(points[second[0]], points[second[1]], points[second[2]]);
  const auto intersection = CGAL::intersection(a, b);
  if (!intersection) return false;
  if (shared.size() == 1) {
    const auto* point = boost::get<ExactPoint>(&*intersection);
    return !point || *point != points[shared[0]];
  }
  if (shared.size() == 2) {
    const auto* segment = boost::get<ExactSegment>(&*intersection);
    return !segment || !((segment->source() == points[shared[0]] && segment->target() == points[shared[1]]) ||
                         (segment->source() == points[shared[1]] && segment->target() == points[shared[0]]));
  }
  return true;
}

}  // namespace

std::vector<std::pair<Index, Index>> capMeetingPairs(const std::vector<ExactPoint>& points,
                                                     const std::vector<TriangleIndices>& triangles, Index firstCap) {
  std::vector<TreeEntry> entries;
  for (Index t = 0; t < triangles.size(); ++t) {
    const TriangleIndices& triangle = triangles[t];
    entries.emplace_back(boxAround({&points[triangle[0]], &points[triangle[1]], &points[triangle[2]]}), t);
  }
  const TriangleTree tree(entries.begin(), entries.end());
  std::vector<std::pair<Index, Index>> pairs;
  for (Index cap = firstCap; cap < triangles.size(); ++cap) {
    std::vector<TreeEntry> near;
    tree.query(bgi::intersects(entries[cap].first), std::back_inserter(near));
    for (const TreeEntry& entry : near) {
      const Index other = entry.second;
      if (other == cap || (other >= firstCap && other < cap)) continue;  // each pair of caps once
      if (meetBeyondSharedFeatures(points, triangles[cap], triangles[other])) {
        pairs.emplace_back(std::min(cap, other), std::max(cap, other));
      }
    }
  }
  return pairs;
}

SoupComplex refineSoup(const std::vector<ExactPoint>& soupPoints, const std::vector<TriangleIndices>& triangles,
                       const std::vector<std::pair<Index, Index>>& pairs) {
  PointIndex points(soupPoints);
  std::vector<bool> refined(triangles.size(), false);
  for (const auto& [first, second] : pairs) refined[first] = refined[second] = true;
  for (Index t = 0; t < triangles.size(); ++t) {
    if (!refined[t]) continue;
    for (Index vertex : triangles[t]) points.addSoupVertex(vertex);
  }

  // Intersections: coplanar overlaps join clusters, the rest constrain them.
  DisjointSets clusters(triangles.size());
  std::vector<std::pair<Index, TriangleIntersection>> pieces;  // (triangle, piece)
  for (const auto& [first, second] : pairs) {
    const auto intersection =
        CGAL::intersection(exactTriangle(points, triangles[first]), exactTriangle(points, triangles[second]));
    if (!intersection) continue;
    if (hasArea(*intersection)) {
      clusters.unite(first, second);
      continue;
    }
    pieces.emplace_back(first, *intersection);
    pieces.emplace_back(second, *intersection);
  }
  std::map<Index, std::vector<Index>> members;  // cluster -> its triangles
  std::map<Index, Constraints> constraints;     // cluster -> what splits it
  for (Index t = 0; t < triangles.size(); ++t) {
    if (refined[t]) members[clusters.find(t)].push_back(t);
  }
  for (const auto& [triangle, piece] : pieces) addIntersection(piece, constraints[clusters.find(triangle)]);

  SoupComplex complex;
  for (Index t = 0; t < triangles.size(); ++t) {
    if (refined[t]) continue;
    complex.faces.push_back(triangles[t]);
    complex.sourceTriangle.push_back(t);
  }
  for (const auto& [cluster, clusterMembers] : members) {
    triangulateCluster(clusterMembers, triangles, constraints[cluster], points, complex);
    complex.refinedTriangles += clusterMembers.size();
  }
  complex.points = points.release();
  return complex;
}

}  // namespace freespace::detail
