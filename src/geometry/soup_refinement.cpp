// Refinement of a soup's triangles along their intersections (soup_complex.h).

#include <array>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <tuple>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lazy.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/intersections.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include "closed_triangle_tests.h"
#include "disjoint_sets.h"
#include "freespace/numbers/double_double_interval.h"
#include "soup_complex.h"
#include "soup_seams.h"
#include "vertex_predicates.h"

namespace freespace::detail {

namespace {

using Index = std::uint32_t;
using ExactSegment = ExactKernel::Segment_3;
using ExactTriangle = ExactKernel::Triangle_3;

// What a cluster of coplanar triangles must be split along: segments and points
// (indices of the complex's points) where other triangles meet them.
struct Constraints {
  std::vector<std::pair<Index, Index>> segments;
  std::vector<Index> points;
};

// A construction of CGAL's lazy exact kernel from one functor template, written
// once for both of its kernels: its result is one node of the kernel's graph of
// constructions, evaluated exactly (in one step, when first needed) from its
// arguments. CGAL's own constructions and coordinate accessors make a node each, and
// the first exact evaluation of every node is synchronised (a system call each).
template <template <class> class Functor>
using LazyConstruction =
    CGAL::Lazy_construction<ExactKernel, Functor<ExactKernel::Approximate_kernel>, Functor<ExactKernel::Exact_kernel>>;

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

// How two triangles that meet do: overlapping in one plane (an area: they are
// triangulated together), else in a point or a segment (its ends), indices of the
// complex's points, that splits both.
struct Meeting {
  bool overlap = false;
  std::vector<Index> points;
};

void addConstraint(const Meeting& meeting, Constraints& constraints) {
  if (meeting.points.size() == 1) constraints.points.push_back(meeting.points[0]);
  if (meeting.points.size() == 2) constraints.segments.emplace_back(meeting.points[0], meeting.points[1]);
}

// The meeting of two triangles by CGAL's intersection of triangles, nothing if they are apart.
std::optional<Meeting> generalMeeting(const ExactTriangle& first, const ExactTriangle& second, PointIndex& points) {
  const auto intersection = CGAL::intersection(first, second);
  if (!intersection) return std::nullopt;
  Meeting meeting;
  meeting.overlap = hasArea(*intersection);
  if (const auto* point = boost::get<ExactPoint>(&*intersection)) meeting.points = {points.indexOf(*point)};
  if (const auto* segment = boost::get<ExactSegment>(&*intersection)) {
    meeting.points = {points.indexOf(segment->source()), points.indexOf(segment->target())};
  }
  return meeting;
}

// The axis to drop so that the plane's projection keeps its area: the normal's
// largest component (nonzero for a triangle that has an area).
int droppedAxis(const ExactTriangle& triangle) {
  const auto normal = CGAL::normal(triangle[0], triangle[1], triangle[2]);
  const double x = std::abs(CGAL::to_double(normal.x())), y = std::abs(CGAL::to_double(normal.y())),
               z = std::abs(CGAL::to_double(normal.z()));
  return x >= y && x >= z ? 0 : (y >= z ? 1 : 2);
}

// The point p without its coordinate `dropped` (the next two in cyclic order), in
// kernel K.
template <class K>
struct DropCoordinate {
  using result_type = typename K::Point_2;
  result_type operator()(const typename K::Point_3& p, int dropped) const {
    return {p[(dropped + 1) % 3], p[(dropped + 2) % 3]};
  }
};

// The point of `plane` whose coordinates other than `dropped` are q's (as
// DropCoordinate orders them), in kernel K; the plane's normal has a nonzero
// coordinate `dropped`.
template <class K>
struct LiftOntoPlane {
  using result_type = typename K::Point_3;
  result_type operator()(const typename K::Plane_3& plane, const typename K::Point_2& q, int dropped) const {
    const std::array<typename K::FT, 3> normal{plane.a(), plane.b(), plane.c()};
    const int u = (dropped + 1) % 3, v = (dropped + 2) % 3;
    std::array<typename K::FT, 3> coordinates;
    coordinates[u] = q.x();
    coordinates[v] = q.y();
    coordinates[dropped] = -(normal[u] * q.x() + normal[v] * q.y() + plane.d()) / normal[dropped];
    return {coordinates[0], coordinates[1], coordinates[2]};
  }
};

// A cluster's plane seen in the coordinate plane that keeps its area: points are
// projected once (dropping one coordinate) and the triangulation runs on plane
// points, whose predicates CGAL filters directly; a new point is lifted back onto
// the plane exactly (solving the plane's equation for the dropped coordinate). Both
// are single lazy nodes (LazyConstruction).
class ClusterPlane {
 public:
  using Point2 = ExactKernel::Point_2;

  explicit ClusterPlane(const ExactTriangle& triangle)
      : plane_(triangle[0], triangle[1], triangle[2]), dropped_(droppedAxis(triangle)) {}

  Point2 project(const ExactPoint& p) const {
    const LazyConstruction<DropCoordinate> drop;
    return drop(p, dropped_);
  }

  ExactPoint lift(const Point2& q) const {
    const LazyConstruction<LiftOntoPlane> lift;
    return lift(plane_, q, dropped_);
  }

 private:
  ExactKernel::Plane_3 plane_;
  int dropped_;
};

// Where the line through a and b crosses the plane through p, q and r (they are not
// parallel), in kernel K, with each coordinate whose bit is set in `edgeConstant`
// taken from a (the edge keeps it) and else, if set in `planeConstant`, from p.
template <class K>
struct EdgePlaneCrossing {
  using Point = typename K::Point_3;
  using result_type = Point;
  Point operator()(const Point& p, const Point& q, const Point& r, const Point& a, const Point& b, int edgeConstant,
                   int planeConstant) const {
    std::optional<Point> general;  // made only for a coordinate that needs it
    std::array<typename K::FT, 3> coordinates;
    for (int axis = 0; axis < 3; ++axis) {
      if (edgeConstant >> axis & 1) {
        coordinates[axis] = a[axis];
      } else if (planeConstant >> axis & 1) {
        coordinates[axis] = p[axis];
      } else {
        if (!general) general = K().construct_plane_line_intersection_point_3_object()(p, q, r, a, b);
        coordinates[axis] = (*general)[axis];
      }
    }
    return {coordinates[0], coordinates[1], coordinates[2]};
  }
};

// How pairs of triangles on a soup's vertices meet, from signs of determinants of
// the vertices' coordinates (decided in doubles almost always): a new point is made
// only where an edge crosses the other triangle's plane, as one construction from
// that edge and plane, evaluated exactly when compared. CGAL's intersection of two
// triangles would evaluate every degenerate meeting in exact rationals at once (a
// corner on the other's face, faces in one plane: most pairs of a soup of boxes).
// Each crossing is made once, whichever pairs of triangles meet there: looking up
// a point among the others compares it exactly with its equals. Triangles with new
// points (caps), and the rare pairs whose meeting is not a point, a segment spanned
// by two boundary points or an overlap, go to CGAL.
class PairMeetings {
 public:
  PairMeetings(const std::vector<Point3>& vertices, PointIndex& points, SeamPoints& seamPoints)
      : vertices_(vertices), points_(points), seamPoints_(seamPoints), predicates_(vertices, statistics_) {}

  // Inside a NearestRoundingScope.
  std::optional<Meeting> of(const TriangleIndices& first, const TriangleIndices& second) {
    if (onSoupVertices(first) && onSoupVertices(second)) {
      Tests tests(predicates_);
      const Triangle p{first[0], first[1], first[2]}, q{second[0], second[1], second[2]};
      if (!tests.inPlaneOf(p, q)) {
        const std::vector<Tests::BoundaryPoint> found = tests.boundaryMeetingPoints(p, q);
        if (found.size() == 1) return touching(indexOf(found[0]));
        if (found.size() == 2) return Meeting{false, {indexOf(found[0]), indexOf(found[1])}};
      } else if (tests.coplanarInteriorsOverlap(p, q)) {
        return Meeting{true, {}};
      }
    }
    std::optional<Meeting> meeting =
        generalMeeting(exactTriangle(points_, first), exactTriangle(points_, second), points_);
    if (meeting) {
      for (Index point : meeting->points) seamPoints_.keep(point);
    }
    return meeting;
  }

 private:
  using Tests = ClosedTriangleTests<VertexPredicates, Index>;
  using Triangle = Tests::Triangle;

  Meeting touching(Index point) {
    seamPoints_.keep(point);
    return {false, {point}};
  }

  bool onSoupVertices(const TriangleIndices& triangle) const {
    return std::all_of(triangle.begin(), triangle.end(), [&](Index vertex) { return vertex < vertices_.size(); });
  }

  // Where an edge crosses a plane, by the edge's ends (in order) and the plane: its
  // axis and offset when it is parallel to a coordinate plane (one name for every
  // triangle in it, such as the faces of walls glued together), else the corners of
  // the triangle that spans it (in order), with axis -1.
  using PlaneCrossing = std::tuple<Index, Index, int, double, Triangle>;

  PlaneCrossing planeCrossing(Index a, Index b, const Triangle& plane) const {
    for (int axis = 0; axis < 3; ++axis) {
      const double offset = vertices_[plane[0]][axis];
      if (vertices_[plane[1]][axis] == offset && vertices_[plane[2]][axis] == offset) {
        return {std::min(a, b), std::max(a, b), axis, offset, Triangle{}};
      }
    }
    Triangle corners = plane;
    std::sort(corners.begin(), corners.end());
    return {std::min(a, b), std::max(a, b), -1, 0.0, corners};
  }

  // Each crossing point is made once under every name it is met by: its edge and
  // plane, and for a crossing of two edges (a boundary point's key then names the
  // two), those edges. Another name for it still finds it among the points, by an
  // exact comparison. Every name tells the seam points which edges the point lies on.
  Index indexOf(const Tests::BoundaryPoint& point) {
    const auto [a, b] = point.edge;
    if (a == b) return a;
    const Index index = crossingIndex(point);
    seamPoints_.liesOn(index, a, b);
    if (point.onTwoEdges()) {
      seamPoints_.liesOn(index, point.key[0], point.key[1]);
      seamPoints_.liesOn(index, point.key[2], point.key[3]);
    }
    return index;
  }

  Index crossingIndex(const Tests::BoundaryPoint& point) {
    const auto [a, b] = point.edge;
    const PlaneCrossing byPlane = planeCrossing(a, b, point.plane);
    const bool onTwoEdges = point.onTwoEdges();
    if (onTwoEdges) {
      const auto known = edgeCrossings_.find(point.key);
      if (known != edgeCrossings_.end()) {
        planeCrossings_.emplace(byPlane, known->second);
        return known->second;
      }
    }
    const auto [found, inserted] = planeCrossings_.try_emplace(byPlane);
    if (inserted) found->second = points_.indexOf(crossing(a, b, point.plane));
    if (onTwoEdges) edgeCrossings_.emplace(point.key, found->second);
    return found->second;
  }

  // Where the edge ab crosses the plane of `plane`, one lazy node (EdgePlaneCrossing):
  // each coordinate that the edge or the plane keeps constant is that double, so the
  // crossings of walls parallel to coordinate planes are doubles, or nearly, whose
  // degenerate predicates CGAL's interval filter decides without exact evaluation.
  ExactPoint crossing(Index a, Index b, const Triangle& plane) const {
    int edgeConstant = 0, planeConstant = 0;  // bits by axis
    for (int axis = 0; axis < 3; ++axis) {
      const auto constant = [&](Index u, Index w) { return vertices_[u][axis] == vertices_[w][axis]; };
      if (constant(a, b)) edgeConstant |= 1 << axis;
      if (constant(plane[0], plane[1]) && constant(plane[0], plane[2])) planeConstant |= 1 << axis;
    }
    const LazyConstruction<EdgePlaneCrossing> construct;
    return construct(points_[plane[0]], points_[plane[1]], points_[plane[2]], points_[a], points_[b], edgeConstant,
                     planeConstant);
  }

  const std::vector<Point3>& vertices_;
  PointIndex& points_;
  SeamPoints& seamPoints_;
  std::map<PlaneCrossing, Index> planeCrossings_;
  std::map<std::array<Index, 4>, Index> edgeCrossings_;
  PredicateStatistics statistics_;
  VertexPredicates predicates_;
};

using ClusterTriangulation = CGAL::Constrained_Delaunay_triangulation_2<
    ExactKernel,
    CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<std::optional<Index>, ExactKernel>,
                                         CGAL::Constrained_triangulation_face_base_2<ExactKernel>>,
    CGAL::Exact_intersections_tag>;

// The points of a cluster (the members' corners, the constraints' ends and points),
// each once, inserted in spatial order (by their approximations), each located from
// the last one: a short walk, whose orientation tests at degenerate places (points on
// lines through others, everywhere on walls parallel to coordinate planes) are
// evaluated exactly. Returns each index's vertex.
std::map<Index, ClusterTriangulation::Vertex_handle> insertPoints(
    const std::map<Index, ClusterPlane::Point2>& projected, ClusterTriangulation& triangulation) {
  using Approximate = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Approximate::Point_2> approximations;
  std::vector<std::map<Index, ClusterPlane::Point2>::const_iterator> entries;
  for (auto entry = projected.begin(); entry != projected.end(); ++entry) {
    approximations.emplace_back(CGAL::to_double(entry->second.x()), CGAL::to_double(entry->second.y()));
    entries.push_back(entry);
  }
  std::vector<std::size_t> order(entries.size());
  std::iota(order.begin(), order.end(), 0);
  using Traits =
      CGAL::Spatial_sort_traits_adapter_2<Approximate, CGAL::Pointer_property_map<Approximate::Point_2>::type>;
  CGAL::spatial_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(approximations)));
  std::map<Index, ClusterTriangulation::Vertex_handle> vertices;
  ClusterTriangulation::Face_handle hint;
  for (std::size_t k : order) {
    const auto vertex = triangulation.insert(entries[k]->second, hint);
    vertex->info() = entries[k]->first;
    vertices[entries[k]->first] = vertex;
    hint = vertex->face();
  }
  return vertices;
}

// Triangulates the union of a cluster's coplanar triangles with its constraints and
// appends the faces inside the triangles (each vertex of the soup keeps its index).
void triangulateCluster(const std::vector<Index>& members, const std::vector<TriangleIndices>& triangles,
                        const Constraints& constraints, const Seams& seams, PointIndex& points, SoupComplex& complex) {
  const ClusterPlane plane(exactTriangle(points, triangles[members.front()]));
  std::map<Index, ClusterPlane::Point2> projected;  // the points inserted, by index
  const auto corner = [&](Index vertex) {
    const auto [found, inserted] = projected.try_emplace(vertex);
    if (inserted) found->second = plane.project(points[vertex]);
    return found->second;
  };
  for (Index t : members) {
    for (Index vertex : triangles[t]) corner(vertex);
  }
  for (const auto& [source, target] : constraints.segments) {
    corner(source);
    corner(target);
  }
  for (Index point : constraints.points) corner(point);
  ClusterTriangulation triangulation;
  const std::map<Index, ClusterTriangulation::Vertex_handle> vertices = insertPoints(projected, triangulation);
  for (Index t : members) {
    for (int k = 0; k < 3; ++k) {
      const Index a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      if (!seams.sides(a, b)) triangulation.insert_constraint(vertices.at(a), vertices.at(b));
    }
  }
  for (const auto& [source, target] : constraints.segments) {
    if (source != target) triangulation.insert_constraint(vertices.at(source), vertices.at(target));
  }

  // Closed: a face's interior lies inside the members' union or outside it (its
  // boundary edges are constraints), but may cross a seam, with its centre on it.
  const auto inside = [&](Index t, const ClusterPlane::Point2& point) {
    const ClusterPlane::Point2 &a = corner(triangles[t][0]), &b = corner(triangles[t][1]), &c = corner(triangles[t][2]);
    const CGAL::Orientation beyond = CGAL::opposite(CGAL::orientation(a, b, c));
    return CGAL::orientation(a, b, point) != beyond && CGAL::orientation(b, c, point) != beyond &&
           CGAL::orientation(c, a, point) != beyond;
  };
  // A vertex the triangulation made (where constraints cross) is lifted and looked up
  // once (its faces share it): the lookup compares equal points, which makes CGAL
  // evaluate them exactly.
  const auto indexOf = [&](const ClusterTriangulation::Vertex_handle& vertex) {
    if (!vertex->info()) vertex->info() = points.indexOf(plane.lift(vertex->point()));
    return *vertex->info();
  };
  // The points of a lone triangle all lie in it, and so does every face.
  const auto sourceOf = [&](const ClusterTriangulation::Face_handle& face) {
    if (members.size() == 1) return members.begin();
    const ClusterPlane::Point2 centre =
        CGAL::centroid(face->vertex(0)->point(), face->vertex(1)->point(), face->vertex(2)->point());
    return std::find_if(members.begin(), members.end(), [&](Index t) { return inside(t, centre); });
  };
  const auto cluster = static_cast<Index>(members.size() == 1 ? SoupComplex::kNoCluster : complex.clusters.size());
  if (cluster != SoupComplex::kNoCluster) {
    complex.clusters.emplace_back();
    for (Index t : members) complex.clusters.back().emplace_back(t, triangles[t]);
  }
  for (auto face = triangulation.finite_faces_begin(); face != triangulation.finite_faces_end(); ++face) {
    const auto source = sourceOf(face);
    if (source == members.end()) continue;  // in the convex hull of the triangles, outside them
    complex.faces.push_back({indexOf(face->vertex(0)), indexOf(face->vertex(1)), indexOf(face->vertex(2))});
    complex.sourceTriangle.push_back(*source);
    complex.clusterOf.push_back(cluster);
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
  const ExactTriangle a = exactTriangle(points, first), b = exactTriangle(points, second);
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

// A meeting of two triangles as it splits one of them (`own`).
struct Piece {
  Index own;
  Index other;
  Meeting meeting;
};

// What splits each cluster (by its representative), with the points that only cuts
// of planar faces made left out where nothing needs them (SeamPoints).
std::map<Index, Constraints> clusterConstraints(const std::vector<Piece>& pieces, DisjointSets& clusters,
                                                SeamPoints& seamPoints) {
  std::map<Index, Constraints> constraints;
  for (const Piece& piece : pieces) {
    const Index cluster = clusters.find(piece.own);
    addConstraint(piece.meeting, constraints[cluster]);
    if (piece.meeting.points.size() == 2) {
      seamPoints.addSegment(cluster, piece.own, piece.other, {piece.meeting.points[0], piece.meeting.points[1]});
    }
  }
  for (auto& [cluster, around] : seamPoints.joins()) {
    Constraints& split = constraints[cluster];
    split.segments = SeamPoints::joined(split.segments, std::move(around));
  }
  return constraints;
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

SoupComplex refineSoup(const std::vector<Point3>& soupVertices, const std::vector<ExactPoint>& soupPoints,
                       const std::vector<TriangleIndices>& triangles, const std::vector<std::pair<Index, Index>>& pairs,
                       Index firstCap) {
  PointIndex points(soupPoints);
  std::vector<bool> refined(triangles.size(), false);
  for (const auto& [first, second] : pairs) refined[first] = refined[second] = true;
  for (Index t = 0; t < triangles.size(); ++t) {
    if (!refined[t]) continue;
    for (Index vertex : triangles[t]) points.addSoupVertex(vertex);
  }
  std::vector<bool> seamSides = refined;  // caps are never cut by a modelling tool
  std::fill(seamSides.begin() + std::min<std::size_t>(firstCap, triangles.size()), seamSides.end(), false);
  const Seams seams(soupVertices, triangles, seamSides);
  SeamPoints seamPoints(soupVertices, triangles, seams);

  // Intersections: coplanar overlaps and seams join clusters, the rest constrain them.
  DisjointSets clusters(triangles.size());
  std::vector<Piece> pieces;
  {
    PairMeetings meetings(soupVertices, points, seamPoints);
    const NearestRoundingScope rounding;
    for (const auto& [first, second] : pairs) {
      const std::optional<Meeting> meeting = meetings.of(triangles[first], triangles[second]);
      if (!meeting) continue;
      if (meeting->overlap) {
        clusters.unite(first, second);
        continue;
      }
      pieces.push_back({first, second, *meeting});
      pieces.push_back({second, first, *meeting});
    }
  }
  for (const auto& [edge, sides] : seams.all()) clusters.unite(sides.first, sides.second);
  std::map<Index, std::vector<Index>> members;  // cluster -> its triangles
  for (Index t = 0; t < triangles.size(); ++t) {
    if (refined[t]) members[clusters.find(t)].push_back(t);
  }
  std::map<Index, Constraints> constraints = clusterConstraints(pieces, clusters, seamPoints);

  SoupComplex complex;
  for (Index t = 0; t < triangles.size(); ++t) {
    if (refined[t]) continue;
    complex.faces.push_back(triangles[t]);
    complex.sourceTriangle.push_back(t);
    complex.clusterOf.push_back(SoupComplex::kNoCluster);
  }
  for (const auto& [cluster, clusterMembers] : members) {
    triangulateCluster(clusterMembers, triangles, constraints[cluster], seams, points, complex);
    complex.refinedTriangles += clusterMembers.size();
  }
  complex.points = points.release();
  return complex;
}

}  // namespace freespace::detail
