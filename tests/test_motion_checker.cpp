// Certified motions (docs/design.md section 7) against the exact collision test on
// the construction's meshes: a motion certified free has no colliding configuration
// among 10,000 along it, and its certified least clearance is at most the clearance
// at 200 points along it; a motion with a colliding configuration is never certified
// free, and its certified free prefix has none.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>

#include "bundled_problem.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/scenes/scene_generator.h"
#include "freespace/space/motion_checker.h"

using namespace freespace;
using freespace::testing::loadBundledProblem;

namespace {

struct DenseCheck {
  bool collides = false;      // somewhere along the motion
  double firstCollision = 2;  // the fraction of the first colliding sample
};

DenseCheck denseCollisions(const FreeSpace& space, const ExactCollisionChecker& collision, const Pose2& from,
                           const Pose2& to, int samples) {
  const double scale = space.meshes().scale;
  DenseCheck dense;
  for (int i = 0; i <= samples; ++i) {
    const double t = static_cast<double>(i) / samples;
    const Pose2 pose = MotionChecker::interpolate(from, to, t);
    if (collision.inCollision({pose.x * scale, pose.y * scale, pose.theta})) {
      dense.collides = true;
      dense.firstCollision = t;
      return dense;
    }
  }
  return dense;
}

class BundledMotions : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledMotions, CertifiedMotionsPassTheExactCollisionTest) {
  const LoadedProblem problem = loadBundledProblem(GetParam());
  const FreeSpace space(problem.robot, problem.world);
  const ExactCollisionChecker collision(space.meshes().robot, space.meshes().world);
  const MotionChecker motions(space);
  const Box3 world = space.meshes().world.bounds();
  const double scale = space.meshes().scale;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(world.min().x() / scale, world.max().x() / scale);
  std::uniform_real_distribution<double> y(world.min().y() / scale, world.max().y() / scale);
  std::uniform_real_distribution<double> theta(-M_PI, M_PI), step(-0.3, 0.3);
  int certified = 0, refused = 0;
  for (int i = 0; i < 40; ++i) {
    // Short motions from free configurations, so that many are free.
    Pose2 from{x(random), y(random), theta(random)};
    if (!space.locate(from).free) continue;
    const double span = 0.2 * (world.max().x() - world.min().x()) / scale;
    const Pose2 to{from.x + span * step(random), from.y + span * step(random), from.theta + 4 * step(random)};
    const MotionCheck check = motions.check(from, to, 0.02);
    const DenseCheck dense = denseCollisions(space, collision, from, to, check.free ? 10000 : 1000);
    if (check.free) {
      ++certified;
      EXPECT_FALSE(dense.collides) << i;
      for (int k = 0; k <= 200; ++k) {
        const Clearance along = space.clearance(MotionChecker::interpolate(from, to, k / 200.0));
        EXPECT_LE(check.minClearance, along.upper) << i << " at " << k;
      }
      EXPECT_GT(check.minClearance, 0) << i;
    } else {
      ++refused;
      EXPECT_LT(check.lastFreeFraction, 1) << i;
      if (dense.collides) {
        EXPECT_LE(check.lastFreeFraction, dense.firstCollision) << i;
      }
    }
  }
  std::cout << GetParam() << ": " << certified << " motions certified free, " << refused << " not\n";
  EXPECT_GT(certified, 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledMotions, ::testing::Values("keyhole", "maze", "table", "room_door"));

/// The keyhole's start, its clearance and witness: slides toward the contact.
class KeyholeSlides : public ::testing::Test {
 protected:
  const LoadedProblem problem = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole.cfg");
  const FreeSpace space{problem.robot, problem.world};
  const MotionChecker motions{space};
  const Pose2 start = problem.problem.start;
  const Clearance clearance = space.clearance(start);
};

// A straight slide across a wall is never free; its free prefix ends before the wall.
TEST_F(KeyholeSlides, ASlideIntoAWallStopsBeforeIt) {
  ASSERT_TRUE(clearance.contact.has_value());
  // Slide toward the nearest contact, twice as far as the clearance.
  const double reach = 2 * clearance.upper;
  const Pose2 into{start.x + reach * clearance.direction[0], start.y + reach * clearance.direction[1], start.theta};
  const MotionCheck check = motions.check(start, into);
  EXPECT_FALSE(check.free);
  EXPECT_LE(check.lastFreeFraction, 0.5);
  EXPECT_GT(check.lastFreeFraction, 0.49);
  // The same slide stopping short of it is free, with its clearance left at its end.
  const Pose2 shortOf{start.x + 0.4 * reach * clearance.direction[0], start.y + 0.4 * reach * clearance.direction[1],
                      start.theta};
  const MotionCheck free = motions.check(start, shortOf, 0.02);
  EXPECT_TRUE(free.free);
  const double left = clearance.upper - 0.4 * reach;  // at its end, the least along it
  EXPECT_LE(free.minClearance, left * (1 + 1e-12));
  EXPECT_GE(free.minClearance, 0.98 * left);
}

// keepsClearance on a slide toward the contact: a level the slide keeps (below
// the clearance left at its end) is certified, one above it never is.
TEST_F(KeyholeSlides, KeepsClearanceOnlyAboveTheLeastAlongTheMotion) {
  const double slide = 0.6 * clearance.upper;  // toward the contact
  const Pose2 to{start.x + slide * clearance.direction[0], start.y + slide * clearance.direction[1], start.theta};
  const double left = clearance.upper - slide;  // at its end, the least along it
  EXPECT_TRUE(motions.keepsClearance(start, to, 0.95 * left));
  EXPECT_FALSE(motions.keepsClearance(start, to, 1.01 * left));
}

// Where the environment lies above the robot's heights nothing can be touched: the
// clearance is unbounded and any motion is free at once (an unbounded clearance once
// made the check halve the motion without end).
TEST(MotionChecker, AMotionWhereNothingCanBeTouchedIsFree) {
  const Mesh robot = makeBarRobot(2, 0.5, 0.5);
  const Mesh world = makeCheckedMesh(makeBox(Box3(Point3(-1, -1, 2), Point3(1, 1, 3))), "shelf");
  const FreeSpace space(robot, world);
  const MotionChecker motions(space);
  EXPECT_EQ(space.clearance({0, 0, 0}).lower, HUGE_VAL);
  for (const double slack : {1.0, 0.02}) {
    const MotionCheck check = motions.check({-3, 0, 0}, {3, 1, 2}, slack);
    EXPECT_TRUE(check.free) << slack;
    EXPECT_EQ(check.minClearance, HUGE_VAL) << slack;
    EXPECT_LE(check.clearanceQueries, 2u) << slack;
  }
}

// OMPL's SO(2) interpolation: the shorter arc, across theta = +-pi.
TEST(MotionChecker, InterpolatesThetaAlongTheShorterArc) {
  const Pose2 middle = MotionChecker::interpolate({0, 0, 3.0}, {2, 4, -3.0}, 0.5);
  EXPECT_DOUBLE_EQ(middle.x, 1);
  EXPECT_DOUBLE_EQ(middle.y, 2);
  EXPECT_NEAR(std::remainder(middle.theta - M_PI, 2 * M_PI), 0, 1e-12);
}

}  // namespace
