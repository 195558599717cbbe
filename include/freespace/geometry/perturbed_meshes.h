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
  /// The power of two the input's coordinates were multiplied by (1 for a scene of
  /// ordinary size; docs/design.md section 5): the construction's x and y are the
  /// input's times this, its angles the input's.
  double scale = 1;
};

/// Scales both meshes by a power of two when the scene's largest coordinate lies
/// outside [kSmallestUnscaled, kLargestUnscaled] (bringing it into [1, 2)), then
/// perturbs the robot's coordinates (in its own frame), then the environment's, in
/// vertex order, by at most settings.relativeSize times the scene size (the larger
/// bounding box diagonal of the two). The results are checked meshes again; where
/// they fail the checks (features closer than the perturbation crossing once moved),
/// the perturbation is made 16 times smaller and tried again, up to 4 times; the
/// record holds the size used, and the last failure is thrown.
constexpr double kSmallestUnscaled = 0x1p-8, kLargestUnscaled = 0x1p16;
PerturbedMeshes perturbMeshes(const Mesh& robot, const Mesh& world, const PerturbationSettings& settings);

}  // namespace freespace
