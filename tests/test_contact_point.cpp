// The robot's point in a clearance's contact (src/space/contact_point.h) against the
// contact's features, placed independently: at the contact's configuration (the
// witness's `nearest`, the configuration's angle), the point lies, in (x, y), on the
// environment's triangle (VF), at the environment's vertex (FV) or on the
// environment's edge (EE), and on the robot: no farther from its axis than its reach.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>

#include "bundled_problem.h"
#include "random_configurations.h"
#include "space/contact_point.h"

using namespace freespace;
using freespace::testing::loadBundledProblem;

namespace {

using Point2 = Eigen::Vector2d;

double distanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 along = b - a;
  const double share = along.squaredNorm() > 0 ? std::clamp((p - a).dot(along) / along.squaredNorm(), 0.0, 1.0) : 0;
  return (p - (a + share * along)).norm();
}

/// 0 inside the triangle's (x, y) shadow, else the distance to its nearest side.
double distanceToTriangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  const auto side = [&](const Point2& from, const Point2& to) {
    const Point2 along = to - from, off = p - from;
    return along.x() * off.y() - along.y() * off.x();
  };
  const double ab = side(a, b), bc = side(b, c), ca = side(c, a);
  if ((ab >= 0 && bc >= 0 && ca >= 0) || (ab <= 0 && bc <= 0 && ca <= 0)) return 0;
  return std::min({distanceToSegment(p, a, b), distanceToSegment(p, b, c), distanceToSegment(p, c, a)});
}

class ContactPoints : public ::testing::TestWithParam<std::string> {};

TEST_P(ContactPoints, LieOnTheEnvironmentsFeature) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  const PerturbedMeshes& meshes = space.meshes();
  const double scale = meshes.scale;
  const auto world = [&](std::uint32_t vertex) -> Point2 { return meshes.world.vertices()[vertex].head<2>() / scale; };
  double reach = 0;
  for (const Point3& vertex : meshes.robot.vertices()) reach = std::max(reach, vertex.head<2>().norm() / scale);
  freespace::testing::RandomConfigurations configurations(space, 20261205);
  std::array<int, 3> checked{};
  for (int sample = 0; sample < 3000; ++sample) {
    const Pose2 scaled = configurations.next();
    const Pose2 pose{scaled.x / scale, scaled.y / scale, scaled.theta};
    const Clearance clearance = space.clearance(pose);
    if (!clearance.location.free || !clearance.contact) continue;
    const std::optional<ContactPoint> point = contactPoint(space, clearance, pose.theta, 0);
    if (!point) continue;
    const Point2 placed =
        Point2(clearance.nearest[0], clearance.nearest[1]) + Point2(point->fromAxis[0], point->fromAxis[1]);
    const std::array<std::uint32_t, 4>& vertices = clearance.contactVertices;
    const double tolerance = 1e-9 + point->error;
    EXPECT_LE(Point2(point->fromAxis[0], point->fromAxis[1]).norm(), reach + tolerance);
    switch (clearance.contact->kind) {
      case ContactKind::VertexFacet:
        EXPECT_LE(distanceToTriangle(placed, world(vertices[1]), world(vertices[2]), world(vertices[3])), tolerance)
            << "sample " << sample;
        ++checked[0];
        break;
      case ContactKind::FacetVertex:
        EXPECT_LE((placed - world(vertices[0])).norm(), tolerance) << "sample " << sample;
        ++checked[1];
        break;
      case ContactKind::EdgeEdge:
        EXPECT_LE(distanceToSegment(placed, world(vertices[2]), world(vertices[3])), tolerance) << "sample " << sample;
        ++checked[2];
        break;
    }
  }
  EXPECT_GT(checked[0] + checked[1] + checked[2], 100);
}

INSTANTIATE_TEST_SUITE_P(Bundled, ContactPoints, ::testing::Values("keyhole", "random_polyhedra", "overhang", "maze"));

}  // namespace
