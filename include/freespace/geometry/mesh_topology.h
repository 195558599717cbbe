#pragma once

#include <cstdint>
#include <vector>

#include "freespace/geometry/mesh.h"
#include "freespace/numbers/predicate_statistics.h"

namespace freespace {

/// An undirected edge of a closed, consistently oriented mesh and its two triangles:
/// `left` traverses it from `from` to `to`, `right` from `to` to `from`.
struct MeshEdge {
  std::uint32_t from = 0;
  std::uint32_t to = 0;
  std::uint32_t left = 0;
  std::uint32_t right = 0;
  /// The solid's dihedral angle at the edge is strictly less than pi (decided
  /// exactly); flat and reflex edges are not convex.
  bool convex = false;
};

/// Adjacency of a checked mesh (docs/design.md section 6, step 1): edges with their
/// triangles and convexity, the edges around each vertex, and which vertices are
/// pointed (the solid's cone there lies in an open half space but for the vertex).
/// Convexity and pointedness are decided by exact predicates on the mesh's
/// coordinates, counted in `statistics`.
class MeshTopology {
 public:
  MeshTopology(const Mesh& mesh, PredicateStatistics& statistics);

  const std::vector<MeshEdge>& edges() const { return edges_; }
  /// Indices into edges() of the edges incident to the vertex.
  const std::vector<std::uint32_t>& vertexEdges(std::uint32_t vertex) const { return vertexEdges_[vertex]; }
  /// The vertex at the other end of an incident edge.
  std::uint32_t otherEnd(std::uint32_t edge, std::uint32_t vertex) const;
  bool isPointed(std::uint32_t vertex) const { return pointed_[vertex]; }

 private:
  std::vector<MeshEdge> edges_;
  std::vector<std::vector<std::uint32_t>> vertexEdges_;
  std::vector<bool> pointed_;
};

}  // namespace freespace
