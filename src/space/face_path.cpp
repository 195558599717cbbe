#include "freespace/space/face_path.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <iterator>
#include <map>

#include "freespace/geometry/interval_segment_distance.h"
#include "freespace/numbers/interval.h"

namespace freespace {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
/// Each triangle keeps how many of the face's loops lie around it (-1: not yet known).
using FaceBase =
    CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>;
using Triangulation = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<Kernel>, FaceBase>,
    CGAL::Exact_predicates_tag>;
using Face = Triangulation::Face_handle;

Kernel::Point_2 pointOf(const std::array<double, 2>& p) { return {p[0], p[1]}; }

/// Flood fill from the infinite face: a triangle's nesting level is the number of
/// constraints crossed to reach it.
void markNesting(Triangulation& triangulation) {
  for (Face face : triangulation.all_face_handles()) face->info() = -1;
  std::deque<std::pair<Face, int>> border{{triangulation.infinite_face(), 0}};
  while (!border.empty()) {
    const auto [start, level] = border.front();
    border.pop_front();
    if (start->info() != -1) continue;
    std::deque<Face> queue{start};
    start->info() = level;
    while (!queue.empty()) {
      const Face face = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        const Face next = face->neighbor(i);
        if (next->info() != -1) continue;
        if (face->is_constrained(i)) {
          border.push_back({next, level + 1});
        } else {
          next->info() = level;
          queue.push_back(next);
        }
      }
    }
  }
}

}  // namespace

struct FaceTriangulation::Impl {
  Triangulation triangulation;
  int inside = 1;
  std::array<Kernel::Point_2, 4> boxCorners;

  bool inFace(Face face) const { return !triangulation.is_infinite(face) && face->info() == inside; }
};

FaceTriangulation::FaceTriangulation(const SliceFace& face, const std::vector<std::array<double, 2>>& alsoHolding)
    : impl_(std::make_unique<Impl>()) {
  Triangulation& triangulation = impl_->triangulation;
  // Corners of a box around everything, so that the points given lie inside the hull
  // (the unbounded face reaches past its loops).
  double low[2] = {HUGE_VAL, HUGE_VAL}, high[2] = {-HUGE_VAL, -HUGE_VAL};
  const auto hold = [&](const std::array<double, 2>& point) {
    for (int axis : {0, 1})
      low[axis] = std::min(low[axis], point[axis]), high[axis] = std::max(high[axis], point[axis]);
  };
  for (const SliceLoop& loop : face.loops) {
    for (const auto& corner : loop.corners) hold(corner);
  }
  for (const auto& point : alsoHolding) hold(point);
  if (low[0] > high[0]) low[0] = low[1] = high[0] = high[1] = 0;
  const double margin = 1 + (high[0] - low[0]) + (high[1] - low[1]);
  int corner = 0;
  for (const double x : {low[0] - margin, high[0] + margin}) {
    for (const double y : {low[1] - margin, high[1] + margin}) {
      impl_->boxCorners[corner++] = Kernel::Point_2(x, y);
      triangulation.insert(Kernel::Point_2(x, y));
    }
  }
  // The loops' edges as constraints, their corners inserted together first (CGAL sorts
  // them along a space-filling curve: far faster than constraint after constraint).
  std::vector<Kernel::Point_2> corners;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (const SliceLoop& loop : face.loops) {
    const std::size_t first = corners.size();
    for (std::size_t i = 0; i < loop.corners.size(); ++i) {
      corners.push_back(pointOf(loop.corners[i]));
      const std::size_t next = (i + 1) % loop.corners.size();
      if (loop.corners[i] != loop.corners[next]) edges.push_back({first + i, first + next});
    }
  }
  triangulation.insert_constraints(corners.begin(), corners.end(), edges.begin(), edges.end());
  markNesting(triangulation);
  impl_->inside = face.unbounded ? 0 : 1;
}

FaceTriangulation::~FaceTriangulation() = default;

std::optional<std::vector<std::array<double, 2>>> FaceTriangulation::path(const std::array<double, 2>& from,
                                                                          const std::array<double, 2>& to) const {
  const Triangulation& triangulation = impl_->triangulation;
  const Face first = triangulation.locate(pointOf(from)), last = triangulation.locate(pointOf(to));
  if (!impl_->inFace(first) || !impl_->inFace(last)) return std::nullopt;
  // Breadth-first over the triangles of the face, across edges off its boundary.
  std::map<Face, std::pair<Face, int>> reachedFrom{{first, {first, -1}}};
  std::deque<Face> queue{first};
  while (!queue.empty() && !reachedFrom.count(last)) {
    const Face f = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i) {
      const Face next = f->neighbor(i);
      if (f->is_constrained(i) || !impl_->inFace(next) || reachedFrom.count(next)) continue;
      reachedFrom[next] = {f, i};
      queue.push_back(next);
    }
  }
  if (!reachedFrom.count(last)) return std::nullopt;
  std::vector<std::array<double, 2>> path{to};
  for (Face at = last; at != first;) {
    const auto [previous, edge] = reachedFrom.at(at);
    const Kernel::Point_2 a = previous->vertex(Triangulation::cw(edge))->point();
    const Kernel::Point_2 b = previous->vertex(Triangulation::ccw(edge))->point();
    path.push_back({CGAL::to_double((a.x() + b.x()) / 2), CGAL::to_double((a.y() + b.y()) / 2)});
    at = previous;
  }
  path.push_back(from);
  return std::vector<std::array<double, 2>>(path.rbegin(), path.rend());
}

namespace {

/// A triangle's incentre (the corners weighted by the lengths of the sides facing
/// them) and inradius; none for a degenerate one.
std::optional<std::pair<std::array<double, 2>, double>> incircleOf(Face face) {
  std::array<std::array<double, 2>, 3> corner;
  for (int i = 0; i < 3; ++i) {
    const Kernel::Point_2& p = face->vertex(i)->point();
    corner[i] = {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
  }
  std::array<double, 3> side;
  for (int i = 0; i < 3; ++i) {
    const auto &a = corner[(i + 1) % 3], &b = corner[(i + 2) % 3];
    side[i] = std::hypot(a[0] - b[0], a[1] - b[1]);
  }
  const double perimeter = side[0] + side[1] + side[2];
  if (!(perimeter > 0)) return std::nullopt;
  std::array<double, 2> centre{0, 0};
  for (int i = 0; i < 3; ++i) {
    for (int axis : {0, 1}) centre[axis] += side[i] * corner[i][axis] / perimeter;
  }
  const double twiceArea = std::fabs((corner[1][0] - corner[0][0]) * (corner[2][1] - corner[0][1]) -
                                     (corner[2][0] - corner[0][0]) * (corner[1][1] - corner[0][1]));
  return std::pair(centre, twiceArea / perimeter);
}

}  // namespace

std::vector<std::array<double, 2>> FaceTriangulation::roomyPoints(bool everyTriangle) const {
  std::vector<std::pair<double, std::array<double, 2>>> points;
  for (Face face : impl_->triangulation.finite_face_handles()) {
    if (!everyTriangle && !impl_->inFace(face)) continue;
    bool onBox = false;
    for (int i = 0; i < 3; ++i) {
      const Kernel::Point_2& p = face->vertex(i)->point();
      onBox |= std::find(impl_->boxCorners.begin(), impl_->boxCorners.end(), p) != impl_->boxCorners.end();
    }
    if (onBox) continue;
    if (const auto incircle = incircleOf(face)) points.push_back({incircle->second, incircle->first});
  }
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::array<double, 2>> roomy;
  for (const auto& point : points) roomy.push_back(point.second);
  return roomy;
}

std::optional<std::array<double, 2>> FaceTriangulation::incentreAt(const std::array<double, 2>& point) const {
  const Face face = impl_->triangulation.locate(pointOf(point));
  if (!impl_->inFace(face)) return std::nullopt;
  const auto incircle = incircleOf(face);
  if (!incircle) return std::nullopt;
  return incircle->first;
}

bool FaceTriangulation::contains(const std::array<double, 2>& point) const {
  return impl_->inFace(impl_->triangulation.locate(pointOf(point)));
}

bool FaceTriangulation::boxHolds(const std::array<double, 2>& point) const {
  const Kernel::Point_2 &low = impl_->boxCorners.front(), &high = impl_->boxCorners.back();
  return low.x() < point[0] && point[0] < high.x() && low.y() < point[1] && point[1] < high.y();
}

std::optional<std::vector<std::array<double, 2>>> pathInFace(const SliceFace& face, const std::array<double, 2>& from,
                                                             const std::array<double, 2>& to) {
  if (face.loops.empty()) return std::vector<std::array<double, 2>>{from, to};
  return FaceTriangulation(face, {from, to}).path(from, to);
}

namespace {

/// Keeps the point of the edge from `a` to `b` nearest to `point` when it is nearer
/// than `nearestSquared` (the squared distance kept so far).
void keepNearerOnEdge(const std::array<double, 2>& a, const std::array<double, 2>& b,
                      const std::array<double, 2>& point, double& nearestSquared, std::array<double, 2>& nearestPoint) {
  // An edge whose box lies farther than the nearest point so far is skipped.
  const double gapX = std::max({0.0, std::min(a[0], b[0]) - point[0], point[0] - std::max(a[0], b[0])});
  const double gapY = std::max({0.0, std::min(a[1], b[1]) - point[1], point[1] - std::max(a[1], b[1])});
  if (gapX * gapX + gapY * gapY > nearestSquared) return;
  const double ex = b[0] - a[0], ey = b[1] - a[1], length2 = ex * ex + ey * ey;
  const double along = length2 > 0 ? ((point[0] - a[0]) * ex + (point[1] - a[1]) * ey) / length2 : 0;
  const double t = std::clamp(along, 0.0, 1.0);
  const std::array<double, 2> foot{a[0] + t * ex, a[1] + t * ey};
  const double dx = point[0] - foot[0], dy = point[1] - foot[1], squared = dx * dx + dy * dy;
  if (squared < nearestSquared) {
    nearestSquared = squared;
    nearestPoint = foot;
  }
}

/// The end of edge k of a loop (the start of the next).
const std::array<double, 2>& edgeEnd(const SliceLoop& loop, std::size_t k) {
  return loop.corners[k + 1 < loop.corners.size() ? k + 1 : 0];
}

/// Faces with at least this many edges get an R-tree (BoundaryDistances): at 72, one
/// took 10 us to build and answered in 135 ns where each edge in turn took 230-290 ns,
/// so it repays its build after about a hundred points, as many as a walk asks of
/// such a face; at 685, 520 ns against 1.9 us.
constexpr std::size_t kIndexedEdges = 128;

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using TreePoint = bg::model::point<double, 2, bg::cs::cartesian>;
using TreeBox = bg::model::box<TreePoint>;
using TreeEdge = std::pair<bg::model::segment<TreePoint>, std::pair<std::uint32_t, std::uint32_t>>;  // loop, edge

}  // namespace

BoundaryPoint nearestOnBoundary(const SliceFace& face, const std::array<double, 2>& point) {
  // Squared distances compared; one square root at the end.
  double nearestSquared = HUGE_VAL;
  std::array<double, 2> nearestPoint{};
  for (const SliceLoop& loop : face.loops) {
    for (std::size_t k = 0; k < loop.corners.size(); ++k) {
      keepNearerOnEdge(loop.corners[k], edgeEnd(loop, k), point, nearestSquared, nearestPoint);
    }
  }
  return {std::sqrt(nearestSquared), nearestPoint};
}

struct BoundaryDistances::Impl {
  explicit Impl(const std::vector<TreeEdge>& all) : edges(all) {}  // packed
  bgi::rtree<TreeEdge, bgi::rstar<8>> edges;
};

BoundaryDistances::BoundaryDistances(const SliceFace& face) : face_(face) {
  std::size_t count = 0;
  for (const SliceLoop& loop : face.loops) count += loop.corners.size();
  if (count < kIndexedEdges) return;
  std::vector<TreeEdge> edges;
  edges.reserve(count);
  for (std::uint32_t l = 0; l < face.loops.size(); ++l) {
    const SliceLoop& loop = face.loops[l];
    for (std::uint32_t k = 0; k < loop.corners.size(); ++k) {
      const std::array<double, 2>&a = loop.corners[k], &b = edgeEnd(loop, k);
      edges.push_back({{TreePoint(a[0], a[1]), TreePoint(b[0], b[1])}, {l, k}});
    }
  }
  impl_ = std::make_unique<Impl>(edges);
}

BoundaryDistances::~BoundaryDistances() = default;

BoundaryPoint BoundaryDistances::nearest(const std::array<double, 2>& point) const {
  if (!impl_) return nearestOnBoundary(face_, point);
  TreeEdge found;
  if (impl_->edges.query(bgi::nearest(TreePoint(point[0], point[1]), 1), &found) == 0) return {};
  const auto [l, k] = found.second;
  double nearestSquared = HUGE_VAL;
  std::array<double, 2> nearestPoint{};
  keepNearerOnEdge(face_.loops[l].corners[k], edgeEnd(face_.loops[l], k), point, nearestSquared, nearestPoint);
  return {std::sqrt(nearestSquared), nearestPoint};
}

namespace {

using Point2 = std::array<double, 2>;

/// A lower bound on the distance from `p` to the segment from `a` to `b` (inside a
/// RoundingScope).
double leastDistanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  return segmentDistanceBounds({p[0], p[1]}, {a[0], a[1]}, {b[0], b[1]}).lower;
}

/// A lower bound on the distance between the boxes of two segments (inside a
/// RoundingScope), itself a lower bound on the segments' distance.
double leastBoxGap(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  Interval squared(0);
  for (int axis : {0, 1}) {
    const double low0 = std::min(a[axis], b[axis]), high0 = std::max(a[axis], b[axis]);
    const double low1 = std::min(c[axis], d[axis]), high1 = std::max(c[axis], d[axis]);
    const Interval gap = low1 > high0 ? Interval(low1) - high0 : low0 > high1 ? Interval(low0) - high1 : Interval(0);
    squared = squared + gap * gap;
  }
  return sqrt(squared).lower();
}

/// Calls visit(c, d) for each edge of the face's loops.
struct EveryEdge {
  const SliceFace& face;
  template <class Visit>
  void operator()(const Visit& visit) const {
    for (const SliceLoop& loop : face.loops) {
      for (std::size_t k = 0; k < loop.corners.size(); ++k) visit(loop.corners[k], edgeEnd(loop, k));
    }
  }
};

/// certifiedClearanceAlong from the edges `edges` visits (each once): at least all
/// that lie nearer the motion than the nearest of them.
template <class Edges>
std::optional<double> certifiedAlongEdges(const SliceFace& face, const Point2& from, const Point2& to,
                                          const Edges& edges) {
  if (face.loops.empty()) return face.unbounded ? std::optional<double>(HUGE_VAL) : std::nullopt;
  if (!std::isfinite(face.cornerError)) return std::nullopt;
  // The least distance, each loop edge's bounded by its box's gap first; edges whose
  // segments' distance was bounded may meet the motion (their ends' distances say
  // nothing then): those are tested exactly after the rounding scope.
  double least = HUGE_VAL;
  std::vector<std::pair<Point2, Point2>> near;
  {
    const RoundingScope rounding;
    edges([&](const Point2& c, const Point2& d) {
      if (leastBoxGap(from, to, c, d) >= least) return;
      least = std::min({least, leastDistanceToSegment(from, c, d), leastDistanceToSegment(to, c, d),
                        leastDistanceToSegment(c, from, to), leastDistanceToSegment(d, from, to)});
      if (c != d) near.push_back({c, d});
    });
    least = (Interval(least) - face.cornerError).lower();
  }
  if (!(least > 0)) return std::nullopt;
  if (from != to) {
    const Kernel::Segment_2 motion(pointOf(from), pointOf(to));
    for (const auto& [c, d] : near) {
      if (CGAL::do_intersect(motion, Kernel::Segment_2(pointOf(c), pointOf(d)))) return std::nullopt;
    }
  }
  return least;
}

/// liesInside from the edges `edges` visits (each once): at least all that cross the
/// ray from the point toward +x.
template <class Edges>
bool insideByEdges(const SliceFace& face, const Point2& point, const Edges& edges) {
  // Crossings of the ray toward +x: an edge crossing the ray's line lies right of the
  // point when the point lies left of it walked upward.
  bool inside = face.unbounded;
  edges([&](const Point2& c, const Point2& d) {
    if ((c[1] > point[1]) == (d[1] > point[1])) return;
    const Point2 &low = c[1] < d[1] ? c : d, &high = c[1] < d[1] ? d : c;
    if (CGAL::orientation(pointOf(low), pointOf(high), pointOf(point)) == CGAL::LEFT_TURN) inside = !inside;
  });
  return inside;
}

}  // namespace

std::optional<double> certifiedClearanceAlong(const SliceFace& face, const std::array<double, 2>& from,
                                              const std::array<double, 2>& to) {
  const std::optional<double> along = certifiedAlongEdges(face, from, to, EveryEdge{face});
  return along && liesInside(face, from) ? along : std::nullopt;
}

bool liesInside(const SliceFace& face, const std::array<double, 2>& point) {
  return insideByEdges(face, point, EveryEdge{face});
}

/// The face's edges that meet a box (by the R-tree's floating-point test: the box is
/// padded by far more than its rounding), gathered before the caller's rounding scope.
struct BoundaryDistances::EdgesMeeting {
  std::vector<std::pair<Point2, Point2>> edges;
  EdgesMeeting(const BoundaryDistances& distances, const TreeBox& box) {
    std::vector<TreeEdge> found;
    distances.impl_->edges.query(bgi::intersects(box), std::back_inserter(found));
    for (const TreeEdge& edge : found) {
      const auto [l, k] = edge.second;
      const SliceLoop& loop = distances.face_.loops[l];
      edges.push_back({loop.corners[k], edgeEnd(loop, k)});
    }
  }
  template <class Visit>
  void operator()(const Visit& visit) const {
    for (const auto& [c, d] : edges) visit(c, d);
  }
};

double BoundaryDistances::rounding(const std::array<double, 2>& point) const {
  const TreeBox& all = impl_->edges.bounds();
  const double extent = std::max({std::fabs(all.min_corner().get<0>()), std::fabs(all.min_corner().get<1>()),
                                  std::fabs(all.max_corner().get<0>()), std::fabs(all.max_corner().get<1>())});
  return 1e-12 * (extent + std::fabs(point[0]) + std::fabs(point[1]));
}

std::optional<double> BoundaryDistances::certifiedClearanceAlong(const std::array<double, 2>& from,
                                                                 const std::array<double, 2>& to) const {
  if (!impl_) return freespace::certifiedClearanceAlong(face_, from, to);
  // Only edges within the distance from `from` to the boundary (padded by far more
  // than its rounding) of the motion's box can be nearest to the motion, or meet it.
  const double reach = nearest(from).distance * (1 + 1e-9) + rounding(from) + rounding(to);
  const TreeBox around(TreePoint(std::min(from[0], to[0]) - reach, std::min(from[1], to[1]) - reach),
                       TreePoint(std::max(from[0], to[0]) + reach, std::max(from[1], to[1]) + reach));
  const std::optional<double> along = certifiedAlongEdges(face_, from, to, EdgesMeeting(*this, around));
  return along && liesInside(from) ? along : std::nullopt;
}

bool BoundaryDistances::liesInside(const std::array<double, 2>& point) const {
  if (!impl_) return freespace::liesInside(face_, point);
  const double farthest = impl_->edges.bounds().max_corner().get<0>();
  if (point[0] > farthest) return face_.unbounded;  // no edge meets the ray
  // The ray toward +x, padded: the exact test decides for the edges gathered.
  const double pad = rounding(point);
  const TreeBox ray(TreePoint(point[0] - pad, point[1] - pad), TreePoint(farthest + pad, point[1] + pad));
  return insideByEdges(face_, point, EdgesMeeting(*this, ray));
}

}  // namespace freespace
