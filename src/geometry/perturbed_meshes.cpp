#include "freespace/geometry/perturbed_meshes.h"

#include <algorithm>

namespace freespace {

namespace {

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
  Perturbation perturbation(settings, sceneSize);
  Mesh perturbedRobot = perturbMesh(robot, perturbation, "perturbed robot");
  Mesh perturbedWorld = perturbMesh(world, perturbation, "perturbed environment");
  return {std::move(perturbedRobot), std::move(perturbedWorld), perturbation.record()};
}

}  // namespace freespace
