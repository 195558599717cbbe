#include "freespace/geometry/patch_candidates.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace freespace {

namespace {

/// Height ranges as two sorted lists, lows and highs, for counting the ranges that
/// meet an open interval.
class HeightRanges {
 public:
  void add(double low, double high) {
    lows_.push_back(low);
    highs_.push_back(high);
  }
  void sort() {
    std::sort(lows_.begin(), lows_.end());
    std::sort(highs_.begin(), highs_.end());
  }
  /// How many ranges (low, high) meet the open interval (from, to): those starting
  /// below `to`, less those ending at or below `from` (which start below it too).
  std::size_t meeting(double from, double to) const {
    const auto startingBelow = std::lower_bound(lows_.begin(), lows_.end(), to) - lows_.begin();
    const auto endedBefore = std::upper_bound(highs_.begin(), highs_.end(), from) - highs_.begin();
    return static_cast<std::size_t>(std::max<std::ptrdiff_t>(startingBelow - endedBefore, 0));
  }

 private:
  std::vector<double> lows_, highs_;
};

std::pair<double, double> heightsOf(const Mesh& mesh, const TriangleIndices& triangle) {
  const auto [low, high] = std::minmax({mesh.vertices()[triangle[0]].z(), mesh.vertices()[triangle[1]].z(),
                                        mesh.vertices()[triangle[2]].z()});
  return {low, high};
}

/// Pointed vertices of `vertexMesh` strictly within the heights of triangles of `facetMesh`.
std::size_t vertexFacetCandidates(const Mesh& vertexMesh, const MeshTopology& vertexTopology, const Mesh& facetMesh) {
  HeightRanges triangles;
  for (const TriangleIndices& triangle : facetMesh.triangles()) {
    const auto [low, high] = heightsOf(facetMesh, triangle);
    triangles.add(low, high);
  }
  triangles.sort();
  std::size_t count = 0;
  for (std::uint32_t vertex = 0; vertex < vertexMesh.vertices().size(); ++vertex) {
    // A point z strictly inside (low, high): the ranges meeting (z, z) counted as
    // those with low < z, less those with high <= z.
    const double z = vertexMesh.vertices()[vertex].z();
    if (vertexTopology.isPointed(vertex)) count += triangles.meeting(z, z);
  }
  return count;
}

std::size_t edgeEdgeCandidates(const Mesh& robot, const MeshTopology& robotTopology, const Mesh& world,
                               const MeshTopology& worldTopology) {
  HeightRanges worldEdges;
  for (const MeshEdge& edge : worldTopology.edges()) {
    if (!edge.convex) continue;
    const auto [low, high] = std::minmax(world.vertices()[edge.from].z(), world.vertices()[edge.to].z());
    worldEdges.add(low, high);
  }
  worldEdges.sort();
  std::size_t count = 0;
  for (const MeshEdge& edge : robotTopology.edges()) {
    if (!edge.convex) continue;
    const auto [low, high] = std::minmax(robot.vertices()[edge.from].z(), robot.vertices()[edge.to].z());
    count += worldEdges.meeting(low, high);
  }
  return count;
}

}  // namespace

std::size_t countPatchCandidates(const Mesh& robot, const MeshTopology& robotTopology, const Mesh& world,
                                 const MeshTopology& worldTopology) {
  return vertexFacetCandidates(robot, robotTopology, world) + vertexFacetCandidates(world, worldTopology, robot) +
         edgeEdgeCandidates(robot, robotTopology, world, worldTopology);
}

}  // namespace freespace
