// Caps for the planar openings of a soup (soup_enclosure.h).
//
// Modelling tools often leave out faces nobody sees, such as the bottoms of walls
// standing on the floor or of a car standing on the road: the rest of the surface
// then encloses nothing. An opening is found where a chain of open edges (each
// bordering one triangle) turns within a plane (points within the repair tolerance of
// it count as in it): in that plane, the soup's edges that lie in it cut the plane
// into regions (with new points where edges cross), and a bounded region that no
// triangle covers and that an open edge borders is a candidate cap (walls that stand
// in one another, each without its bottom and its buried ends, have one opening
// together). Candidates are only offered: the enclosure keeps
// a cap's faces where they separate an enclosed region from the outside, and only if
// that region's caps all lie in one plane (a courtyard whose floor and sky would both
// be capped stays open), so a cap never adds a sheet.

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <unordered_map>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Projection_traits_xz_3.h>
#include <CGAL/Projection_traits_yz_3.h>

#include "soup_complex.h"

namespace freespace::detail {

namespace {

using Index = std::uint32_t;
using EdgeKey = std::uint64_t;

EdgeKey edgeKey(Index a, Index b) { return (EdgeKey{std::min(a, b)} << 32) | std::max(a, b); }
Index edgeLow(EdgeKey key) { return static_cast<Index>(key >> 32); }
Index edgeHigh(EdgeKey key) { return static_cast<Index>(key & 0xFFFFFFFFu); }

ExactPoint exactPoint(const Point3& point) { return {point.x(), point.y(), point.z()}; }

// Edges of some triangles with the number of triangles using each.
std::unordered_map<EdgeKey, Index> edgeUses(const std::vector<TriangleIndices>& triangles) {
  std::unordered_map<EdgeKey, Index> uses;
  for (const TriangleIndices& triangle : triangles) {
    for (int corner = 0; corner < 3; ++corner) ++uses[edgeKey(triangle[corner], triangle[(corner + 1) % 3])];
  }
  return uses;
}

// A plane through three soup vertices; points within the tolerance of it count as
// lying in it (openings in faces that float noise bent slightly are still planar).
struct Plane {
  Point3 point;
  Point3 unitNormal;

  bool holds(const Point3& p, double tolerance) const { return std::abs(unitNormal.dot(p - point)) <= tolerance; }
};

// The plane through a, b and c, unless they lie within the tolerance of one line.
std::optional<Plane> planeThrough(const Point3& a, const Point3& b, const Point3& c, double tolerance) {
  const Point3 normal = (b - a).cross(c - a);
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  if (!(normal.norm() > tolerance * longest)) return std::nullopt;
  return Plane{a, normal.normalized()};
}

// The planes found so far, each once, numbered.
class PlaneList {
 public:
  PlaneList(const std::vector<Point3>& vertices, double tolerance) : vertices_(vertices), tolerance_(tolerance) {}

  // The number of the plane holding a, b and c, a new one if none does yet.
  Index planeOf(const Plane& candidate, Index a, Index b, Index c) {
    for (Index p = 0; p < planes_.size(); ++p) {
      if (planes_[p].holds(vertices_[a], tolerance_) && planes_[p].holds(vertices_[b], tolerance_) &&
          planes_[p].holds(vertices_[c], tolerance_)) {
        return p;
      }
    }
    planes_.push_back(candidate);
    return static_cast<Index>(planes_.size() - 1);
  }

  const Plane& operator[](Index p) const { return planes_[p]; }

 private:
  const std::vector<Point3>& vertices_;
  double tolerance_;
  std::vector<Plane> planes_;
};

// The planes in which two open edges meet at an angle.
std::vector<Index> openingPlanes(const std::vector<Point3>& vertices, const std::unordered_map<EdgeKey, Index>& uses,
                                 double tolerance, PlaneList& planes) {
  std::map<Index, std::vector<Index>> openNeighbours;
  for (const auto& [key, count] : uses) {
    if (count != 1) continue;
    openNeighbours[edgeLow(key)].push_back(edgeHigh(key));
    openNeighbours[edgeHigh(key)].push_back(edgeLow(key));
  }
  std::vector<Index> found;
  for (const auto& [corner, neighbours] : openNeighbours) {
    for (std::size_t i = 0; i < neighbours.size(); ++i) {
      for (std::size_t j = i + 1; j < neighbours.size(); ++j) {
        const Index a = neighbours[i], b = neighbours[j];
        const std::optional<Plane> plane = planeThrough(vertices[a], vertices[corner], vertices[b], tolerance);
        if (plane) found.push_back(planes.planeOf(*plane, a, corner, b));
      }
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

// The new points of caps, each once, numbered after the soup's vertices.
class NewPoints {
 public:
  NewPoints(std::size_t firstIndex, std::vector<ExactPoint>& points) : firstIndex_(firstIndex), points_(points) {}

  Index indexOf(const ExactPoint& point) {
    const auto [found, inserted] = index_.emplace(point, static_cast<Index>(firstIndex_ + points_.size()));
    if (inserted) points_.push_back(point);
    return found->second;
  }

 private:
  struct LessXyz {
    bool operator()(const ExactPoint& a, const ExactPoint& b) const { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; }
  };

  std::size_t firstIndex_;
  std::vector<ExactPoint>& points_;
  std::map<ExactPoint, Index, LessXyz> index_;
};

// The uncovered bounded regions of one plane that an open edge borders, as triangles
// on soup vertices and new points; `Traits` projects the plane.
template <class Traits>
class PlaneRegions {
 public:
  using Triangulation = CGAL::Constrained_Delaunay_triangulation_2<Traits, CGAL::Default, CGAL::Exact_intersections_tag>;
  using Face = typename Triangulation::Face_handle;

  PlaneRegions(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
               const std::unordered_map<EdgeKey, Index>& uses, const Plane& plane, double tolerance)
      : vertices_(vertices) {
    const auto inPlane = [&](Index v) { return plane.holds(vertices[v], tolerance); };
    std::vector<TreeEntry> openEdgeBoxes;
    for (const auto& [key, count] : uses) {
      if (!inPlane(edgeLow(key)) || !inPlane(edgeHigh(key))) continue;
      const ExactPoint low = exactPoint(vertices[edgeLow(key)]), high = exactPoint(vertices[edgeHigh(key)]);
      triangulation_.insert_constraint(low, high);
      if (count == 1) {
        openEdgeBoxes.emplace_back(triangleBox(vertices, {edgeLow(key), edgeHigh(key), edgeHigh(key)}),
                                   static_cast<Index>(openEdges_.size()));
        openEdges_.emplace_back(low, high);
      }
      pointIndex_.emplace(low, edgeLow(key));
      pointIndex_.emplace(high, edgeHigh(key));
    }
    openEdgeTree_ = TriangleTree(openEdgeBoxes.begin(), openEdgeBoxes.end());
    std::vector<TreeEntry> coveringBoxes;
    for (const TriangleIndices& triangle : triangles) {
      if (!inPlane(triangle[0]) || !inPlane(triangle[1]) || !inPlane(triangle[2])) continue;
      coveringBoxes.emplace_back(triangleBox(vertices, triangle), static_cast<Index>(covering_.size()));
      covering_.push_back(triangle);
    }
    coveringTree_ = TriangleTree(coveringBoxes.begin(), coveringBoxes.end());
  }

  void appendCaps(NewPoints& newPoints, std::vector<TriangleIndices>& caps) {
    std::map<Face, bool> visited;
    for (const Face face : triangulation_.finite_face_handles()) {
      if (visited[face]) continue;
      const Region region = regionFrom(face, visited);
      if (region.bounded && region.bordersOpenEdge && !covered(region.faces.front())) {
        addRegion(region, newPoints, caps);
      }
    }
  }

 private:
  struct LessXyz {
    bool operator()(const ExactPoint& a, const ExactPoint& b) const { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; }
  };

  struct Region {
    std::vector<Face> faces;
    bool bounded = true;
    bool bordersOpenEdge = false;
  };

  // The faces reached from `start` without crossing a constraint.
  Region regionFrom(Face start, std::map<Face, bool>& visited) {
    Region region;
    std::vector<Face> stack{start};
    visited[start] = true;
    while (!stack.empty()) {
      const Face face = stack.back();
      stack.pop_back();
      region.faces.push_back(face);
      for (int i = 0; i < 3; ++i) {
        if (triangulation_.is_constrained({face, i})) {
          region.bordersOpenEdge = region.bordersOpenEdge || isOpenEdge(face, i);
          continue;
        }
        const Face next = face->neighbor(i);
        if (triangulation_.is_infinite(next)) {
          region.bounded = false;
        } else if (!visited[next]) {
          visited[next] = true;
          stack.push_back(next);
        }
      }
    }
    return region;
  }

  // A constrained edge lies along one of the piece's edges, or a part of one.
  bool isOpenEdge(Face face, int i) const {
    const ExactPoint& p = face->vertex(Triangulation::ccw(i))->point();
    const ExactPoint& q = face->vertex(Triangulation::cw(i))->point();
    std::vector<TreeEntry> near;
    openEdgeTree_.query(bgi::intersects(boxAround({&p, &q})), std::back_inserter(near));
    return std::any_of(near.begin(), near.end(), [&](const TreeEntry& entry) {
      const auto& [first, second] = openEdges_[entry.second];
      return CGAL::collinear(first, second, p) && CGAL::collinear(first, second, q) &&
             CGAL::collinear_are_ordered_along_line(first, p, second) &&
             CGAL::collinear_are_ordered_along_line(first, q, second);
    });
  }

  // A region lies in no triangle's edge (they are all constraints), so it is covered
  // when the centre of one of its faces lies inside a triangle of the plane.
  bool covered(Face face) const {
    const ExactPoint centre = CGAL::centroid(face->vertex(0)->point(), face->vertex(1)->point(), face->vertex(2)->point());
    const auto orientation = Traits().orientation_2_object();
    std::vector<TreeEntry> near;
    coveringTree_.query(bgi::intersects(boxAround({&centre})), std::back_inserter(near));
    return std::any_of(near.begin(), near.end(), [&](const TreeEntry& entry) {
      const TriangleIndices& triangle = covering_[entry.second];
      const ExactPoint a = exactPoint(vertices_[triangle[0]]), b = exactPoint(vertices_[triangle[1]]),
                       c = exactPoint(vertices_[triangle[2]]);
      const CGAL::Orientation turn = orientation(a, b, c);
      return orientation(a, b, centre) == turn && orientation(b, c, centre) == turn &&
             orientation(c, a, centre) == turn;
    });
  }

  void addRegion(const Region& region, NewPoints& newPoints, std::vector<TriangleIndices>& caps) const {
    for (const Face& face : region.faces) {
      TriangleIndices corners;
      for (int i = 0; i < 3; ++i) {
        const ExactPoint& point = face->vertex(i)->point();
        const auto found = pointIndex_.find(point);
        corners[i] = found != pointIndex_.end() ? found->second : newPoints.indexOf(point);
      }
      caps.push_back(corners);
    }
  }

  const std::vector<Point3>& vertices_;
  Triangulation triangulation_;
  std::vector<std::pair<ExactPoint, ExactPoint>> openEdges_;
  TriangleTree openEdgeTree_;  // boxes of openEdges_
  std::map<ExactPoint, Index, LessXyz> pointIndex_;
  std::vector<TriangleIndices> covering_;
  TriangleTree coveringTree_;  // boxes of covering_
};

// The axis to drop so that the plane's projection keeps its area.
int droppedAxis(const Plane& plane) {
  int axis = 2;
  plane.unitNormal.cwiseAbs().maxCoeff(&axis);
  return axis;
}

template <class Traits>
void appendRegions(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
                   const std::unordered_map<EdgeKey, Index>& uses, const PlaneList& planes, Index plane,
                   double tolerance, NewPoints& newPoints, PlanarCaps& caps) {
  PlaneRegions<Traits>(vertices, triangles, uses, planes[plane], tolerance).appendCaps(newPoints, caps.triangles);
}

}  // namespace

PlanarCaps planarCaps(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
                      double tolerance) {
  PlanarCaps caps;
  PlaneList planes(vertices, tolerance);
  NewPoints newPoints(vertices.size(), caps.newPoints);
  const std::unordered_map<EdgeKey, Index> uses = edgeUses(triangles);
  for (Index plane : openingPlanes(vertices, uses, tolerance, planes)) {
    switch (droppedAxis(planes[plane])) {
      case 0:
        appendRegions<CGAL::Projection_traits_yz_3<ExactKernel>>(vertices, triangles, uses, planes, plane, tolerance,
                                                                 newPoints, caps);
        break;
      case 1:
        appendRegions<CGAL::Projection_traits_xz_3<ExactKernel>>(vertices, triangles, uses, planes, plane, tolerance,
                                                                 newPoints, caps);
        break;
      default:
        appendRegions<CGAL::Projection_traits_xy_3<ExactKernel>>(vertices, triangles, uses, planes, plane, tolerance,
                                                                 newPoints, caps);
    }
  }
  return caps;
}

}  // namespace freespace::detail
