#pragma once

#include <cstddef>

#include "freespace/geometry/mesh.h"
#include "freespace/geometry/mesh_topology.h"

namespace freespace {

/// The contacts that pass the first test of patch generation (vertexFacetPatches,
/// edgeEdgePatches): a pointed vertex of one body strictly within the height range of
/// a triangle of the other, and a convex edge of each body with overlapping height
/// ranges. An upper bound on the number of patches, counted in O((n + m) log m)
/// without building any, for the memory estimate made before the construction
/// (docs/design.md section 6).
std::size_t countPatchCandidates(const Mesh& robot, const MeshTopology& robotTopology, const Mesh& world,
                                 const MeshTopology& worldTopology);

}  // namespace freespace
