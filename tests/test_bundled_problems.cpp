// The bundled problems load, and their start and goal configurations are free by
// the exact test and by FCL, including the OMPL.app-style problem with COLLADA meshes.
#include <gtest/gtest.h>

#include <filesystem>

#include "command_runner.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/problem/planar_problem.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

const std::string kProblems = std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/";

void expectStartAndGoalFree(const std::string& cfg) {
  const LoadedProblem loaded = loadProblem(cfg);
  const ExactCollisionChecker exact(loaded.robot, loaded.world);
  const FclCollisionChecker fcl(loaded.robot, loaded.world);
  for (const Pose2& pose : {loaded.problem.start, loaded.problem.goal}) {
    EXPECT_FALSE(exact.inCollision(pose)) << cfg << " at " << pose.x << " " << pose.y << " " << pose.theta;
    EXPECT_FALSE(fcl.inCollision(pose)) << cfg << " at " << pose.x << " " << pose.y << " " << pose.theta;
  }
}

}  // namespace

TEST(BundledProblems, StartAndGoalAreFree) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kProblems)) {
    if (entry.path().extension() != ".cfg") continue;
    expectStartAndGoalFree(entry.path().string());
    ++count;
  }
  EXPECT_GE(count, 8);
}

TEST(BundledProblems, ColladaProblemLoadsAndItsStartAndGoalAreReportedFree) {
  const std::string cfg = kProblems + "room_door_dae.cfg";
  const PlanarProblem problem = readProblem(cfg);
  EXPECT_EQ(std::filesystem::path(problem.robot).extension(), ".dae");
  EXPECT_EQ(std::filesystem::path(problem.world).extension(), ".dae");
  expectStartAndGoalFree(cfg);
  // The same through the command line, as a user would ask.
  for (const Pose2& pose : {problem.start, problem.goal}) {
    std::ostringstream at;
    at.precision(17);
    at << pose.x << " " << pose.y << " " << pose.theta;
    const CommandResult result = runFreespace("check --cfg '" + cfg + "' --at " + at.str());
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("exact free, fcl free"), std::string::npos) << result.out;
  }
}
