// VF and FV patches against their geometric definitions: the patch line is the
// signed contact function, exactly, and a patch exists over exactly the angles where
// every edge at the vertex points out of the facet plane (checked by trigonometry at
// sampled angles, away from the range ends).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "freespace/geometry/patch.h"
#include "exact_geometry.h"
#include "random_scene.h"
#include "test_meshes.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

/// The signed contact function straight from its definition: VF n . (R p + d - q0),
/// FV (R m) . (q - R p0 - d).
Rational geometricContact(const Contact& contact, const Mesh& robot, const Mesh& world, const ExactRotation& r,
                          const Exact3& d) {
  if (contact.kind == ContactKind::VertexFacet) {
    const Exact3 placed = rotate(r, exactPoint(robot.vertices()[contact.robot]));
    const Exact3 q0 = exactPoint(world.vertices()[world.triangles()[contact.world][0]]);
    return dot(normalOf(world, contact.world), {placed.x + d.x - q0.x, placed.y + d.y - q0.y, placed.z - q0.z});
  }
  const Exact3 m = rotate(r, normalOf(robot, contact.robot));
  const Exact3 p0 = rotate(r, exactPoint(robot.vertices()[robot.triangles()[contact.robot][0]]));
  const Exact3 q = exactPoint(world.vertices()[contact.world]);
  return dot(m, {q.x - p0.x - d.x, q.y - p0.y - d.y, q.z - p0.z});
}

/// Compatibility by trigonometry in long double: the smallest (R u) . n over the
/// edges at the vertex (positive: compatible).
long double compatibilityMargin(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                                const Mesh& world, const MeshTopology& worldTopology, long double theta) {
  const long double c = std::cos(theta), s = std::sin(theta);
  const auto rotated = [c, s](const Point3& v) {
    return std::array<long double, 3>{c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()};
  };
  const auto normal = [](const Mesh& mesh, std::uint32_t triangle) {
    const TriangleIndices& t = mesh.triangles()[triangle];
    return Point3((mesh.vertices()[t[1]] - mesh.vertices()[t[0]]).cross(mesh.vertices()[t[2]] - mesh.vertices()[t[0]]));
  };
  long double smallest = 1e300L;
  const bool vf = contact.kind == ContactKind::VertexFacet;
  const Mesh& vertexMesh = vf ? robot : world;
  const MeshTopology& topology = vf ? robotTopology : worldTopology;
  const std::uint32_t vertex = vf ? contact.robot : contact.world;
  for (std::uint32_t edge : topology.vertexEdges(vertex)) {
    const Point3 direction = vertexMesh.vertices()[topology.otherEnd(edge, vertex)] - vertexMesh.vertices()[vertex];
    // VF: (R u) . n; FV: (R m) . v.
    const auto a = rotated(vf ? direction : normal(robot, contact.robot));
    const Point3 b = vf ? normal(world, contact.world) : direction;
    smallest = std::min(smallest, a[0] * b.x() + a[1] * b.y() + a[2] * b.z());
  }
  return smallest;
}

}  // namespace

RC_GTEST_PROP(Patches, LinesAreTheSignedContactFunctionsAndRangesTheCompatibleAngles, ()) {
  const std::unique_ptr<RandomScene> scene = randomScene();
  const Mesh &robot = scene->robot, &world = scene->world;
  const MeshTopology &robotTopology = scene->robotTopology, &worldTopology = scene->worldTopology;
  AngleAlgebra& algebra = scene->algebra;
  const std::vector<Patch> patches = vertexFacetPatches(robot, robotTopology, world, worldTopology, algebra);

  for (const Patch& patch : patches) {
    const PatchLine<Rational> line = contactLine<Rational>(patch.contact, robot, robotTopology, world, worldTopology);
    for (double theta : {-2.5, -0.4, 0.0, 1.3, 3.0}) {
      const ExactRotation r = rotationAt(theta);
      const Exact3 d{Rational(theta) / 3, Rational(1) - Rational(theta), Rational(0)};
      RC_ASSERT(lineValue(line, r, d) == geometricContact(patch.contact, robot, world, r, d));
    }
  }
  // Every feature pair in height range: compatible at a sampled angle (clearly)
  // exactly when a patch of that pair contains the angle.
  const auto findPatch = [&patches](const Contact& contact) -> const Patch* {
    for (const Patch& patch : patches) {
      if (patch.contact.kind == contact.kind && patch.contact.robot == contact.robot &&
          patch.contact.world == contact.world) {
        return &patch;
      }
    }
    return nullptr;
  };
  int checked = 0;
  for (std::uint32_t v = 0; v < 4; ++v) {
    for (std::uint32_t t = 0; t < 4; ++t) {
      for (const Contact contact : {Contact{ContactKind::VertexFacet, v, t}, Contact{ContactKind::FacetVertex, t, v}}) {
        const bool vf = contact.kind == ContactKind::VertexFacet;
        const Mesh& facetMesh = vf ? world : robot;
        const double z = (vf ? robot : world).vertices()[v].z();
        const TriangleIndices& triangle = facetMesh.triangles()[t];
        const double low = std::min({facetMesh.vertices()[triangle[0]].z(), facetMesh.vertices()[triangle[1]].z(),
                                     facetMesh.vertices()[triangle[2]].z()});
        const double high = std::max({facetMesh.vertices()[triangle[0]].z(), facetMesh.vertices()[triangle[1]].z(),
                                      facetMesh.vertices()[triangle[2]].z()});
        const Patch* patch = findPatch(contact);
        if (!(low < z && z < high)) {
          RC_ASSERT(patch == nullptr);
          continue;
        }
        for (int i = 0; i < 72; ++i) {
          const double theta = -M_PI + (i + 0.5) * (2 * M_PI / 72);
          const long double margin = compatibilityMargin(contact, robot, robotTopology, world, worldTopology, theta);
          if (std::fabs(margin) < 1e-9) continue;
          const bool inRange = patch && algebra.contains(patch->range, AlgebraicAngle::rational(HalfAngle::fromRadians(theta)));
          RC_ASSERT(inRange == (margin > 0));
          ++checked;
        }
      }
    }
  }
  RC_TAG(checked > 0 ? "pairs in height range" : "no pair in height range");
}

TEST(Patches, EdgesParallelToAFacetGiveNoStrictContact) {
  // Unperturbed, a column's vertical edges lie parallel to a wall's vertical faces:
  // (R u) . n = u_z n_z vanishes at every angle, so no corner contact is strictly
  // compatible (perturbing the input resolves such contacts one way or the other).
  const Mesh robot = boxMesh({-0.5, -0.5, 0.25}, {0.5, 0.5, 0.75});
  const Mesh world = boxMesh({2, -3, 0}, {3, 3, 1});
  PredicateStatistics statistics;
  const MeshTopology robotTopology(robot, statistics), worldTopology(world, statistics);
  AngleAlgebra algebra(statistics);
  EXPECT_TRUE(vertexFacetPatches(robot, robotTopology, world, worldTopology, algebra).empty());
}

TEST(Patches, ApexAgainstAWallTouchesOverTheExpectedArc) {
  // The apex A = (1, 0, 0.5) of a tetrahedron has edges with horizontal directions
  // (-2, 1), (-2, -1), (-2, 0). Against the wall face x = 2 (outward normal -x) it is
  // compatible while every rotated edge has a negative x component, which is for
  // theta in [-atan 2, atan 2]. The face is two triangles: two such patches.
  const Mesh robot = tetrahedronMesh({1, 0, 0.5}, {-1, 1, 0.25}, {-1, -1, 0.25}, {-1, 0, 0.75});
  const Mesh world = boxMesh({2, -3, 0}, {3, 3, 1});
  ASSERT_EQ(robot.vertices()[0], Point3(1, 0, 0.5));
  PredicateStatistics statistics;
  const MeshTopology robotTopology(robot, statistics), worldTopology(world, statistics);
  AngleAlgebra algebra(statistics);
  const std::vector<Patch> patches = vertexFacetPatches(robot, robotTopology, world, worldTopology, algebra);
  int apexOnNearFace = 0;
  for (const Patch& patch : patches) {
    EXPECT_EQ(patch.contact.kind, ContactKind::VertexFacet);  // no wall vertex within the robot's heights
    const TriangleIndices& t = world.triangles()[patch.contact.world];
    const bool nearFace = world.vertices()[t[0]].x() == 2 && world.vertices()[t[1]].x() == 2 &&
                          world.vertices()[t[2]].x() == 2;
    if (patch.contact.robot != 0 || !nearFace) continue;
    ++apexOnNearFace;
    ASSERT_EQ(patch.range.arcs.size(), 1u);
    EXPECT_NEAR(patch.range.arcs[0].from.radians(), -std::atan(2.0), 1e-12);
    EXPECT_NEAR(patch.range.arcs[0].to.radians(), std::atan(2.0), 1e-12);
  }
  EXPECT_EQ(apexOnNearFace, 2);
}

namespace {

/// Weights lambda with sum lambda_i g_i = 0 and sum lambda_i = 1 (Gaussian
/// elimination in long double); nothing when the system is near singular.
std::optional<std::array<long double, 4>> convexWeightsOfOrigin(const std::array<std::array<long double, 3>, 4>& g) {
  long double m[4][5];
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) m[row][column] = g[column][row];
    m[row][4] = 0;
  }
  for (int column = 0; column < 4; ++column) m[3][column] = 1;
  m[3][4] = 1;
  for (int pivot = 0; pivot < 4; ++pivot) {
    int best = pivot;
    for (int row = pivot + 1; row < 4; ++row) {
      if (std::fabs(m[row][pivot]) > std::fabs(m[best][pivot])) best = row;
    }
    if (std::fabs(m[best][pivot]) < 1e-12L) return std::nullopt;
    std::swap(m[pivot], m[best]);
    for (int row = 0; row < 4; ++row) {
      if (row == pivot) continue;
      const long double factor = m[row][pivot] / m[pivot][pivot];
      for (int column = pivot; column < 5; ++column) m[row][column] -= factor * m[pivot][column];
    }
  }
  std::array<long double, 4> lambda;
  for (int i = 0; i < 4; ++i) lambda[i] = m[i][4] / m[i][i];
  return lambda;
}

std::array<long double, 3> rotatedNormal(const Mesh& mesh, std::uint32_t triangle, long double theta) {
  const TriangleIndices& t = mesh.triangles()[triangle];
  const Point3 n = (mesh.vertices()[t[1]] - mesh.vertices()[t[0]]).cross(mesh.vertices()[t[2]] - mesh.vertices()[t[0]]);
  const long double c = std::cos(theta), s = std::sin(theta);
  return {c * n.x() - s * n.y(), s * n.x() + c * n.y(), n.z()};
}

}  // namespace

RC_GTEST_PROP(Patches, EdgeEdgeRangesAreWhereTheWedgesAreApart, ()) {
  const std::unique_ptr<RandomScene> scene = randomScene();
  const Mesh &robot = scene->robot, &world = scene->world;
  const MeshTopology &robotTopology = scene->robotTopology, &worldTopology = scene->worldTopology;
  AngleAlgebra& algebra = scene->algebra;
  const std::vector<Patch> patches = edgeEdgePatches(robot, robotTopology, world, worldTopology, algebra);

  // The line is -sigma N . (R a0 + d - b0) with N = (R u) x v, exactly.
  for (const Patch& patch : patches) {
    const MeshEdge& a = robotTopology.edges()[patch.contact.robot];
    const MeshEdge& b = worldTopology.edges()[patch.contact.world];
    const PatchLine<Rational> line = contactLine<Rational>(patch.contact, robot, robotTopology, world, worldTopology);
    for (double theta : {-2.0, 0.5, 2.9}) {
      const ExactRotation r = rotationAt(theta);
      const Exact3 d{Rational(theta), Rational(2) - Rational(theta) / 5, Rational(0)};
      const Exact3 u = rotate(r, minus(exactPoint(robot.vertices()[a.to]), exactPoint(robot.vertices()[a.from])));
      const Exact3 v = minus(exactPoint(world.vertices()[b.to]), exactPoint(world.vertices()[b.from]));
      const Exact3 a0 = rotate(r, exactPoint(robot.vertices()[a.from]));
      const Exact3 b0 = exactPoint(world.vertices()[b.from]);
      const Rational expected =
          -patch.contact.side * dot(cross(u, v), {a0.x + d.x - b0.x, a0.y + d.y - b0.y, a0.z - b0.z});
      RC_ASSERT(lineValue(line, r, d) == expected);
    }
  }
  // For every pair of convex edges in height range and sampled angles: the wedges
  // are apart (0 in the convex hull of the four face normals, Gordan's theorem)
  // exactly when one of the pair's two patches contains the angle.
  int checked = 0;
  for (std::uint32_t i = 0; i < robotTopology.edges().size(); ++i) {
    for (std::uint32_t j = 0; j < worldTopology.edges().size(); ++j) {
      const MeshEdge& a = robotTopology.edges()[i];
      const MeshEdge& b = worldTopology.edges()[j];
      const double low = std::max(std::min(robot.vertices()[a.from].z(), robot.vertices()[a.to].z()),
                                  std::min(world.vertices()[b.from].z(), world.vertices()[b.to].z()));
      const double high = std::min(std::max(robot.vertices()[a.from].z(), robot.vertices()[a.to].z()),
                                   std::max(world.vertices()[b.from].z(), world.vertices()[b.to].z()));
      std::vector<const Patch*> pairPatches;
      for (const Patch& patch : patches) {
        if (patch.contact.robot == i && patch.contact.world == j) pairPatches.push_back(&patch);
      }
      if (!(low < high)) {
        RC_ASSERT(pairPatches.empty());
        continue;
      }
      for (int k = 0; k < 36; ++k) {
        const double theta = -M_PI + (k + 0.5) * (2 * M_PI / 36);
        const auto lambda = convexWeightsOfOrigin({rotatedNormal(robot, a.left, theta), rotatedNormal(robot, a.right, theta),
                                                   rotatedNormal(world, b.left, 0), rotatedNormal(world, b.right, 0)});
        if (!lambda) continue;
        const long double smallest = *std::min_element(lambda->begin(), lambda->end());
        if (std::fabs(smallest) < 1e-9) continue;
        const AlgebraicAngle angle = AlgebraicAngle::rational(HalfAngle::fromRadians(theta));
        int containing = 0;
        for (const Patch* patch : pairPatches) containing += algebra.contains(patch->range, angle);
        RC_ASSERT(containing == (smallest > 0 ? 1 : 0));
        ++checked;
      }
    }
  }
  RC_TAG(checked > 0 ? "edge pairs checked" : "no edge pair in height range");
}
