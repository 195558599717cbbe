#pragma once

#include "freespace/geometry/mesh.h"
#include "freespace/numbers/perturbation.h"

namespace freespace {

/// The robot and environment with every vertex coordinate perturbed once
/// (docs/design.md section 5, step 1), and the record that reproduces it.
struct PerturbedMeshes {
  Mesh robot;
  Mesh world;
  PerturbationRecord record;
};

/// Perturbs the robot's coordinates (in its own frame), then the environment's, in
/// vertex order, by at most settings.relativeSize times the scene size (the larger
/// bounding box diagonal of the two). The results are checked meshes again; where
/// they fail the checks (features closer than the perturbation crossing once moved),
/// the perturbation is made 16 times smaller and tried again, up to 4 times; the
/// record holds the size used, and the last failure is thrown.
PerturbedMeshes perturbMeshes(const Mesh& robot, const Mesh& world, const PerturbationSettings& settings);

}  // namespace freespace
