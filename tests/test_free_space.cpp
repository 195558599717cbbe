// The free space against known topology and against the exact collision test.
// Known topology: the bundled scenes' start and goal lie in one free cell exactly
// when the scene was made solvable (the scene generator's record: the cage and the
// too-narrow keyhole are not, the passable keyhole and the turn through theta = pi
// are), and the caged robot's free space has exactly two cells (inside and outside
// the cage). Against the collision
// test: locate, which reads the arrangement only, says blocked exactly where the
// exact collision test on the perturbed meshes (an independent oracle on the
// meshes' triangles) says the robot touches or overlaps the environment. And a
// construction announces its stages and stops within a second of being cancelled.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "bundled_problem.h"
#include "freespace/geometry/mesh_topology.h"
#include "freespace/geometry/patch_candidates.h"
#include "freespace/input_error.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/scenes/scene_generator.h"
#include "freespace/space/free_space.h"
#include "locate_oracle.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

struct SceneCase {
  std::string name;
  int cells;  // the expected number of free cells, or -1 when not known independently
};

std::ostream& operator<<(std::ostream& out, const SceneCase& c) { return out << c.name; }

class BundledFreeSpace : public ::testing::TestWithParam<SceneCase> {};

TEST_P(BundledFreeSpace, KnownTopologyAndAgreementWithTheExactCollisionTest) {
  const SceneCase& scene = GetParam();
  const LoadedProblem problem = loadBundledProblem(scene.name);
  const FreeSpace space(problem.robot, problem.world);
  // Topology: start and goal share a cell exactly when the scene was made solvable.
  const bool solvable = makeScene(scene.name).expectSolvable;
  const Location start = space.locate(problem.problem.start), goal = space.locate(problem.problem.goal);
  std::cout << scene.name << ": " << space.shellCount() << " shells, " << space.freeShellCount() << " free, "
            << space.cellCount() << " free cells; start in cell " << start.cell << ", goal in cell " << goal.cell
            << (solvable ? " (solvable)" : " (not solvable)") << "\n";
  ASSERT_TRUE(start.free);
  ASSERT_TRUE(goal.free);
  EXPECT_EQ(start.cell == goal.cell, solvable);
  if (scene.cells >= 0) {
    EXPECT_EQ(space.cellCount(), static_cast<std::size_t>(scene.cells));
  }
  // A bounded cell's box holds the configurations in it.
  const std::vector<std::optional<PatchBox>>& boxes = space.cellBoxes();
  ASSERT_EQ(boxes.size(), space.cellCount());
  EXPECT_FALSE(boxes[0].has_value());
  for (const Pose2& pose : {problem.problem.start, problem.problem.goal}) {
    const std::optional<PatchBox>& box = boxes[space.locate(pose).cell];
    if (!box) continue;
    EXPECT_TRUE(box->low[0] <= pose.x && pose.x <= box->high[0] && box->low[1] <= pose.y && pose.y <= box->high[1]);
  }
  // Free or blocked: the exact collision test on the perturbed meshes.
  const LocateCheck check = locateAgainstCollision(space, 500, 11);
  EXPECT_EQ(check.disagreements, 0) << "of 500";
  EXPECT_GT(check.free, 0);
}

// The benchmark's robots (14-facet house, non-convex fishbone) in a floor plan whose
// walls have three heights: locate agrees with the exact collision test, and the
// robot placed in each room's centre is free, all rooms in one cell (doors are wider
// than both robots).
TEST(FreeSpace, BenchmarkRobotsAmongWallsOfSeveralHeights) {
  FloorPlanLayout layout;
  layout.rooms = 2;
  layout.columns = 2;
  layout.cellSize = 3;
  layout.wallHeights = {0.375, 0.75, 1.25};
  layout.doorWidth = 1;
  const FloorPlan plan = makeFloorPlan(layout, 1);
  const Mesh world = makeCheckedMesh(plan.walls, "floor plan");
  for (const Mesh& robot : {makeHouseRobot(), makeFishboneRobot(2)}) {
    const FreeSpace space(robot, world);
    const LocateCheck check = locateAgainstCollision(space, 500, 5);
    std::cout << robot.triangles().size() << "-facet robot: " << space.cellCount() << " cells, " << check.free
              << " of 500 free\n";
    EXPECT_EQ(check.disagreements, 0) << "of 500";
    EXPECT_GT(check.free, 0);
    const Location first = space.locate({plan.roomCentres[0].x(), plan.roomCentres[0].y(), 0});
    const Location second = space.locate({plan.roomCentres[1].x(), plan.roomCentres[1].y(), 0});
    ASSERT_TRUE(first.free);
    ASSERT_TRUE(second.free);
    EXPECT_EQ(first.cell, second.cell);
  }
}

// The cage: inside and outside; flip_window: outside, and the bar's headings about 0
// and about pi in the box. The other counts are not known independently.
INSTANTIATE_TEST_SUITE_P(Scenes, BundledFreeSpace,
                         ::testing::Values(SceneCase{"cage", 2}, SceneCase{"keyhole", -1},
                                           SceneCase{"keyhole_narrow", -1}, SceneCase{"keyhole_wide", -1},
                                           SceneCase{"keyhole_tight", -1}, SceneCase{"flip_window", 3},
                                           SceneCase{"turn_around", -1}, SceneCase{"table", -1},
                                           SceneCase{"table_tall", -1}, SceneCase{"overhang", -1},
                                           SceneCase{"room_door", -1}, SceneCase{"random_polyhedra", -1},
                                           SceneCase{"tetra_floorplan", -1}),
                         [](const ::testing::TestParamInfo<SceneCase>& info) { return info.param.name; });

/// What a construction did when asked to stop `delay` after announcing `stage`.
struct CancelledBuild {
  std::vector<std::string> stages;  // announced, in order
  bool cancelled = false;           // it threw Cancelled
  double secondsToStop = 0;         // from the request to the end of the unwinding
};

CancelledBuild cancelDuring(const Scene& scene, const std::string& stage, std::chrono::milliseconds delay) {
  CancelledBuild result;
  std::atomic<bool> stop{false}, stageStarted{false};
  FreeSpaceOptions options;
  options.cancellation = Cancellation(stop);
  options.progress = [&](const std::string& announced) {
    result.stages.push_back(announced);
    if (announced == stage) stageStarted = true;
  };
  std::chrono::steady_clock::time_point asked;
  std::thread asker([&] {
    while (!stageStarted) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::this_thread::sleep_for(delay);
    asked = std::chrono::steady_clock::now();
    stop = true;
  });
  try {
    const FreeSpace space(scene.robot, scene.world, options);
  } catch (const Cancelled&) {
    result.cancelled = true;
  }
  const auto stopped = std::chrono::steady_clock::now();
  stageStarted = true;  // releases the asker if the stage never came
  asker.join();
  result.secondsToStop = std::chrono::duration<double>(stopped - asked).count();
  return result;
}

}  // namespace

TEST(FreeSpaceConstruction, AnnouncesItsStagesAndStopsSoonAfterCancellation) {
  // The tetrahedron in a floor plan of 1,024 rooms (35,216 facets): seconds to build.
  // Stopped 50 ms into the patches (every feature pair) and into the curves (the box
  // index and its pairs come first), it stops within a second of the request.
  const Scene scene = makeScene("tetra_floorplan_1024");
  const std::vector<std::string> expectedStages{"perturb", "patches", "curves"};
  for (std::size_t last = 1; last < expectedStages.size(); ++last) {
    const CancelledBuild build = cancelDuring(scene, expectedStages[last], std::chrono::milliseconds(50));
    std::cout << "cancelled 50 ms into " << expectedStages[last] << ": stopped after " << build.secondsToStop << " s\n";
    EXPECT_TRUE(build.cancelled) << expectedStages[last];
    EXPECT_LT(build.secondsToStop, 1.0) << expectedStages[last];
    const std::vector<std::string> prefix(expectedStages.begin(), expectedStages.begin() + last + 1);
    EXPECT_EQ(build.stages, prefix);
  }
}

// The candidates counted before the construction bound its patches from above, on
// every bundled problem; a memory limit below the estimate they give is refused
// before any patch is built, naming the scene and the estimate.
TEST(FreeSpaceConstruction, PatchCandidatesBoundThePatchesAndAreWeighedAgainstTheMemoryLimit) {
  for (const char* name : {"cage", "keyhole", "maze", "table", "random_polyhedra"}) {
    const LoadedProblem loaded = loadBundledProblem(name);
    const FreeSpace space(loaded.robot, loaded.world);
    PredicateStatistics statistics;
    const MeshTopology robotTopology(space.meshes().robot, statistics), worldTopology(space.meshes().world, statistics);
    const std::size_t candidates =
        countPatchCandidates(space.meshes().robot, robotTopology, space.meshes().world, worldTopology);
    EXPECT_GE(candidates, space.arrangement().patches.size()) << name;
    EXPECT_LE(candidates, 4 * space.arrangement().patches.size()) << name;
  }
  const LoadedProblem keyhole = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole.cfg");
  FreeSpaceOptions options;
  options.sourceName = "keyhole";
  options.memoryLimitBytes = 1e6;
  std::vector<std::string> stages;
  options.progress = [&](const std::string& stage) { stages.push_back(stage); };
  try {
    const FreeSpace space(keyhole.robot, keyhole.world, options);
    ADD_FAILURE() << "built within 1 MB";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "keyhole");
    EXPECT_NE(error.problem().find("the construction needs at least"), std::string::npos) << error.problem();
    EXPECT_NE(error.problem().find("more than the memory limit of 0.001 GB"), std::string::npos) << error.problem();
  }
  EXPECT_EQ(stages, (std::vector<std::string>{"perturb", "patches"}));
}
