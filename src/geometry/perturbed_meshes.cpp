#include "freespace/geometry/perturbed_meshes.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "freespace/input_error.h"

namespace freespace {

namespace {

// How often, and by what factor, the perturbation shrinks when the perturbed meshes
// are no longer valid: 1e-8 of the scene becomes at least 1.5e-13 of it, still
// hundreds of double steps.
constexpr int kSmallerPerturbations = 4;
constexpr double kShrinkFactor = 16;

// The power of two that brings the scene's largest coordinate into [1, 2), or 1 when
// it is of ordinary size. Multiplying by it is exact, the free space scales with the
// scene, and the construction's numbers (products of several coordinates) stay far
// from double precision's underflow and overflow, where its filters fail and every
// predicate falls back to exact arithmetic.
double normalisingScale(const Mesh& robot, const Mesh& world) {
  double largest = 0;
  for (const Mesh* mesh : {&robot, &world}) {
    for (const Point3& vertex : mesh->vertices()) largest = std::max(largest, vertex.cwiseAbs().maxCoeff());
  }
  if (largest == 0 || (largest >= kSmallestUnscaled && largest <= kLargestUnscaled)) return 1;
  return std::ldexp(1.0, -std::ilogb(largest));
}

// Perturbs the mesh's coordinates; `heights` holds those given to vertices so far.
// The construction needs every vertex height distinct (requireDistinctHeights): with
// a million vertices at one height, two offsets land on one double now and then (about
// n^2 / 2 in 1e8 at the default size), and the later one is moved up by double steps
// until its height is free, a perturbation as good as any.
Mesh perturbMesh(const Mesh& mesh, double scale, Perturbation& perturbation, std::unordered_set<double>& heights,
                 const std::string& name) {
  TriangleSoup soup{mesh.vertices(), mesh.triangles()};
  for (Point3& vertex : soup.vertices) {
    for (int axis = 0; axis < 3; ++axis) vertex[axis] = perturbation.perturb(vertex[axis] * scale);
    if (perturbation.record().absoluteSize == 0) continue;
    while (!heights.insert(vertex.z()).second) vertex.z() = std::nextafter(vertex.z(), HUGE_VAL);
  }
  // Checked again: moved vertices can make triangles meet that were a hair apart.
  return Mesh::fromSoup(soup, name, nullptr, VertexWelding::asIndexed);
}

}  // namespace

PerturbedMeshes perturbMeshes(const Mesh& robot, const Mesh& world, const PerturbationSettings& settings) {
  const double scale = normalisingScale(robot, world);
  const double sceneSize = scale * std::max(robot.bounds().diagonal().norm(), world.bounds().diagonal().norm());
  PerturbationSettings attempt = settings;
  for (int smaller = 0;; ++smaller) {
    try {
      Perturbation perturbation(attempt, sceneSize);
      std::unordered_set<double> heights;
      Mesh perturbedRobot = perturbMesh(robot, scale, perturbation, heights, "perturbed robot");
      Mesh perturbedWorld = perturbMesh(world, scale, perturbation, heights, "perturbed environment");
      return {std::move(perturbedRobot), std::move(perturbedWorld), perturbation.record(), scale};
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
