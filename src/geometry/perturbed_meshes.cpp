#include "freespace/geometry/perturbed_meshes.h"

#include <algorithm>

namespace freespace {

namespace {

Mesh perturbMesh(const Mesh& mesh, Perturbation& perturbation, const std::string& name) {
  TriangleSoup soup{mesh.vertices(), mesh.triangles()};
  for (Point3& vertex : soup.vertices) {
    for (int axis = 0; axis < 3; ++axis) vertex[axis] = perturbation.perturb(vertex[axis]);
  }
  // The input was checked for surfaces that meet themselves (touching included).
  // Vertices moved by about 1e-8 of the scene's size (DESIGN.md section 5) cannot make
  // two triangles meet that were farther apart than that; checking again would cost
  // several times the perturbation itself.
  return Mesh::fromSoup(soup, name, nullptr, Mesh::SelfIntersection::Skip);
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
