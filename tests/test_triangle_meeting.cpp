// How two triangles meet, from signs of determinants (ClosedTriangleTests: the
// soup refinement's fast path), against CGAL's exact intersection of two triangles.

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include "freespace/numbers/double_double_interval.h"
#include "geometry/closed_triangle_tests.h"
#include "geometry/vertex_predicates.h"

namespace freespace {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Tests = detail::ClosedTriangleTests<detail::VertexPredicates, std::uint32_t>;

Kernel::Point_3 exact(const Point3& p) { return {p.x(), p.y(), p.z()}; }

// The point a boundary point names: a corner, or where an edge crosses a plane.
Kernel::Point_3 pointOf(const std::vector<Point3>& vertices, const Tests::BoundaryPoint& point) {
  const auto [a, b] = point.edge;
  if (a == b) return exact(vertices[a]);
  const auto line = Kernel::Line_3(exact(vertices[a]), exact(vertices[b]));
  const auto plane = Kernel::Plane_3(exact(vertices[point.plane[0]]), exact(vertices[point.plane[1]]),
                                     exact(vertices[point.plane[2]]));
  const auto crossing = CGAL::intersection(line, plane);
  return boost::get<Kernel::Point_3>(*crossing);
}

// Random triangles with corners on a coarse grid (many corners on other triangles'
// edges and planes, many triangles in one plane, shared corners and edges), a
// tilted one now and then. Like a welded soup, one point has one index.
class GridTriangles {
 public:
  explicit GridTriangles(unsigned seed) : random_(seed) {}

  std::vector<Point3> vertices;

  // Every third triangle lies in a plane z = constant, where others may lie too.
  Tests::Triangle next() {
    const bool flat = std::uniform_int_distribution<int>(0, 2)(random_) == 0;
    const double height = std::uniform_int_distribution<int>(0, 3)(random_);
    for (;;) {
      std::array<std::uint32_t, 3> corners;
      for (std::uint32_t& corner : corners) {
        Point3 point = gridPoint();
        if (flat) point.z() = height;
        corner = indexOf(point);
      }
      const Point3 &a = vertices[corners[0]], &b = vertices[corners[1]], &c = vertices[corners[2]];
      if ((b - a).cross(c - a).squaredNorm() > 0) return corners;
    }
  }

 private:
  std::uint32_t indexOf(const Point3& point) {
    const auto [found, inserted] = index_.try_emplace({point.x(), point.y(), point.z()}, vertices.size());
    if (inserted) vertices.push_back(point);
    return found->second;
  }

  std::map<std::array<double, 3>, std::uint32_t> index_;
  Point3 gridPoint() {
    std::uniform_int_distribution<int> coordinate(0, 3);
    std::array<double, 3> axes;
    for (double& axis : axes) axis = coordinate(random_);
    if (std::uniform_int_distribution<int>(0, 9)(random_) == 0) axes[2] += 0.5;
    return {axes[0], axes[1], axes[2]};
  }

  std::mt19937 random_;
};

TEST(TriangleMeeting, BoundaryPointsSpanCGALsIntersectionAndOverlapsHaveItsArea) {
  GridTriangles grid(20261205);
  std::vector<std::pair<Tests::Triangle, Tests::Triangle>> pairs;
  for (int i = 0; i < 4000; ++i) {
    const Tests::Triangle first = grid.next();
    pairs.emplace_back(first, grid.next());
  }
  PredicateStatistics statistics;
  detail::VertexPredicates predicates(grid.vertices, statistics);
  Tests tests(predicates);
  const NearestRoundingScope rounding;
  int overlaps = 0, touchingInPlane = 0, points = 0, segments = 0, spanned = 0;
  for (const auto& [p, q] : pairs) {
    const auto triangle = [&](const Tests::Triangle& t) {
      return Kernel::Triangle_3(exact(grid.vertices[t[0]]), exact(grid.vertices[t[1]]), exact(grid.vertices[t[2]]));
    };
    const auto intersection = CGAL::intersection(triangle(p), triangle(q));
    ASSERT_EQ(tests.trianglesIntersect(p, q), bool(intersection));
    if (!intersection) continue;
    const bool hasArea =
        boost::get<Kernel::Triangle_3>(&*intersection) || boost::get<std::vector<Kernel::Point_3>>(&*intersection);
    if (tests.inPlaneOf(p, q)) {
      EXPECT_EQ(tests.coplanarInteriorsOverlap(p, q), hasArea);
      ++(hasArea ? overlaps : touchingInPlane);
      continue;
    }
    ASSERT_FALSE(hasArea);
    std::vector<Kernel::Point_3> found;
    for (const Tests::BoundaryPoint& point : tests.boundaryMeetingPoints(p, q)) {
      found.push_back(pointOf(grid.vertices, point));
    }
    std::sort(found.begin(), found.end());
    EXPECT_TRUE(std::adjacent_find(found.begin(), found.end()) == found.end()) << "a point named twice";
    if (const auto* point = boost::get<Kernel::Point_3>(&*intersection)) {
      ++points;
      EXPECT_EQ(found, std::vector<Kernel::Point_3>{*point});
    } else {
      const auto& segment = *boost::get<Kernel::Segment_3>(&*intersection);
      ++segments;
      ASSERT_GE(found.size(), 2u);
      for (const Kernel::Point_3& point : found) EXPECT_TRUE(segment.has_on(point));
      EXPECT_TRUE(std::count(found.begin(), found.end(), segment.source()) == 1 &&
                  std::count(found.begin(), found.end(), segment.target()) == 1);
      if (found.size() > 2) ++spanned;
    }
  }
  // Every kind of meeting occurs among the pairs.
  EXPECT_GT(overlaps, 10);
  EXPECT_GT(touchingInPlane, 10);
  EXPECT_GT(points, 10);
  EXPECT_GT(segments, 10);
  RecordProperty("more than two boundary points on a segment", spanned);
}

}  // namespace
}  // namespace freespace
