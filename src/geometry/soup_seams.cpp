#include "soup_seams.h"

#include <algorithm>
#include <array>

#include "closed_triangle_tests.h"
#include "freespace/numbers/double_double_interval.h"
#include "vertex_predicates.h"

namespace freespace::detail {

namespace {

using Index = std::uint32_t;
using Edge = Seams::Edge;
using Tests = ClosedTriangleTests<VertexPredicates, Index>;

Edge edgeBetween(Index a, Index b) { return {std::min(a, b), std::max(a, b)}; }

Index cornerOff(const TriangleIndices& triangle, const Edge& edge) {
  return *std::find_if(triangle.begin(), triangle.end(),
                       [&](Index corner) { return corner != edge.first && corner != edge.second; });
}

// Whether the triangles on an edge lie in one plane on either side of it.
bool continueInOnePlane(const Edge& edge, const TriangleIndices& first, const TriangleIndices& second,
                        VertexPredicates& predicates) {
  const auto [a, b] = edge;
  const Index c = cornerOff(first, edge), d = cornerOff(second, edge);
  if (predicates.orient3d(a, b, c, d) != Sign::Zero) return false;
  Tests tests(predicates);
  const int axis = tests.projectionAxis({a, b, c});
  return predicates.orient2d(a, b, c, axis) * predicates.orient2d(a, b, d, axis) == Sign::Negative;
}

}  // namespace

Seams::Seams(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
             const std::vector<bool>& candidate) {
  std::vector<std::pair<Edge, Index>> uses;  // (edge, triangle)
  for (Index t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) uses.emplace_back(edgeBetween(triangles[t][k], triangles[t][(k + 1) % 3]), t);
  }
  std::sort(uses.begin(), uses.end());
  PredicateStatistics statistics;
  VertexPredicates predicates(vertices, statistics);
  const NearestRoundingScope rounding;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t end = i + 1;
    while (end < uses.size() && uses[end].first == uses[i].first) ++end;
    if (end - i == 2) {
      const Edge& edge = uses[i].first;
      const Index first = uses[i].second, second = uses[i + 1].second;
      if (candidate[first] && candidate[second] &&
          continueInOnePlane(edge, triangles[first], triangles[second], predicates)) {
        sides_.emplace(edge, Sides{first, second});
      }
    }
    i = end;
  }
}

const Seams::Sides* Seams::sides(Index a, Index b) const {
  const auto found = sides_.find(edgeBetween(a, b));
  return found == sides_.end() ? nullptr : &found->second;
}

void SeamPoints::liesOn(Index point, Index a, Index b) {
  if (!seams_.sides(a, b)) return;
  const auto [entry, inserted] = seamOf_.emplace(point, edgeBetween(a, b));
  if (!inserted && entry->second != edgeBetween(a, b)) keep(point);
}

void SeamPoints::addSegment(Index cluster, Index own, Index other, Edge segment) {
  segment = edgeBetween(segment.first, segment.second);
  for (Index end : {segment.first, segment.second}) {
    const auto seam = seamOf_.find(end);
    if (seam == seamOf_.end()) continue;
    const Seams::Sides& sides = *seams_.sides(seam->second.first, seam->second.second);
    const auto isSide = [&](Index t) { return own == t || other == t; };
    const int side = isSide(sides.first) ? 0 : (isSide(sides.second) ? 1 : -1);
    ends_[end].push_back({cluster, segment, side, other});
  }
}

SeamPoints::Joins SeamPoints::joins() const {
  PredicateStatistics statistics;
  VertexPredicates predicates(vertices_, statistics);
  const NearestRoundingScope rounding;
  Joins joins;
  for (const auto& [point, ends] : ends_) {
    std::map<Index, Around> byCluster;
    if (kept_.count(point) != 0 || !aroundInEveryCluster(point, ends, predicates, byCluster)) continue;
    for (auto& [cluster, around] : byCluster) joins[cluster][point] = std::move(around);
  }
  return joins;
}

// The other ends of the point's segments, by cluster and side, if in every cluster
// they lie on one line (where the plane their other triangles share crosses the
// cluster's) on both sides of the seam.
bool SeamPoints::aroundInEveryCluster(Index point, const std::vector<End>& ends, VertexPredicates& predicates,
                                      std::map<Index, Around>& byCluster) const {
  std::map<Index, Index> planeOf;  // cluster -> the other triangle of its first segment
  for (const End& end : ends) {
    const Index line = planeOf.emplace(end.cluster, end.other).first->second;
    if (end.side < 0 || end.segment.first == end.segment.second || !inOnePlane(line, end.other, predicates)) {
      return false;
    }
    const Index neighbour = end.segment.first == point ? end.segment.second : end.segment.first;
    std::vector<Index>& side = byCluster[end.cluster][end.side];
    if (std::find(side.begin(), side.end(), neighbour) == side.end()) side.push_back(neighbour);
  }
  return std::all_of(byCluster.begin(), byCluster.end(),
                     [](const auto& entry) { return !entry.second[0].empty() && !entry.second[1].empty(); });
}

bool SeamPoints::inOnePlane(Index first, Index second, VertexPredicates& predicates) const {
  if (first == second) return true;
  const TriangleIndices &p = triangles_[first], &q = triangles_[second];
  const auto onVertices = [&](const TriangleIndices& t) {
    return std::all_of(t.begin(), t.end(), [&](Index corner) { return corner < vertices_.size(); });
  };
  if (!onVertices(p) || !onVertices(q)) return false;
  return std::all_of(q.begin(), q.end(),
                     [&](Index corner) { return predicates.orient3d(p[0], p[1], p[2], corner) == Sign::Zero; });
}

std::vector<Edge> SeamPoints::joined(const std::vector<Edge>& segments, std::map<Index, Around> around) {
  std::set<Edge> distinct;
  for (const auto& [a, b] : segments) {
    if (a != b) distinct.insert(edgeBetween(a, b));
  }
  // A neighbour left out later sees, where it saw `point`, what lies beyond it.
  const auto replace = [&](Index at, Index point, const std::vector<Index>& beyond) {
    const auto found = around.find(at);
    if (found == around.end()) return;
    for (std::vector<Index>& side : found->second) {
      const auto position = std::find(side.begin(), side.end(), point);
      if (position == side.end()) continue;
      side.erase(position);
      for (Index next : beyond) {
        if (next != at && std::find(side.begin(), side.end(), next) == side.end()) side.push_back(next);
      }
    }
  };
  for (const auto& [point, sides] : around) {
    for (const std::vector<Index>& side : sides) {
      for (Index neighbour : side) distinct.erase(edgeBetween(point, neighbour));
    }
    for (Index p : sides[0]) {
      for (Index q : sides[1]) {
        if (p != q) distinct.insert(edgeBetween(p, q));
      }
    }
    for (Index p : sides[0]) replace(p, point, sides[1]);
    for (Index q : sides[1]) replace(q, point, sides[0]);
  }
  return {distinct.begin(), distinct.end()};
}

}  // namespace freespace::detail
