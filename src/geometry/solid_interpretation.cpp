#include "freespace/geometry/solid_interpretation.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <tuple>

#include "disjoint_sets.h"
#include "edge_uses.h"
#include "freespace/input_error.h"
#include "soup_checks.h"
#include "soup_enclosure.h"
#include "surface_self_intersection.h"

namespace freespace {

namespace {

using Index = std::uint32_t;

using detail::EdgeUse;
using detail::forEachEdge;
using detail::sortedEdgeUses;

// The components, and which of them are closed and edge-manifold: every edge of a
// component used by two of its triangles.
struct ComponentKinds {
  std::vector<Index> componentOf;  // of each triangle: its component's first triangle
  std::vector<bool> closed;        // indexed by that first triangle
};

// The components: triangles of one piece of the input (`uses` grouped by piece) joined
// through shared edges; each numbered by its first triangle. An edge's uses within a
// piece all lie in one component, so `uses` serve for the components too.
ComponentKinds classifyComponents(std::size_t triangleCount, const std::vector<EdgeUse>& uses) {
  detail::DisjointSets components(triangleCount);
  forEachEdge(uses, [&](std::size_t first, std::size_t count) {
    for (std::size_t i = first + 1; i < first + count; ++i) components.unite(uses[first].triangle, uses[i].triangle);
  });
  ComponentKinds kinds{std::vector<Index>(triangleCount), std::vector<bool>(triangleCount, true)};
  for (Index t = 0; t < triangleCount; ++t) kinds.componentOf[t] = components.find(t);
  forEachEdge(uses, [&](std::size_t first, std::size_t count) {
    if (count != 2) kinds.closed[kinds.componentOf[uses[first].triangle]] = false;
  });
  return kinds;
}

// Turns triangles of closed components so that each component is consistently
// oriented, spreading its first triangle's orientation across edges (a surface in
// space that is closed and edge-manifold can always be oriented unless it crosses
// itself: a component where the spreading meets a contradiction is no longer
// counted closed). Returns how many triangles were turned.
std::size_t orientConsistently(std::vector<TriangleIndices>& triangles, const std::vector<EdgeUse>& uses,
                               ComponentKinds& kinds) {
  // Up to three neighbours across manifold edges: (triangle, runs the edge the same way).
  struct Neighbours {
    std::array<std::pair<Index, bool>, 3> across;
    int count = 0;
  };
  std::vector<Neighbours> neighbours(triangles.size());
  forEachEdge(uses, [&](std::size_t first, std::size_t count) {
    if (count != 2) return;
    const EdgeUse &a = uses[first], &b = uses[first + 1];
    Neighbours &ofA = neighbours[a.triangle], &ofB = neighbours[b.triangle];
    if (ofA.count < 3) ofA.across[ofA.count++] = {b.triangle, a.lowToHigh == b.lowToHigh};
    if (ofB.count < 3) ofB.across[ofB.count++] = {a.triangle, a.lowToHigh == b.lowToHigh};
  });
  std::vector<int> turned(triangles.size(), -1);  // -1 unseen, 0 kept, 1 turned
  std::size_t count = 0;
  for (Index start = 0; start < triangles.size(); ++start) {
    if (!kinds.closed[kinds.componentOf[start]] || turned[start] >= 0) continue;
    turned[start] = 0;
    std::vector<Index> stack{start};
    while (!stack.empty()) {
      const Index t = stack.back();
      stack.pop_back();
      for (int i = 0; i < neighbours[t].count; ++i) {
        const auto [other, sameDirection] = neighbours[t].across[i];
        const int wanted = sameDirection ? 1 - turned[t] : turned[t];  // neighbours run an edge both ways
        if (turned[other] < 0) {
          turned[other] = wanted;
          stack.push_back(other);
        } else if (turned[other] != wanted) {
          kinds.closed[kinds.componentOf[start]] = false;
        }
      }
    }
  }
  for (Index t = 0; t < triangles.size(); ++t) {
    if (turned[t] == 1 && kinds.closed[kinds.componentOf[t]]) {
      std::swap(triangles[t][1], triangles[t][2]);
      ++count;
    }
  }
  return count;
}

// Turns every closed component whose triangles face inward (a negative enclosed
// volume); returns how many triangles were turned.
std::size_t orientOutward(const std::vector<Point3>& vertices, std::vector<TriangleIndices>& triangles,
                          const ComponentKinds& kinds) {
  std::vector<Box3> bounds(triangles.size());  // by component (its first triangle)
  for (Index t = 0; t < triangles.size(); ++t) {
    for (Index v : triangles[t]) bounds[kinds.componentOf[t]].extend(vertices[v]);
  }
  std::vector<double> volume(triangles.size(), 0);  // six times the signed volume, from each box's corner
  for (Index t = 0; t < triangles.size(); ++t) {
    const Point3& origin = bounds[kinds.componentOf[t]].min();
    const Point3 a = vertices[triangles[t][0]] - origin, b = vertices[triangles[t][1]] - origin,
                 c = vertices[triangles[t][2]] - origin;
    volume[kinds.componentOf[t]] += a.dot(b.cross(c));
  }
  std::size_t count = 0;
  for (Index t = 0; t < triangles.size(); ++t) {
    if (!kinds.closed[kinds.componentOf[t]] || !(volume[kinds.componentOf[t]] < 0)) continue;
    std::swap(triangles[t][1], triangles[t][2]);
    ++count;
  }
  return count;
}

// A closed surface that crosses itself stands for the solid it encloses: its
// component joins the soup. Only closed components are checked.
void markSelfIntersectingAsSoup(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
                                ComponentKinds& kinds) {
  std::vector<TriangleIndices> closed;
  std::vector<Index> componentOf;
  for (Index t = 0; t < triangles.size(); ++t) {
    if (!kinds.closed[kinds.componentOf[t]]) continue;
    closed.push_back(triangles[t]);
    componentOf.push_back(kinds.componentOf[t]);
  }
  for (Index component : detail::selfIntersectingComponents(vertices, closed, componentOf)) {
    kinds.closed[component] = false;
  }
}

std::size_t countDistinct(std::vector<Index> values) {
  std::sort(values.begin(), values.end());
  return static_cast<std::size_t>(std::unique(values.begin(), values.end()) - values.begin());
}

// Sorts the faces that enclose nothing into those the other body may touch and those
// entirely below or above its heights by more than the tolerance.
std::pair<OpenTriangles, OpenTriangles> openTriangles(const std::vector<detail::OpenFace>& faces,
                                                      const SolidSettings& settings) {
  std::vector<Index> inReachSources, outOfReachSources;
  OpenTriangles inReach, outOfReach;
  for (const detail::OpenFace& face : faces) {
    const auto& heights = settings.otherBodyHeights;
    const bool beyond = heights && (face.bounds.max().z() < (*heights)[0] - settings.tolerance ||
                                    face.bounds.min().z() > (*heights)[1] + settings.tolerance);
    OpenTriangles& kind = beyond ? outOfReach : inReach;
    ++kind.pieces;
    kind.bounds.extend(face.bounds);
    std::vector<Index>& sources = beyond ? outOfReachSources : inReachSources;
    sources.insert(sources.end(), face.sourceTriangles.begin(), face.sourceTriangles.end());
  }
  inReach.sourceTriangles = countDistinct(inReachSources);
  outOfReach.sourceTriangles = countDistinct(outOfReachSources);
  return {inReach, outOfReach};
}

std::string openTrianglesText(const OpenTriangles& open) {
  const std::size_t count = open.sourceTriangles;
  return std::to_string(count) + (count == 1 ? " triangle encloses" : " triangles enclose") +
         " nothing (an open sheet, a zero-thickness wall or a crack wider than the tolerance): no volume lies "
         "behind " + (count == 1 ? "it" : "them") + ", between " + detail::formatPoint(open.bounds.min()) +
         " and " + detail::formatPoint(open.bounds.max());
}

// The boundary's components meet themselves nowhere in exact arithmetic; rounding the
// points where triangles cross to doubles could make one touch itself, in principle.
void requireSimpleBoundary(const detail::EnclosedSolid& solid, const std::string& sourceName) {
  const auto pair = detail::firstSelfIntersection(solid.boundary.vertices, solid.boundary.triangles,
                                                  solid.boundaryComponent);
  if (!pair) return;
  const Point3& at = solid.boundary.vertices[solid.boundary.triangles[pair->first][0]];
  throw InputError(sourceName, "the solid the triangles enclose has parts closer than double precision can keep "
                               "apart (near " + detail::formatPoint(at) + ")");
}

// Appends triangles with the vertices they use, renumbered from `soup`'s end in the
// order of their indices.
void appendTriangles(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
                     TriangleSoup& soup) {
  TriangleSoup part{vertices, triangles};
  detail::dropUnusedVertices(part);
  const auto offset = static_cast<Index>(soup.vertices.size());
  soup.vertices.insert(soup.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (TriangleIndices triangle : part.triangles) {
    for (Index& corner : triangle) corner += offset;
    soup.triangles.push_back(triangle);
  }
}

// Appends the closed components (component -> its triangles), each with vertices of
// its own, numbered in the order of their indices within the component (a mesh whose
// vertices are all used and that is one component keeps its numbering).
void appendClosedComponents(const std::vector<Point3>& vertices,
                            const std::map<Index, std::vector<TriangleIndices>>& closed, TriangleSoup& result) {
  constexpr Index kNone = std::numeric_limits<Index>::max();
  std::vector<Index> owner(vertices.size(), kNone), copy(vertices.size());
  std::vector<Index> used;
  for (const auto& [component, componentTriangles] : closed) {
    used.clear();
    for (const TriangleIndices& triangle : componentTriangles) {
      for (Index corner : triangle) {
        if (owner[corner] == component) continue;
        owner[corner] = component;
        used.push_back(corner);
      }
    }
    std::sort(used.begin(), used.end());
    for (Index v : used) {
      copy[v] = static_cast<Index>(result.vertices.size());
      result.vertices.push_back(vertices[v]);
    }
    for (TriangleIndices triangle : componentTriangles) {
      for (Index& corner : triangle) corner = copy[corner];
      result.triangles.push_back(triangle);
    }
  }
}

}  // namespace

std::vector<std::string> SolidReport::describe() const {
  using detail::countOf;
  std::vector<std::string> lines;
  if (soupTriangles > 0) {
    lines.push_back(countOf(soupTriangles, "triangle") + " in " + countOf(soupPieces, "piece") +
                    " not forming closed surfaces, taken as the solid they enclose: " +
                    countOf(enclosedRegions, "enclosed region") + " bounded by " +
                    countOf(boundaryTriangles, "triangle") + " in " + countOf(solids, "solid"));
    if (refinedTriangles > 0) {
      lines.push_back(countOf(refinedTriangles, "triangle") + " split where " + countOf(meetingPairs, "pair") +
                      " of them cross or overlap");
    }
    if (capTriangles > 0) {
      lines.push_back(countOf(capTriangles, "triangle") + " added to close planar openings (faces left out)");
    }
    if (internalTriangles > 0) {
      lines.push_back(countOf(internalTriangles, "piece") + " of triangles inside the solid dropped (internal walls)");
    }
    if (separatedEdges > 0) {
      lines.push_back(countOf(separatedEdges, "edge") + " along which the solid touches itself: the pieces meeting "
                      "there moved apart by the tolerance");
    }
    if (open.pieces > 0) lines.push_back(countOf(open.sourceTriangles, "triangle") + " that enclose nothing dropped");
    if (outOfReach.pieces > 0) {
      lines.push_back(countOf(outOfReach.sourceTriangles, "triangle") + " that enclose nothing dropped where the other "
                      "body can never touch them (beyond its heights), between " +
                      detail::formatPoint(outOfReach.bounds.min()) + " and " +
                      detail::formatPoint(outOfReach.bounds.max()));
    }
    if (closedComponents > 0) lines.push_back(countOf(closedComponents, "closed component") + " kept as they are");
  }
  if (trianglesTurned > 0) {
    lines.push_back(countOf(trianglesTurned, "triangle") + " of closed components turned to face outward like their "
                    "neighbours");
  }
  return lines;
}

TriangleSoup interpretSolid(const TriangleSoup& repaired, const std::vector<std::uint32_t>& pieces,
                            const std::string& sourceName, const SolidSettings& settings, SolidReport* report,
                            std::vector<std::string>* warnings) {
  std::vector<TriangleIndices> triangles = repaired.triangles;
  const std::vector<EdgeUse> uses = sortedEdgeUses(triangles, pieces);
  ComponentKinds kinds = classifyComponents(triangles.size(), uses);
  SolidReport counts;
  const std::size_t turnedAgainstNeighbours = orientConsistently(triangles, uses, kinds);
  counts.trianglesTurned = turnedAgainstNeighbours + orientOutward(repaired.vertices, triangles, kinds);
  markSelfIntersectingAsSoup(repaired.vertices, triangles, kinds);
  std::map<Index, std::vector<TriangleIndices>> closed;  // component -> its triangles
  std::vector<TriangleIndices> soup;
  std::vector<Index> soupPieces;
  for (Index t = 0; t < triangles.size(); ++t) {
    const Index component = kinds.componentOf[t];
    if (kinds.closed[component]) {
      closed[component].push_back(triangles[t]);
    } else {
      soup.push_back(triangles[t]);
      soupPieces.push_back(component);
    }
  }
  counts.closedComponents = closed.size();
  counts.soupTriangles = soup.size();
  counts.soupPieces = countDistinct(soupPieces);

  // Each closed component with vertices of its own: components that touch along an
  // edge would otherwise share it with four triangles.
  TriangleSoup result;
  appendClosedComponents(repaired.vertices, closed, result);
  if (!soup.empty()) {
    const detail::EnclosedSolid solid = detail::enclosedSolid(repaired.vertices, soup, settings.tolerance);
    counts.capTriangles = solid.capFaces;
    counts.separatedEdges = solid.separatedEdges;
    counts.meetingPairs = solid.meetingPairs;
    counts.refinedTriangles = solid.refinedTriangles;
    counts.enclosedRegions = solid.boundedCells;
    counts.solids = solid.components;
    counts.boundaryTriangles = solid.boundary.triangles.size();
    counts.internalTriangles = solid.internalFaces;
    std::tie(counts.open, counts.outOfReach) = openTriangles(solid.openFaces, settings);
    if (counts.open.pieces > 0) {
      if (!settings.ignoreOpen) {
        throw InputError(sourceName, openTrianglesText(counts.open) + "; --ignore-open drops them with a warning");
      }
      if (warnings) warnings->push_back(sourceName + ": " + openTrianglesText(counts.open) + ": dropped (--ignore-open)");
    }
    requireSimpleBoundary(solid, sourceName);
    appendTriangles(solid.boundary.vertices, solid.boundary.triangles, result);
  }
  if (report) *report = counts;
  return result;
}

}  // namespace freespace
