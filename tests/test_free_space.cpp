// The free space against known topology and against the exact collision test.
// Known topology: the bundled scenes' start and goal lie in one free cell exactly
// when the scene is solvable (the cage, the too-narrow keyhole: two cells; the
// passable keyhole; the turn through theta = pi: one), and the caged robot's free
// space has exactly two cells (inside and outside the cage). Against the collision
// test: locate, which reads the arrangement only, says blocked exactly where the
// exact collision test on the perturbed meshes (an independent oracle on the
// meshes' triangles) says the robot touches or overlaps the environment.
#include <gtest/gtest.h>

#include <random>

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/free_space.h"

using namespace freespace;

namespace {

struct SceneCase {
  std::string cfg;
  bool solvable;
  int cells;  // the expected number of free cells, or -1 when not known
};

std::ostream& operator<<(std::ostream& out, const SceneCase& c) { return out << c.cfg; }

class BundledFreeSpace : public ::testing::TestWithParam<SceneCase> {};

TEST_P(BundledFreeSpace, StartAndGoalShareACellExactlyWhenSolvable) {
  const SceneCase& scene = GetParam();
  const LoadedProblem problem = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/" + scene.cfg);
  const FreeSpace space(problem.robot, problem.world);
  const Location start = space.locate(problem.problem.start), goal = space.locate(problem.problem.goal);
  std::cout << scene.cfg << ": " << space.shellCount() << " shells, " << space.freeShellCount() << " free, "
            << space.cellCount() << " free cells; start in cell " << start.cell << ", goal in cell " << goal.cell
            << "\n";
  ASSERT_TRUE(start.free);
  ASSERT_TRUE(goal.free);
  EXPECT_EQ(start.cell == goal.cell, scene.solvable);
  if (scene.cells >= 0) {
    EXPECT_EQ(space.cellCount(), static_cast<std::size_t>(scene.cells));
  }
}

TEST_P(BundledFreeSpace, BlockedExactlyWhereTheExactCollisionTestSaysSo) {
  const SceneCase& scene = GetParam();
  const LoadedProblem problem = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/" + scene.cfg);
  const FreeSpace space(problem.robot, problem.world);
  const ExactCollisionChecker collision(space.meshes().robot, space.meshes().world);
  const Box3 world = space.meshes().world.bounds();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> x(world.min().x() - 1, world.max().x() + 1);
  std::uniform_real_distribution<double> y(world.min().y() - 1, world.max().y() + 1);
  std::uniform_real_distribution<double> theta(-M_PI, M_PI);
  int disagreements = 0, free = 0;
  for (int i = 0; i < 300; ++i) {
    const Pose2 pose{x(random), y(random), theta(random)};
    const Location location = space.locate(pose);
    free += location.free;
    disagreements += location.free == collision.inCollision(pose);
  }
  EXPECT_EQ(disagreements, 0);
  EXPECT_GT(free, 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledFreeSpace,
                         ::testing::Values(SceneCase{"cage.cfg", false, 2}, SceneCase{"keyhole.cfg", true, -1},
                                           SceneCase{"keyhole_narrow.cfg", false, -1},
                                           SceneCase{"turn_around.cfg", true, -1}));

}  // namespace
