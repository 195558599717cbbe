#include "freespace/geometry/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "freespace/input_error.h"
#include "disjoint_sets.h"
#include "edge_uses.h"
#include "soup_checks.h"
#include "surface_self_intersection.h"

namespace freespace {
namespace {

using detail::EdgeUse;
using detail::forEachEdge;
using detail::sortedEdgeUses;
using detail::vertexLocations;

using Index = std::uint32_t;

constexpr Index kNoIndex = std::numeric_limits<Index>::max();

// A component whose |volume| is at most this fraction of its bounding box volume
// encloses nothing: the rest is rounding error.
constexpr double kNoVolumeFraction = 1e-12;

std::string edgeName(Index low, Index high) {
  return "edge (" + std::to_string(low) + ", " + std::to_string(high) + ")";
}

// ---------------------------------------------------------------------------
// Zero-area and duplicate triangles

void requireNonZeroAreas(const TriangleSoup& surface, const std::string& source) {
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const TriangleIndices& triangle = surface.triangles[t];
    if (!detail::hasZeroArea(surface.vertices, triangle)) continue;
    const auto [a, b, c] = triangle;
    throw InputError(source, "triangle " + std::to_string(t) + " (vertices " +
                                 std::to_string(a) + ", " + std::to_string(b) + ", " +
                                 std::to_string(c) + ") has zero area" +
                                 vertexLocations(surface.vertices, {a, b, c}));
  }
}

void requireDistinctTriangles(const TriangleSoup& surface, const std::string& source) {
  std::vector<std::pair<TriangleIndices, Index>> byVertexSet;
  byVertexSet.reserve(surface.triangles.size());
  for (Index t = 0; t < surface.triangles.size(); ++t) {
    TriangleIndices vertexSet = surface.triangles[t];
    std::sort(vertexSet.begin(), vertexSet.end());
    byVertexSet.emplace_back(vertexSet, t);
  }
  std::sort(byVertexSet.begin(), byVertexSet.end());

  // Report the duplicate whose second triangle comes first in the soup.
  std::pair<Index, Index> duplicate{kNoIndex, kNoIndex};
  for (std::size_t i = 1; i < byVertexSet.size(); ++i) {
    const bool sameSet = byVertexSet[i].first == byVertexSet[i - 1].first;
    const bool secondOfRun = i < 2 || byVertexSet[i - 2].first != byVertexSet[i].first;
    if (sameSet && secondOfRun && byVertexSet[i].second < duplicate.second) {
      duplicate = {byVertexSet[i - 1].second, byVertexSet[i].second};
    }
  }
  if (duplicate.first == kNoIndex) return;

  const TriangleIndices& first = surface.triangles[duplicate.first];
  const TriangleIndices& second = surface.triangles[duplicate.second];
  const auto [a, b, c] = first;
  const std::string orientationNote =
      detail::sameOrientation(first, second) ? ""
                                     : " in opposite orientations (a double-sided surface?)";
  throw InputError(source, "triangles " + std::to_string(duplicate.first) + " and " +
                               std::to_string(duplicate.second) +
                               " use the same three vertices (" + std::to_string(a) + ", " +
                               std::to_string(b) + ", " + std::to_string(c) + ")" +
                               orientationNote + vertexLocations(surface.vertices, {a, b, c}));
}

// ---------------------------------------------------------------------------
// Edges: manifold, closed, consistently oriented

// Edges shared by more than two triangles are reported before open edges: they
// are the cause, open edges often only a consequence.
void requireEdgeManifold(const std::vector<EdgeUse>& uses, const std::vector<Point3>& vertices,
                         const std::string& source) {
  forEachEdge(uses, [&](std::size_t first, std::size_t count) {
    const EdgeUse& edge = uses[first];
    if (count > 2) {
      throw InputError(source, edgeName(edge.low, edge.high) + " is shared by " +
                                   std::to_string(count) + " triangles" +
                                   vertexLocations(vertices, {edge.low, edge.high}));
    }
  });
  forEachEdge(uses, [&](std::size_t first, std::size_t count) {
    const EdgeUse& edge = uses[first];
    if (count == 1) {
      throw InputError(source, edgeName(edge.low, edge.high) +
                                   " borders only one triangle: the surface is not closed" +
                                   vertexLocations(vertices, {edge.low, edge.high}));
    }
  });
}

// Assumes every edge has exactly two uses (requireEdgeManifold passed).
void requireConsistentOrientation(const std::vector<EdgeUse>& uses,
                                  const std::vector<Point3>& vertices,
                                  const std::string& source) {
  for (std::size_t i = 0; i < uses.size(); i += 2) {
    const EdgeUse& one = uses[i];
    const EdgeUse& other = uses[i + 1];
    if (one.lowToHigh == other.lowToHigh) {
      throw InputError(source, "triangles " + std::to_string(one.triangle) + " and " +
                                   std::to_string(other.triangle) +
                                   " have inconsistent orientation across " +
                                   edgeName(one.low, one.high) +
                                   vertexLocations(vertices, {one.low, one.high}));
    }
  }
}

// ---------------------------------------------------------------------------
// Components

// Component of each triangle through shared edges (every edge has two uses),
// numbered in the order of each component's first triangle.
std::vector<Index> connectedComponents(std::size_t triangleCount,
                                       const std::vector<EdgeUse>& uses) {
  detail::DisjointSets sets(triangleCount);
  for (std::size_t i = 0; i < uses.size(); i += 2) sets.unite(uses[i].triangle, uses[i + 1].triangle);

  std::vector<Index> componentOfRoot(triangleCount, kNoIndex);
  std::vector<Index> component(triangleCount);
  Index componentCount = 0;
  for (Index t = 0; t < triangleCount; ++t) {
    Index& numbered = componentOfRoot[sets.find(t)];
    if (numbered == kNoIndex) numbered = componentCount++;
    component[t] = numbered;
  }
  return component;
}

struct ComponentSummary {
  Box3 bounds;
  Index representative = kNoIndex;
  double signedVolume = 0;
};

// Bounds, first vertex and signed volume (sum of det(v0, v1, v2) / 6, taken
// relative to the bounding box's min corner for accuracy, dividing once at the end)
// of each component.
std::vector<ComponentSummary> summarizeComponents(const TriangleSoup& surface,
                                                  const std::vector<Index>& componentOf) {
  const Index componentCount =
      componentOf.empty() ? 0 : *std::max_element(componentOf.begin(), componentOf.end()) + 1;
  std::vector<ComponentSummary> components(componentCount);
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    ComponentSummary& component = components[componentOf[t]];
    if (component.representative == kNoIndex) component.representative = surface.triangles[t][0];
    for (Index v : surface.triangles[t]) component.bounds.extend(surface.vertices[v]);
  }
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    ComponentSummary& component = components[componentOf[t]];
    const Point3& origin = component.bounds.min();
    const auto [a, b, c] = surface.triangles[t];
    const Point3 p = surface.vertices[a] - origin;
    const Point3 q = surface.vertices[b] - origin;
    const Point3 r = surface.vertices[c] - origin;
    component.signedVolume += p.dot(q.cross(r));
  }
  for (ComponentSummary& component : components) component.signedVolume /= 6;
  return components;
}

void requireVolume(const ComponentSummary& component, Index index, const std::string& source) {
  const std::string name = "component " + std::to_string(index);
  if (!std::isfinite(component.signedVolume)) {
    throw InputError(source, name + " is too large: its volume overflows");
  }
  const double boxVolume = component.bounds.volume();
  if (!(std::abs(component.signedVolume) > kNoVolumeFraction * boxVolume)) {
    throw InputError(source, name + " encloses no volume");
  }
}

void requireNoSelfIntersection(const TriangleSoup& surface, const std::vector<Index>& componentOf,
                               const std::string& source) {
  const auto pair = detail::firstSelfIntersection(surface.vertices, surface.triangles, componentOf);
  if (!pair) return;
  const auto [first, second] = *pair;
  const TriangleIndices &a = surface.triangles[first], &b = surface.triangles[second];
  throw InputError(source, "component " + std::to_string(componentOf[first]) +
                               " intersects itself: triangles " + std::to_string(first) + " (vertices " +
                               std::to_string(a[0]) + ", " + std::to_string(a[1]) + ", " + std::to_string(a[2]) +
                               ") and " + std::to_string(second) + " (vertices " + std::to_string(b[0]) + ", " +
                               std::to_string(b[1]) + ", " + std::to_string(b[2]) +
                               ") cross or touch away from the vertices they share" +
                               vertexLocations(surface.vertices, {a[0], a[1], a[2], b[0], b[1], b[2]}));
}

void flipTriangles(std::vector<TriangleIndices>& triangles, const std::vector<Index>& componentOf,
                   Index component) {
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (componentOf[t] == component) std::swap(triangles[t][1], triangles[t][2]);
  }
}

}  // namespace

Mesh Mesh::fromSoup(const TriangleSoup& soup, const std::string& sourceName,
                    std::vector<std::string>* warnings, VertexWelding welding,
                    SelfIntersectionCheck selfIntersection) {
  detail::requireFiniteCoordinates(soup, sourceName);
  detail::requireTriangles(soup, sourceName);
  detail::requireIndicesInRange(soup, sourceName);
  TriangleSoup surface = soup;
  if (welding == VertexWelding::identicalPositions) {
    surface = detail::weldIdenticalVertices(soup);
  } else {
    detail::dropUnusedVertices(surface);
  }
  requireNonZeroAreas(surface, sourceName);
  requireDistinctTriangles(surface, sourceName);
  const std::vector<EdgeUse> edgeUses = sortedEdgeUses(surface.triangles);
  requireEdgeManifold(edgeUses, surface.vertices, sourceName);
  requireConsistentOrientation(edgeUses, surface.vertices, sourceName);

  Mesh mesh;
  mesh.triangleComponent_ = connectedComponents(surface.triangles.size(), edgeUses);
  const std::vector<ComponentSummary> components =
      summarizeComponents(surface, mesh.triangleComponent_);
  for (Index c = 0; c < components.size(); ++c) {
    const ComponentSummary& component = components[c];
    requireVolume(component, c, sourceName);
    if (component.signedVolume < 0) {
      flipTriangles(surface.triangles, mesh.triangleComponent_, c);
      if (warnings) {
        warnings->push_back(sourceName + ": component " + std::to_string(c) +
                            " was inside-out and has been flipped");
      }
    }
    mesh.componentBounds_.push_back(component.bounds);
    mesh.componentVertex_.push_back(component.representative);
    mesh.componentVolume_.push_back(std::abs(component.signedVolume));
  }
  if (selfIntersection == SelfIntersectionCheck::perform) {
    requireNoSelfIntersection(surface, mesh.triangleComponent_, sourceName);
  }
  mesh.vertices_ = std::move(surface.vertices);
  mesh.triangles_ = std::move(surface.triangles);
  return mesh;
}

Box3 Mesh::bounds() const {
  Box3 box;
  for (const Box3& componentBox : componentBounds_) box.extend(componentBox);
  return box;
}

double Mesh::horizontalReach() const {
  double reach = 0;
  for (const Point3& vertex : vertices_) reach = std::max(reach, std::hypot(vertex.x(), vertex.y()));
  return reach;
}

double Mesh::volume() const {
  double total = 0;
  for (double componentVolume : componentVolume_) total += componentVolume;
  return total;
}

Mesh Mesh::translated(const Point3& offset, const std::string& sourceName) const {
  TriangleSoup soup{vertices_, triangles_};
  for (Point3& vertex : soup.vertices) vertex += offset;
  return fromSoup(soup, sourceName, nullptr, VertexWelding::asIndexed);
}

}  // namespace freespace
