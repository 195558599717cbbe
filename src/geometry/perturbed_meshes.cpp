#include "freespace/geometry/perturbed_meshes.h"

#include <algorithm>

#include "freespace/input_error.h"

namespace freespace {

namespace {

// How often, and by what factor, the perturbation shrinks when the perturbed meshes
// are no longer valid: 1e-8 of the scene becomes at least 1.5e-13 of it, still
// hundreds of double steps.
constexpr int kSmallerPerturbations = 4;
constexpr double kShrinkFactor = 16;

Mesh perturbMesh(const Mesh& mesh, Perturbation& perturbation, const std::string& name) {
  TriangleSoup soup{mesh.vertices(), mesh.triangles()};
  for (Point3& vertex : soup.vertices) {
    for (int axis = 0; axis < 3; ++axis) vertex[axis] = perturbation.perturb(vertex[axis]);
  }
  // Checked again: moved vertices can make triangles meet that were a hair apart.
  return Mesh::fromSoup(soup, name, nullptr, VertexWelding::asIndexed);
}

}  // namespace

PerturbedMeshes perturbMeshes(const Mesh& robot, const Mesh& world, const PerturbationSettings& settings) {
  const double sceneSize = std::max(robot.bounds().diagonal().norm(), world.bounds().diagonal().norm());
  PerturbationSettings attempt = settings;
  for (int smaller = 0;; ++smaller) {
    try {
      Perturbation perturbation(attempt, sceneSize);
      Mesh perturbedRobot = perturbMesh(robot, perturbation, "perturbed robot");
      Mesh perturbedWorld = perturbMesh(world, perturbation, "perturbed environment");
      return {std::move(perturbedRobot), std::move(perturbedWorld), perturbation.record()};
    } catch (const InputError&) {
      // Features of a mesh closer than the perturbation (a wall's foot a hair from
      // the edge of the floor it stands on) may cross once moved: a smaller
      // perturbation serves general position as well (docs/design.md section 5).
      if (!attempt.enabled || smaller == kSmallerPerturbations) throw;
      attempt.relativeSize /= kShrinkFactor;
    }
  }
}

}  // namespace freespace
