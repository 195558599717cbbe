#pragma once

// A bundled problem (benchmarks/problems) through the construction's first stages,
// for tests on real scenes: perturbed meshes, topology, patches and their geometry.

#include <string>
#include <vector>

#include "freespace/geometry/mesh_topology.h"
#include "freespace/geometry/patch.h"
#include "freespace/geometry/patch_geometry.h"
#include "freespace/geometry/perturbed_meshes.h"
#include "freespace/numbers/algebraic_angle.h"
#include "freespace/problem/planar_problem.h"

namespace freespace::testing {

struct BundledScene {
  explicit BundledScene(const std::string& cfgName)
      : loaded(loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/" + cfgName)),
        meshes(perturbMeshes(loaded.robot, loaded.world, PerturbationSettings{})),
        robotTopology(meshes.robot, statistics),
        worldTopology(meshes.world, statistics),
        algebra(statistics) {
    patches = vertexFacetPatches(meshes.robot, robotTopology, meshes.world, worldTopology, algebra);
    const std::vector<Patch> edgePatches =
        edgeEdgePatches(meshes.robot, robotTopology, meshes.world, worldTopology, algebra);
    patches.insert(patches.end(), edgePatches.begin(), edgePatches.end());
    geometries = patchGeometries(patches, meshes.robot, robotTopology, meshes.world, worldTopology, statistics);
  }

  LoadedProblem loaded;
  PerturbedMeshes meshes;
  PredicateStatistics statistics;
  MeshTopology robotTopology;
  MeshTopology worldTopology;
  AngleAlgebra algebra;
  std::vector<Patch> patches;
  std::vector<PatchGeometry> geometries;
};

}  // namespace freespace::testing
