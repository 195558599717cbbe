// Patch segments against the contact geometry: at rational angles in a patch's
// range, every point of the segment (exact rationals) is a real contact of the two
// features (the contact point lies on both), points just beyond either end are not,
// and the free side is on the left.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>


#include "exact_geometry.h"
#include "freespace/geometry/patch_segment.h"
#include "freespace/input_error.h"
#include "random_scene.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

Exact3 exactVertex(const Mesh& mesh, std::uint32_t i) { return exactPoint(mesh.vertices()[i]); }
Exact3 plus(const Exact3& a, const Exact3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Exact3 scaled(const Rational& k, const Exact3& a) { return {k * a.x, k * a.y, k * a.z}; }

/// Whether p, in the plane of triangle (a, b, c), lies in the closed triangle.
bool inTriangle(const Exact3& p, const Exact3& a, const Exact3& b, const Exact3& c) {
  const Exact3 normal = cross(minus(b, a), minus(c, a));
  const std::array<Exact3, 3> corners{a, b, c};
  for (int i = 0; i < 3; ++i) {
    if (dot(cross(minus(corners[(i + 1) % 3], corners[i]), minus(p, corners[i])), normal) < 0) return false;
  }
  return true;
}

/// Whether the closed segments pq and rs, known to be coplanar, meet: the point of
/// pq at some height equals the point of rs at that height (neither is horizontal).
bool segmentsMeet(const Exact3& p, const Exact3& q, const Exact3& r, const Exact3& s) {
  // p + a (q - p) = r + b (s - r): solve the z equation for b, then x for a.
  const Exact3 u = minus(q, p), v = minus(s, r);
  // Heights: p.z + a u.z = r.z + b v.z, with a from x:  a u.x = r.x - p.x + b v.x.
  // Eliminate a: u.z (r.x - p.x + b v.x) = u.x (r.z - p.z + b v.z).
  const Rational coefficient = u.z * v.x - u.x * v.z;
  if (coefficient == 0) {
    // Use y instead of x.
    const Rational coefficientY = u.z * v.y - u.y * v.z;
    if (coefficientY == 0) return false;
    const Rational b = (u.y * (r.z - p.z) - u.z * (r.y - p.y)) / coefficientY;
    const Exact3 point = plus(r, scaled(b, v));
    const Rational a = (point.z - p.z) / u.z;
    const Exact3 other = plus(p, scaled(a, u));
    return a >= 0 && a <= 1 && b >= 0 && b <= 1 && other.x == point.x && other.y == point.y;
  }
  const Rational b = (u.x * (r.z - p.z) - u.z * (r.x - p.x)) / coefficient;
  const Exact3 point = plus(r, scaled(b, v));
  const Rational a = (point.z - p.z) / u.z;
  const Exact3 other = plus(p, scaled(a, u));
  return a >= 0 && a <= 1 && b >= 0 && b <= 1 && other.x == point.x && other.y == point.y && other.z == point.z;
}

/// Whether the robot placed at (r, d) touches the environment through the contact's
/// features, straight from the definition of the contact.
bool featuresTouch(const Contact& contact, const RandomScene& scene, const ExactRotation& r, const Exact3& d) {
  const auto placed = [&](std::uint32_t robotVertex) { return plus(rotate(r, exactVertex(scene.robot, robotVertex)), d); };
  switch (contact.kind) {
    case ContactKind::VertexFacet: {
      const TriangleIndices& t = scene.world.triangles()[contact.world];
      const Exact3 p = placed(contact.robot);
      const Exact3 a = exactVertex(scene.world, t[0]), b = exactVertex(scene.world, t[1]), c = exactVertex(scene.world, t[2]);
      return dot(cross(minus(b, a), minus(c, a)), minus(p, a)) == 0 && inTriangle(p, a, b, c);
    }
    case ContactKind::FacetVertex: {
      const TriangleIndices& t = scene.robot.triangles()[contact.robot];
      const Exact3 q = exactVertex(scene.world, contact.world);
      const Exact3 a = placed(t[0]), b = placed(t[1]), c = placed(t[2]);
      return dot(cross(minus(b, a), minus(c, a)), minus(q, a)) == 0 && inTriangle(q, a, b, c);
    }
    case ContactKind::EdgeEdge: {
      const MeshEdge& a = scene.robotTopology.edges()[contact.robot];
      const MeshEdge& b = scene.worldTopology.edges()[contact.world];
      return segmentsMeet(placed(a.from), placed(a.to), exactVertex(scene.world, b.from), exactVertex(scene.world, b.to));
    }
  }
  return false;
}

}  // namespace

RC_GTEST_PROP(PatchSegments, AreExactlyTheContactsOfTheirFeaturesWithTheFreeSideOnTheLeft, ()) {
  const std::unique_ptr<RandomScene> scene = randomScene();
  RC_PRE(scene->hasDistinctHeights());
  const std::vector<Patch> patches = scene->allPatches();

  int checked = 0;
  for (const Patch& patch : patches) {
    const PatchSegment segment = patchSegment(patch.contact, scene->robot, scene->robotTopology, scene->world,
                                              scene->worldTopology, scene->statistics);
    RC_ASSERT(segment.ends[0] != segment.ends[1]);
    const PatchLine<Rational> line =
        contactLine<Rational>(patch.contact, scene->robot, scene->robotTopology, scene->world, scene->worldTopology);
    for (int k = 0; k < 12; ++k) {
      const double theta = -M_PI + (k + 0.5) * (2 * M_PI / 12);
      const HalfAngle angle = HalfAngle::fromRadians(theta);
      if (!scene->algebra.contains(patch.range, AlgebraicAngle::rational(angle))) continue;
      const ExactRotation r = rotationAt(theta);
      std::array<Exact3, 2> ends;
      for (int e = 0; e < 2; ++e) {
        const auto point = spiralPoint(spiralOf<Rational>(segment.ends[e], scene->robot, scene->world), r.cosine, r.sine);
        ends[e] = {point[0], point[1], Rational(0)};
      }
      // Free side on the left: n x (end1 - end0) > 0.
      const LineAtAngle<Rational> normal = lineAtAngle(line, r.cosine, r.sine);
      RC_ASSERT(normal.nx * (ends[1].y - ends[0].y) - normal.ny * (ends[1].x - ends[0].x) > 0);
      for (const Rational& lambda : {Rational(0), Rational(1, 3), Rational(1, 2), Rational(1)}) {
        const Exact3 d = plus(ends[0], scaled(lambda, minus(ends[1], ends[0])));
        RC_ASSERT(lineValue(line, r, d) == 0);
        RC_ASSERT(featuresTouch(patch.contact, *scene, r, d));
      }
      for (const Rational& beyond : {Rational(-1, 1000), Rational(1001, 1000)}) {
        const Exact3 d = plus(ends[0], scaled(beyond, minus(ends[1], ends[0])));
        RC_ASSERT(!featuresTouch(patch.contact, *scene, r, d));
      }
      ++checked;
    }
  }
  RC_TAG(checked > 0 ? "segments checked" : "no patch");
}

TEST(PatchSegments, EqualHeightsAreReportedAsAnInputError) {
  const Mesh robot = boxMesh({-0.5, -0.5, 0.25}, {0.5, 0.5, 0.75});
  const Mesh world = boxMesh({2, -3, 0}, {3, 3, 1});
  try {
    requireDistinctHeights(robot, world, "scene.cfg");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "scene.cfg: robot vertex 0 and robot vertex 1 are at the same height 0.25; the construction needs "
              "distinct heights (switch perturbation on)");
  }
  const Mesh tilted = tetrahedronMesh({1, 0, 0.5}, {-1, 1, 0.25}, {-1, -1, 0.3}, {-1, 0, 0.75});
  const Mesh other = tetrahedronMesh({3, 0, 0.1}, {2, 1, 0.2}, {2, -1, 0.4}, {2, 0, 0.9});
  EXPECT_NO_THROW(requireDistinctHeights(tilted, other, "scene.cfg"));
}
