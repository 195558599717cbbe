// The walk along the cell graph's route (src/space/route_path.h) on the bundled maze,
// whose route is long enough to be walked in parts on several cores (docs/design.md
// section 7): the parts joined make one path from the start to the goal, without a
// waypoint twice in a row, every motion free by the motion checker, and every
// clearance the walk certified held by the exact clearance along its motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "bundled_problem.h"
#include "freespace/space/free_space.h"
#include "freespace/space/motion_checker.h"
#include "space/every_core.h"
#include "space/route_path.h"

using namespace freespace;

namespace {

/// Every motion free by the motion checker, every certified clearance held by the
/// exact clearance at 51 configurations along its motion, from `start` to `goal`.
void expectFreeAndCertified(const FreeSpace& space, const RoutedPath& walked, const Pose2& start, const Pose2& goal) {
  const std::vector<Pose2>& waypoints = walked.waypoints;
  ASSERT_GE(waypoints.size(), 2u);
  ASSERT_EQ(walked.certified.size(), waypoints.size() - 1);
  EXPECT_EQ(waypoints.front().x, start.x);
  EXPECT_EQ(waypoints.front().y, start.y);
  EXPECT_EQ(waypoints.back().x, goal.x);
  EXPECT_EQ(waypoints.back().y, goal.y);
  EXPECT_EQ(waypoints.back().theta, goal.theta);
  const MotionChecker motions(space);
  for (std::size_t k = 0; k + 1 < waypoints.size(); ++k) {
    const Pose2 &from = waypoints[k], &to = waypoints[k + 1];
    EXPECT_FALSE(from.x == to.x && from.y == to.y && from.theta == to.theta) << "waypoint " << k << " twice";
    EXPECT_TRUE(motions.check(from, to).free) << "motion " << k;
    if (!walked.certified[k]) continue;
    for (int i = 0; i <= 50; ++i) {
      const Clearance clearance = space.clearance(MotionChecker::interpolate(from, to, i / 50.0));
      ASSERT_TRUE(clearance.location.free) << "motion " << k << " at " << i;
      EXPECT_GE(clearance.upper, *walked.certified[k]) << "motion " << k << " at " << i;
    }
  }
}

}  // namespace

TEST(RoutePath, TheMazesWalkJoinsItsPartsIntoOneFreePath) {
  if (coreCount() < 2) GTEST_SKIP() << "one core: the route is walked whole";
  const LoadedProblem loaded = freespace::testing::loadBundledProblem("maze");
  const FreeSpace space(loaded.robot, loaded.world);
  const Pose2 &start = loaded.problem.start, &goal = loaded.problem.goal;
  // Long enough for a part per core of two (at least four nodes each).
  const std::optional<std::vector<std::uint32_t>> route =
      space.cellGraph().route(*space.nodeOf(start), *space.nodeOf(goal));
  ASSERT_TRUE(route);
  ASSERT_GE(route->size(), 8u);

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  const std::optional<RoutedPath> inParts = routePathInParts(space, start, goal, deadline);
  ASSERT_TRUE(inParts) << "not walked in parts";
  expectFreeAndCertified(space, *inParts, start, goal);
  // routePath gives the same.
  const std::optional<RoutedPath> walked = routePath(space, start, goal, deadline);
  ASSERT_TRUE(walked);
  EXPECT_EQ(walked->waypoints.size(), inParts->waypoints.size());
}

TEST(RoutePath, AShortRouteIsWalkedWhole) {
  const LoadedProblem loaded = freespace::testing::loadBundledProblem("keyhole");
  const FreeSpace space(loaded.robot, loaded.world);
  const Pose2 &start = loaded.problem.start, &goal = loaded.problem.goal;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  EXPECT_FALSE(routePathInParts(space, start, goal, deadline));
  const std::optional<RoutedPath> walked = routePath(space, start, goal, deadline);
  ASSERT_TRUE(walked);
  expectFreeAndCertified(space, *walked, start, goal);
}
