// Patch segments against the exact collision test (an independent oracle): at a
// rational angle, the boundary of the C-obstacle slice lies on the active patch
// segments, so two placements with different collision verdicts are always
// separated by an active segment; and just behind the middle of every active
// segment (its negative side) the robot collides.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <random>

#include "bundled_scene.h"
#include "exact_geometry.h"
#include "freespace/collision/exact_collision_checker.h"
#include "random_scene.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

bool between(const Rational& a, const Rational& b, const Rational& value) {
  return (a <= value && value <= b) || (b <= value && value <= a);
}

/// Whether the closed segments pq and ab meet.
bool closedSegmentsMeet(const ExactPoint2& p, const ExactPoint2& q, const ExactPoint2& a, const ExactPoint2& b) {
  const int pqa = orientation(p, q, a), pqb = orientation(p, q, b), abp = orientation(a, b, p),
            abq = orientation(a, b, q);
  const auto onSegment = [](const ExactPoint2& s, const ExactPoint2& t, const ExactPoint2& r) {
    return between(s.x, t.x, r.x) && between(s.y, t.y, r.y);
  };
  if (pqa * pqb < 0 && abp * abq < 0) return true;
  return (pqa == 0 && onSegment(p, q, a)) || (pqb == 0 && onSegment(p, q, b)) || (abp == 0 && onSegment(a, b, p)) ||
         (abq == 0 && onSegment(a, b, q));
}

/// An active patch's segment at the angle: exact ends, the line's normal, and a
/// double bounding box.
struct SliceSegment {
  std::array<ExactPoint2, 2> ends;
  ExactPoint2 normal;
  double low[2], high[2];
};

std::vector<SliceSegment> activeSegments(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra,
                                         const HalfAngle& angle) {
  Rational cosine, sine;
  angle.cosSin(cosine, sine);
  const AlgebraicAngle at = AlgebraicAngle::rational(angle);
  std::vector<SliceSegment> segments;
  for (const PatchGeometry& patch : patches) {
    if (!algebra.contains(patch.patch.range, at)) continue;
    SliceSegment segment;
    for (int e = 0; e < 2; ++e) {
      const auto point = spiralPoint(spiralOf<Rational>(patch.ends[e]), cosine, sine);
      segment.ends[e] = {point[0], point[1]};
    }
    const LineAtAngle<Rational> line = lineAtAngle(lineOf<Rational>(patch.line), cosine, sine);
    segment.normal = {line.nx, line.ny};
    for (int axis = 0; axis < 2; ++axis) {
      const double a = (axis == 0 ? segment.ends[0].x : segment.ends[0].y).template convert_to<double>();
      const double b = (axis == 0 ? segment.ends[1].x : segment.ends[1].y).convert_to<double>();
      segment.low[axis] = std::min(a, b) - 1e-9 * (1 + std::fabs(a));
      segment.high[axis] = std::max(a, b) + 1e-9 * (1 + std::fabs(b));
    }
    segments.push_back(segment);
  }
  return segments;
}

bool separatedBySegment(const std::vector<SliceSegment>& segments, const Pose2& p, const Pose2& q) {
  const ExactPoint2 exactP{Rational(p.x), Rational(p.y)}, exactQ{Rational(q.x), Rational(q.y)};
  for (const SliceSegment& segment : segments) {
    if (std::max(p.x, q.x) < segment.low[0] || std::min(p.x, q.x) > segment.high[0] ||
        std::max(p.y, q.y) < segment.low[1] || std::min(p.y, q.y) > segment.high[1]) {
      continue;
    }
    if (closedSegmentsMeet(exactP, exactQ, segment.ends[0], segment.ends[1])) return true;
  }
  return false;
}

struct BoundaryCheck {
  int changes = 0;      // sample pairs whose verdicts differ
  int unexplained = 0;  // ... with no active segment between them
  int segments = 0;     // segments whose negative side was tested
  int notColliding = 0; // ... where the robot did not collide there
};

/// The two checks at `angleCount` angles, `pairCount` short random pairs each.
BoundaryCheck checkSliceBoundary(const Mesh& robot, const Mesh& world, const std::vector<PatchGeometry>& patches,
                                 AngleAlgebra& algebra, int angleCount, int pairCount) {
  const ExactCollisionChecker checker(robot, world);
  const Box3 bounds = world.bounds();
  const double reach = robot.bounds().max().head<2>().norm() + robot.bounds().min().head<2>().norm();
  const double size = bounds.diagonal().head<2>().norm() + reach;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  BoundaryCheck check;
  for (int k = 0; k < angleCount; ++k) {
    const double theta = -M_PI + (k + unit(random)) * (2 * M_PI / angleCount);
    const std::vector<SliceSegment> segments = activeSegments(patches, algebra, HalfAngle::fromRadians(theta));
    for (int i = 0; i < pairCount; ++i) {
      const double x = bounds.min().x() - reach + unit(random) * (bounds.sizes().x() + 2 * reach);
      const double y = bounds.min().y() - reach + unit(random) * (bounds.sizes().y() + 2 * reach);
      const double direction = 2 * M_PI * unit(random), step = 0.02 * size;
      const Pose2 p{x, y, theta}, q{x + step * std::cos(direction), y + step * std::sin(direction), theta};
      if (checker.inCollision(p) == checker.inCollision(q)) continue;
      check.changes++;
      check.unexplained += !separatedBySegment(segments, p, q);
    }
    for (const SliceSegment& segment : segments) {
      const double ax = segment.ends[0].x.convert_to<double>(), ay = segment.ends[0].y.convert_to<double>();
      const double bx = segment.ends[1].x.convert_to<double>(), by = segment.ends[1].y.convert_to<double>();
      const double nx = segment.normal.x.convert_to<double>(), ny = segment.normal.y.convert_to<double>();
      const double length = std::hypot(bx - ax, by - ay), normalLength = std::hypot(nx, ny);
      if (length < 1e-6 * size) continue;  // too short to step behind its middle in doubles
      const double behind = 1e-6 * length / normalLength;
      check.segments++;
      check.notColliding += !checker.inCollision({0.5 * (ax + bx) - behind * nx, 0.5 * (ay + by) - behind * ny, theta});
    }
  }
  return check;
}

}  // namespace

RC_GTEST_PROP(SliceBoundary, LiesOnThePatchSegments, ()) {
  const std::unique_ptr<RandomScene> scene = randomCrowdedScene();
  RC_PRE(scene->hasDistinctHeights());
  const std::vector<PatchGeometry> patches = scene->allPatchGeometries();
  const BoundaryCheck check = checkSliceBoundary(scene->robot, scene->world, patches, scene->algebra, 4, 200);
  RC_ASSERT(check.unexplained == 0);
  RC_ASSERT(check.notColliding == 0);
  RC_TAG(check.changes > 0 ? "verdicts change" : "no change");
}

class BundledSceneSlices : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledSceneSlices, BoundaryLiesOnThePatchSegments) {
  BundledScene scene(GetParam());
  const BoundaryCheck check =
      checkSliceBoundary(scene.meshes.robot, scene.meshes.world, scene.geometries, scene.algebra, 16, 2000);
  EXPECT_GT(check.changes, 0);
  EXPECT_GT(check.segments, 0);
  EXPECT_EQ(check.unexplained, 0) << "of " << check.changes << " pairs with different verdicts";
  EXPECT_EQ(check.notColliding, 0) << "of " << check.segments << " segments";
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledSceneSlices,
                         ::testing::Values("cage.cfg", "keyhole.cfg", "keyhole_narrow.cfg", "maze.cfg", "overhang.cfg",
                                           "random_polyhedra.cfg", "room_door.cfg", "table.cfg", "table_tall.cfg",
                                           "tetra_floorplan.cfg", "turn_around.cfg"));
