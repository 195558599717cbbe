#include "surface_self_intersection.h"

#include <algorithm>
#include <array>
#include <iterator>

#include "closed_triangle_tests.h"
#include "freespace/numbers/double_double_interval.h"
#include "triangle_box_tree.h"
#include "vertex_predicates.h"

namespace freespace::detail {
namespace {

using Tests = ClosedTriangleTests<VertexPredicates, std::uint32_t>;
using Triangle = Tests::Triangle;

/// The triangle turned so that it starts at `vertex`, one of its corners.
Triangle startingAt(const TriangleIndices& t, std::uint32_t vertex) {
  const int k = t[0] == vertex ? 0 : (t[1] == vertex ? 1 : 2);
  return {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
}

/// Triangles (v, a, b) and (v, c, d) sharing only v meet elsewhere exactly when
/// segment ab meets the second or segment cd the first. Their intersection is convex;
/// if it holds a point p other than v, the ray from v through p leaves each triangle
/// at a point of its edge opposite v, and the nearer of those two exits lies in both.
bool meetBeyondSharedVertex(const Triangle& p, const Triangle& q, Tests& tests) {
  return tests.segmentIntersectsTriangle(p[1], p[2], q) || tests.segmentIntersectsTriangle(q[1], q[2], p);
}

/// The corner of `t` that is neither u nor w (two of its corners).
std::uint32_t thirdCorner(const TriangleIndices& t, std::uint32_t u, std::uint32_t w) {
  return *std::find_if(t.begin(), t.end(), [&](std::uint32_t corner) { return corner != u && corner != w; });
}

/// Triangles (u, w, a) and (u, w, c) sharing the edge uw meet beyond it exactly when
/// they lie in one plane on the same side of the edge (folded onto each other): two
/// planes that differ meet in the edge's line only.
bool meetBeyondSharedEdge(std::uint32_t u, std::uint32_t w, std::uint32_t a, std::uint32_t c, Tests& tests,
                          VertexPredicates& predicates) {
  if (predicates.orient3d(u, w, a, c) != Sign::Zero) return false;
  // A projection in which the plane does not collapse keeps sides of the edge's line.
  const int axis = tests.projectionAxis({u, w, a});
  return predicates.orient2d(u, w, c, axis) == predicates.orient2d(u, w, a, axis);
}

bool meetBeyondSharedFeatures(const TriangleIndices& first, const TriangleIndices& second,
                              VertexPredicates& predicates) {
  Tests tests(predicates);
  std::array<std::uint32_t, 3> shared{};
  int sharedCount = 0;
  for (std::uint32_t vertex : first) {
    if (std::find(second.begin(), second.end(), vertex) != second.end()) shared[sharedCount++] = vertex;
  }
  switch (sharedCount) {
    case 0:
      return tests.trianglesIntersect({first[0], first[1], first[2]}, {second[0], second[1], second[2]});
    case 1:
      return meetBeyondSharedVertex(startingAt(first, shared[0]), startingAt(second, shared[0]), tests);
    default: {
      const std::uint32_t u = shared[0], w = shared[1];
      return meetBeyondSharedEdge(u, w, thirdCorner(first, u, w), thirdCorner(second, u, w), tests, predicates);
    }
  }
}

/// Calls visit(i, j) for each pair i < j (by i, then j) of triangles that meet beyond
/// their shared features and are both accepted by `accept`, until visit returns false.
template <class Accept, class Visit>
void forEachMeetingPair(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
                        const Accept& accept, const Visit& visit) {
  const TriangleTree tree = triangleTree(vertices, triangles);
  PredicateStatistics statistics;
  VertexPredicates predicates(vertices, statistics);
  NearestRoundingScope rounding;
  std::vector<TreeEntry> near;
  std::vector<std::uint32_t> candidates;
  for (std::uint32_t i = 0; i < triangles.size(); ++i) {
    near.clear();
    candidates.clear();
    // Closed boxes: triangles that only touch are found too.
    tree.query(bgi::intersects(triangleBox(vertices, triangles[i])), std::back_inserter(near));
    for (const TreeEntry& entry : near) {
      if (entry.second > i && accept(i, entry.second)) candidates.push_back(entry.second);
    }
    std::sort(candidates.begin(), candidates.end());
    for (std::uint32_t j : candidates) {
      if (meetBeyondSharedFeatures(triangles[i], triangles[j], predicates) && !visit(i, j)) return;
    }
  }
}

}  // namespace

std::optional<std::pair<std::uint32_t, std::uint32_t>> firstSelfIntersection(
    const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
    const std::vector<std::uint32_t>& componentOf) {
  std::optional<std::pair<std::uint32_t, std::uint32_t>> first;
  forEachMeetingPair(
      vertices, triangles, [&](std::uint32_t i, std::uint32_t j) { return componentOf[i] == componentOf[j]; },
      [&](std::uint32_t i, std::uint32_t j) {
        first = std::make_pair(i, j);
        return false;
      });
  return first;
}

std::vector<std::uint32_t> selfIntersectingComponents(const std::vector<Point3>& vertices,
                                                      const std::vector<TriangleIndices>& triangles,
                                                      const std::vector<std::uint32_t>& componentOf) {
  std::vector<std::uint32_t> found;
  forEachMeetingPair(
      vertices, triangles,
      [&](std::uint32_t i, std::uint32_t j) {
        return componentOf[i] == componentOf[j] &&
               std::find(found.begin(), found.end(), componentOf[i]) == found.end();
      },
      [&](std::uint32_t i, std::uint32_t) {
        found.push_back(componentOf[i]);
        return true;
      });
  std::sort(found.begin(), found.end());
  return found;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> meetingPairs(const std::vector<Point3>& vertices,
                                                                  const std::vector<TriangleIndices>& triangles) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  forEachMeetingPair(
      vertices, triangles, [](std::uint32_t, std::uint32_t) { return true; },
      [&](std::uint32_t i, std::uint32_t j) {
        pairs.emplace_back(i, j);
        return true;
      });
  return pairs;
}

}  // namespace freespace::detail
