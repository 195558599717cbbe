// VF and FV patches against their geometric definitions: the patch line is the
// signed contact function, exactly, and a patch exists over exactly the angles where
// every edge at the vertex points out of the facet plane (checked by trigonometry at
// sampled angles, away from the range ends).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "freespace/geometry/patch.h"
#include "test_meshes.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

struct ExactRotation {
  Rational cosine, sine;
};

ExactRotation rotationAt(double theta) {
  ExactRotation rotation;
  HalfAngle::fromRadians(theta).cosSin(rotation.cosine, rotation.sine);
  return rotation;
}

struct Exact3 {
  Rational x, y, z;
};

Exact3 exactPoint(const Point3& p) { return {Rational(p.x()), Rational(p.y()), Rational(p.z())}; }
Exact3 minus(const Exact3& a, const Exact3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Exact3 cross(const Exact3& a, const Exact3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Rational dot(const Exact3& a, const Exact3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Exact3 rotate(const ExactRotation& r, const Exact3& p) {
  return {r.cosine * p.x - r.sine * p.y, r.sine * p.x + r.cosine * p.y, p.z};
}
Exact3 normalOf(const Mesh& mesh, std::uint32_t triangle) {
  const TriangleIndices& t = mesh.triangles()[triangle];
  const Exact3 a = exactPoint(mesh.vertices()[t[0]]);
  return cross(minus(exactPoint(mesh.vertices()[t[1]]), a), minus(exactPoint(mesh.vertices()[t[2]]), a));
}

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

Rational lineValue(const PatchLine<Rational>& line, const ExactRotation& r, const Exact3& d) {
  const Rational nx = r.cosine * line.a1x - r.sine * line.a1y + line.a2x;
  const Rational ny = r.sine * line.a1x + r.cosine * line.a1y + line.a2y;
  return nx * d.x + ny * d.y + line.k1 * r.sine + line.k2 * r.cosine + line.k3;
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

Point3 randomPoint(double zLow, double zHigh) {
  const auto coordinate = [](double low, double high) {
    return low + (high - low) * *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 1000001)) / 1e6;
  };
  return {coordinate(-1, 1), coordinate(-1, 1), coordinate(zLow, zHigh)};
}

std::optional<Mesh> randomTetrahedron(double zLow, double zHigh) {
  try {
    return tetrahedronMesh(randomPoint(zLow, zHigh), randomPoint(zLow, zHigh), randomPoint(zLow, zHigh),
                           randomPoint(zLow, zHigh));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

RC_GTEST_PROP(Patches, LinesAreTheSignedContactFunctionsAndRangesTheCompatibleAngles, ()) {
  // A robot inside the environment's height range and one reaching past it, so that
  // both VF and FV contacts occur.
  const std::optional<Mesh> robot = randomTetrahedron(0.1, 1.2);
  const std::optional<Mesh> world = randomTetrahedron(0.0, 1.0);
  RC_PRE(robot.has_value() && world.has_value());
  PredicateStatistics statistics;
  const MeshTopology robotTopology(*robot, statistics), worldTopology(*world, statistics);
  AngleAlgebra algebra(statistics);
  const std::vector<Patch> patches = vertexFacetPatches(*robot, robotTopology, *world, worldTopology, algebra);

  for (const Patch& patch : patches) {
    const PatchLine<Rational> line = contactLine<Rational>(patch.contact, *robot, *world);
    for (double theta : {-2.5, -0.4, 0.0, 1.3, 3.0}) {
      const ExactRotation r = rotationAt(theta);
      const Exact3 d{Rational(theta) / 3, Rational(1) - Rational(theta), Rational(0)};
      RC_ASSERT(lineValue(line, r, d) == geometricContact(patch.contact, *robot, *world, r, d));
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
        const Mesh& facetMesh = vf ? *world : *robot;
        const double z = (vf ? *robot : *world).vertices()[v].z();
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
          const long double margin = compatibilityMargin(contact, *robot, robotTopology, *world, worldTopology, theta);
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
