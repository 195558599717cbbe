#include <gtest/gtest.h>

#include <fstream>

#include "freespace/input_error.h"
#include "freespace/problem/planar_problem.h"
#include "temp_dir.h"

using namespace freespace;
using freespace::testing::TempDir;

namespace {

const char* kCubeObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
    "f 1 3 2\nf 2 3 4\nf 5 6 7\nf 6 8 7\nf 1 2 5\nf 2 6 5\nf 3 7 4\nf 4 7 8\nf 1 5 3\nf 3 5 7\nf 2 4 6\nf 4 8 6\n";

std::string errorOf(const std::string& path) {
  try {
    readProblem(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(Problem, ReadsOmplAppKeys) {
  TempDir dir;
  dir.write("p.cfg",
            "[problem]\nname = test\nrobot = r.obj\nworld = w.obj\n"
            "start.x = 1.5\nstart.y = -2\nstart.theta = 0.25\ngoal.x = 3\ngoal.y = 4\ngoal.theta = -3.1\n"
            "volume.min.x = -10\nvolume.min.y = -11\nvolume.max.x = 12\nvolume.max.y = 13\n"
            "[benchmark]\ntime_limit = 5\nmem_limit = 1000\nrun_count = 7\n"
            "[planner]\nrrtconnect =\nprm =\n");
  std::vector<std::string> warnings;
  const PlanarProblem problem = readProblem(dir.file("p.cfg"), &warnings);
  EXPECT_EQ(problem.name, "test");
  EXPECT_EQ(problem.robot, "r.obj");
  EXPECT_EQ(problem.world, "w.obj");
  EXPECT_EQ(problem.start.x, 1.5);
  EXPECT_EQ(problem.start.y, -2);
  EXPECT_EQ(problem.start.theta, 0.25);
  EXPECT_EQ(problem.goal.theta, -3.1);
  ASSERT_TRUE(problem.volume.has_value());
  EXPECT_EQ(problem.volume->min().y(), -11);
  EXPECT_EQ(problem.volume->max().x(), 12);
  EXPECT_EQ(problem.timeLimit, 5);
  EXPECT_EQ(problem.runCount, 7u);
  EXPECT_EQ(problem.planners, (std::vector<PlannerEntry>{{"rrtconnect", {}}, {"prm", {}}}));
  EXPECT_TRUE(warnings.empty());
}

TEST(Problem, MissingRequiredKeyIsAnError) {
  TempDir dir;
  dir.write("p.cfg", "[problem]\nrobot = r.obj\nworld = w.obj\nstart.x = 0\nstart.y = 0\n"
                               "goal.x = 1\ngoal.y = 1\ngoal.theta = 0\n");
  EXPECT_EQ(errorOf(dir.file("p.cfg")), dir.file("p.cfg") + ": missing required key 'start.theta' in [problem]");
  dir.write("q.cfg", "[benchmark]\nrun_count = 3\n");
  EXPECT_EQ(errorOf(dir.file("q.cfg")), dir.file("q.cfg") + ": missing section [problem]");
}

TEST(Problem, BadValuesAndSyntaxAreErrors) {
  TempDir dir;
  dir.write("p.cfg", "[problem]\nrobot = r.obj\nworld = w.obj\nstart.x = abc\nstart.y = 0\n"
                               "start.theta = 0\ngoal.x = 1\ngoal.y = 1\ngoal.theta = 0\n");
  EXPECT_EQ(errorOf(dir.file("p.cfg")), dir.file("p.cfg") + ": [problem] start.x = 'abc' is not a finite number");
  dir.write("s.cfg", "[problem\nrobot = r.obj\n");
  EXPECT_EQ(errorOf(dir.file("s.cfg")), dir.file("s.cfg") + ": a line is neither '[section]' nor 'key = value': '[problem'");
  // The parser's own message would loop for ever substituting this line into itself.
  dir.write("loop.cfg", "[problem]\nrobot %invalid_line%\n");
  EXPECT_EQ(errorOf(dir.file("loop.cfg")),
            dir.file("loop.cfg") + ": a line is neither '[section]' nor 'key = value': 'robot %invalid_line%'");
  dir.write("r.cfg", "[problem]\nrobot = r.obj\nworld = w.obj\nstart.x = 0\nstart.y = 0\nstart.theta = 0\n"
                     "goal.x = 1\ngoal.y = 1\ngoal.theta = 0\n[benchmark]\nrun_count = -3\n");
  EXPECT_EQ(errorOf(dir.file("r.cfg")),
            dir.file("r.cfg") + ": [benchmark] run_count = '-3' is not a whole number from 0 to 4294967295");
  EXPECT_EQ(errorOf(dir.file("none.cfg")), dir.file("none.cfg") + ": cannot open file: No such file or directory");
  dir.write("nul.cfg", std::string("[problem]\nrobot = r.obj\0junk\nworld = w.obj\n", 43));
  EXPECT_EQ(errorOf(dir.file("nul.cfg")),
            dir.file("nul.cfg") + ": key 'problem.robot': a control character (such as a NUL byte) in the line");
}

TEST(Problem, UnknownKeysAreWarnings) {
  TempDir dir;
  dir.write("p.cfg", "[problem]\nrobot = r.obj\nworld = w.obj\nstart.x = 0\nstart.y = 0\n"
                               "start.theta = 0\ngoal.x = 1\ngoal.y = 1\ngoal.theta = 0\ncolour = red\n[extra]\na = 1\n");
  std::vector<std::string> warnings;
  readProblem(dir.file("p.cfg"), &warnings);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], dir.file("p.cfg") + ": unknown key 'colour' in [problem] ignored");
  EXPECT_EQ(warnings[1], dir.file("p.cfg") + ": unknown section [extra] ignored");
}

TEST(Problem, WriteThenReadGivesTheSameProblem) {
  TempDir dir;
  PlanarProblem problem;
  problem.name = "round trip";
  problem.robot = "robot.dae";
  problem.world = "world.dae";
  problem.start = {0.1, -0.2, 0.3};
  problem.goal = {1e-7, 2.5, -3.0};
  problem.volume = Eigen::AlignedBox2d(Eigen::Vector2d(-1, -2), Eigen::Vector2d(3, 4));
  problem.runCount = 4;
  problem.planners = {{"kpiece", {}}, {"rrt", {{"range", "0.5"}}}, {"rrt", {{"name", "RRT2"}}}};
  problem.benchmarkSettings = {{"save_paths", "all"}};
  writeProblem(problem, dir.file("p.cfg"));
  const PlanarProblem back = readProblem(dir.file("p.cfg"));
  EXPECT_EQ(back.name, problem.name);
  EXPECT_EQ(back.start.y, problem.start.y);
  EXPECT_EQ(back.goal.x, problem.goal.x);
  EXPECT_EQ(back.volume->max().y(), 4);
  EXPECT_EQ(back.runCount, 4u);
  EXPECT_EQ(back.planners, problem.planners);
  EXPECT_EQ(back.benchmarkSettings, problem.benchmarkSettings);
  // Nothing the user had is overwritten.
  EXPECT_THROW(writeProblem(problem, dir.file("p.cfg")), InputError);
}

TEST(Problem, LoadRecentresTheRobotAtItsVertexAverage) {
  TempDir dir;
  dir.write("cube.obj", kCubeObj);
  dir.write("p.cfg", "[problem]\nrobot = cube.obj\nworld = cube.obj\nstart.x = 0\nstart.y = 0\n"
                               "start.theta = 0\ngoal.x = 1\ngoal.y = 1\ngoal.theta = 0\n");
  const LoadedProblem loaded = loadProblem(dir.file("p.cfg"));
  // The unit cube's vertex average is (0.5, 0.5, 0.5); only x and y are removed.
  EXPECT_EQ(loaded.robotCentre, Point3(0.5, 0.5, 0));
  EXPECT_EQ(loaded.robot.bounds().min(), Point3(-0.5, -0.5, 0));
  EXPECT_EQ(loaded.robot.bounds().max(), Point3(0.5, 0.5, 1));
  EXPECT_EQ(loaded.world.bounds().min(), Point3(0, 0, 0));
}

TEST(Problem, RepeatedPlannerKeysAreKeptInOrderAsOmplAppGroupsThem) {
  TempDir dir;
  dir.write("p.cfg", "[problem]\nrobot = r.obj\nworld = w.obj\nstart.x = 0\nstart.y = 0\nstart.theta = 0\n"
                     "goal.x = 1\ngoal.y = 1\ngoal.theta = 0\ncontrol = dynamic_car\n"
                     "[benchmark]\ntime_limit=300.0\nrun_count=50\ntime_limit=20\nsave_paths = shortest\n"
                     "[planner]\nprm=\naps=\naps.name=APS1\naps.num_planners=1\naps=\naps.name=APS4\n"
                     "rrtstar.name=RRT*\nprm.max_nearest_neighbors = 8 # a comment\n");
  std::vector<std::string> warnings;
  const PlanarProblem problem = readProblem(dir.file("p.cfg"), &warnings);
  const std::vector<PlannerEntry> expected{{"prm", {{"max_nearest_neighbors", "8"}}},
                                           {"aps", {{"name", "APS1"}, {"num_planners", "1"}}},
                                           {"aps", {{"name", "APS4"}}},
                                           {"rrtstar", {{"name", "RRT*"}}}};
  EXPECT_EQ(problem.planners, expected);
  EXPECT_EQ(problem.timeLimit, 20) << "a repeated [benchmark] key takes its last value";
  EXPECT_EQ(problem.runCount, 50u);
  EXPECT_EQ(problem.benchmarkSettings, (std::vector<ConfigEntry>{{"save_paths", "shortest"}}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], dir.file("p.cfg") + ": unknown key 'control' in [problem] ignored");
}

TEST(Problem, RepeatedProblemKeyIsAnError) {
  TempDir dir;
  dir.write("p.cfg", "[problem]\nrobot = r.obj\nworld = w.obj\nstart.x = 0\nstart.y = 0\nstart.theta = 0\n"
                     "goal.x = 1\ngoal.y = 1\ngoal.theta = 0\nrobot = other.obj\n");
  EXPECT_EQ(errorOf(dir.file("p.cfg")), dir.file("p.cfg") + ": [problem] key 'robot' is given more than once");
}

// OMPL.app's centre is the single precision average of the vertices assimp returns
// with its flags: GenNormals gives each face its own normal, so corners of faces in
// different planes stay separate vertices. In this bipyramid the three equator
// vertices have four faces each and the two apexes three.
TEST(Problem, RobotCentreIsOmplAppsAverageOfTheImportedVertices) {
  TempDir dir;
  dir.write("bipyramid.obj", "v 3 0 0\nv -1 2 0\nv -1 -2 0\nv 0 0 1\nv 0 0 -1\n"
                             "f 1 2 4\nf 2 3 4\nf 3 1 4\nf 2 1 5\nf 3 2 5\nf 1 3 5\n");
  dir.write("p.cfg", "[problem]\nrobot = bipyramid.obj\nworld = bipyramid.obj\nstart.x = 0\nstart.y = 0\n"
                     "start.theta = 0\ngoal.x = 1\ngoal.y = 1\ngoal.theta = 0\n");
  const float corners[6][3][2] = {{{3, 0}, {-1, 2}, {0, 0}},  {{-1, 2}, {-1, -2}, {0, 0}}, {{-1, -2}, {3, 0}, {0, 0}},
                                  {{-1, 2}, {3, 0}, {0, 0}},  {{-1, -2}, {-1, 2}, {0, 0}}, {{3, 0}, {-1, -2}, {0, 0}}};
  float sumX = 0;
  float sumY = 0;
  for (const auto& face : corners) {
    for (const auto& corner : face) {
      sumX += corner[0];
      sumY += corner[1];
    }
  }
  const LoadedProblem loaded = loadProblem(dir.file("p.cfg"));
  EXPECT_EQ(loaded.robotCentre, Point3(sumX / 18.0f, sumY / 18.0f, 0));
  EXPECT_NE(loaded.robotCentre.x(), 0.2) << "the average of the five distinct vertices is another point";
  EXPECT_FLOAT_EQ(static_cast<float>(loaded.robot.bounds().max().x()), 3.0f - sumX / 18.0f);
}
