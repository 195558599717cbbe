// The generator's soups, written to files as modelling tools write them and loaded
// as a user would: the meshes read must be the solids the generator meant (its
// checked meshes, an oracle built without the loader) by the exact collision test,
// and agree with FCL run on the triangles exactly as the files hold them, at random
// states away from contact; the defective soups are refused naming the file.
#include <gtest/gtest.h>

#include <random>

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/input_error.h"
#include "freespace/io/mesh_reader.h"
#include "freespace/scenes/scene_generator.h"
#include "temp_dir.h"

using namespace freespace;
using freespace::testing::TempDir;

namespace {

constexpr int kStates = 1500;

struct Written {
  Scene scene;
  LoadedProblem loaded;
  TriangleSoup robotAsRead;
  TriangleSoup worldAsRead;
};

Written writeAndLoad(const std::string& name, const TempDir& dir) {
  Written written{makeScene(name), {}, {}, {}};
  const std::string cfg = writeScene(written.scene, dir.file(""), "dae");
  written.loaded = loadProblem(cfg);
  written.robotAsRead = readTriangleSoup(dir.file(written.loaded.problem.robot));
  for (Point3& vertex : written.robotAsRead.vertices) vertex -= written.loaded.robotCentre;
  written.worldAsRead = readTriangleSoup(dir.file(written.loaded.problem.world));
  return written;
}

// A state where moving the robot by `step` along x or y changes the answer.
bool nearContact(const ExactCollisionChecker& checker, const Pose2& pose, bool collides, double step) {
  for (const auto& [dx, dy] : {std::pair{step, 0.0}, {-step, 0.0}, {0.0, step}, {0.0, -step}}) {
    if (checker.inCollision({pose.x + dx, pose.y + dy, pose.theta}) != collides) return true;
  }
  return false;
}

class SoupScene : public ::testing::TestWithParam<std::string> {};

TEST_P(SoupScene, ReadsAsTheSolidsTheGeneratorMeantAndAgreesWithFclOnTheFiles) {
  const TempDir dir;
  const Written written = writeAndLoad(GetParam(), dir);
  const ExactCollisionChecker loaded(written.loaded.robot, written.loaded.world);
  const ExactCollisionChecker meant(written.scene.robot, written.scene.world);
  const FclCollisionChecker fcl(written.robotAsRead, written.worldAsRead);
  const Box3 world = written.scene.world.bounds();
  const double step = 1e-4 * world.diagonal().norm();
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> x(world.min().x(), world.max().x()), y(world.min().y(), world.max().y()),
      theta(-M_PI, M_PI);
  int compared = 0, collisions = 0;
  for (int i = 0; i < kStates; ++i) {
    const Pose2 pose{x(random), y(random), theta(random)};
    const bool collides = meant.inCollision(pose);
    if (nearContact(meant, pose, collides, step)) continue;
    ++compared;
    collisions += collides;
    EXPECT_EQ(loaded.inCollision(pose), collides) << GetParam() << " at " << pose.x << " " << pose.y << " " << pose.theta;
    // FCL sees surfaces only: it may call free a robot inside a wall, never the reverse.
    if (fcl.inCollision(pose)) {
      EXPECT_TRUE(collides) << GetParam() << " at " << pose.x << " " << pose.y;
    }
  }
  EXPECT_GT(compared, kStates * 9 / 10);
  EXPECT_GT(collisions, kStates / 10) << "the states must test the walls";
}

INSTANTIATE_TEST_SUITE_P(Generated, SoupScene, ::testing::Values("soup_maze", "soup_pieces"));

TEST(SoupScene, DefectiveSoupsAreRefusedNamingTheFileAndWhere) {
  for (const char* name : {"soup_open_sheet", "soup_crack"}) {
    const TempDir dir;
    const std::string cfg = writeScene(makeScene(name), dir.file(""), "dae");
    try {
      loadProblem(cfg);
      ADD_FAILURE() << name << " loaded";
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), dir.file(std::string(name) + "_world.dae")) << error.what();
      EXPECT_NE(error.problem().find("enclose nothing"), std::string::npos) << error.what();
      EXPECT_NE(error.problem().find("between ("), std::string::npos) << error.what();
    }
  }
}

}  // namespace
