#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "command_runner.h"

using namespace freespace::testing;

namespace {

const std::string kMeshes = std::string(FREESPACE_TEST_DATA) + "/meshes/";

}  // namespace

TEST(Cli, EveryMalformedMeshExitsWithStatusTwoNamingTheFile) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kMeshes)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("bad_", 0) != 0) continue;
    const std::string path = entry.path().string();
    const CommandResult result = runFreespace("info " + quoted(kMeshes + "cube.obj") + " " + quoted(path));
    EXPECT_EQ(result.status, 2) << name << ": " << result.err;
    EXPECT_EQ(result.err.rfind("error: " + path + ": ", 0), 0u) << result.err;
    EXPECT_TRUE(result.out.empty()) << result.out;
    ++checked;
  }
  EXPECT_GE(checked, 15);
}

TEST(Cli, MissingFileExitsWithStatusTwo) {
  const CommandResult result = runFreespace("info " + quoted(kMeshes + "cube.obj") + " /nonexistent/world.obj");
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err.rfind("error: /nonexistent/world.obj: cannot open file", 0), 0u) << result.err;
  const CommandResult cfg = runFreespace("check --cfg /nonexistent/p.cfg --at 0 0 0");
  EXPECT_EQ(cfg.status, 2);
  EXPECT_EQ(cfg.err.rfind("error: /nonexistent/p.cfg: cannot open file", 0), 0u) << cfg.err;
}

TEST(Cli, InfoReportsMeshStatistics) {
  const CommandResult result =
      runFreespace("info --json " + quoted(kMeshes + "cube.obj") + " " + quoted(kMeshes + "two_cubes.obj"));
  ASSERT_EQ(result.status, 0) << result.err;
  const nlohmann::json info = nlohmann::json::parse(result.out);
  EXPECT_EQ(info["robot"]["triangles"], 12);
  EXPECT_EQ(info["robot"]["vertices"], 8);
  EXPECT_EQ(info["world"]["components"], 2);
  EXPECT_EQ(info["world"]["triangles"], 24);
}

TEST(Cli, CheckAnswersByBothTests) {
  // Robot and world are the same unit cube [0, 1]^3.
  const std::string meshes = quoted(kMeshes + "cube.obj") + " " + quoted(kMeshes + "cube.obj");
  const CommandResult far = runFreespace("check --json " + meshes + " --at 5 0 0");
  ASSERT_EQ(far.status, 0) << far.err;
  const nlohmann::json answer = nlohmann::json::parse(far.out);
  EXPECT_EQ(answer["exact_free"], true);
  EXPECT_EQ(answer["fcl_free"], true);
  EXPECT_NEAR(answer["fcl_distance"].get<double>(), 4.0, 1e-9);

  TempDir dir;
  std::ofstream(dir.file("batch.txt")) << "# x y theta\n5 0 0\n0.5 0.5 0\n1 0 0\n";
  const CommandResult batch = runFreespace("check --json " + meshes + " --batch " + quoted(dir.file("batch.txt")));
  ASSERT_EQ(batch.status, 0) << batch.err;
  std::istringstream lines(batch.out);
  std::vector<bool> free;
  for (std::string line; std::getline(lines, line);) free.push_back(nlohmann::json::parse(line)["exact_free"]);
  // Touching faces at x = 1 count as collision.
  EXPECT_EQ(free, (std::vector<bool>{true, false, false}));
}

TEST(Cli, BadBatchLineIsAnError) {
  TempDir dir;
  std::ofstream(dir.file("batch.txt")) << "5 0 0\n1 2\n";
  const std::string meshes = quoted(kMeshes + "cube.obj") + " " + quoted(kMeshes + "cube.obj");
  const CommandResult result = runFreespace("check " + meshes + " --batch " + quoted(dir.file("batch.txt")));
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err, "error: " + dir.file("batch.txt") + ": line 2: expected three finite numbers X Y THETA\n");
}

TEST(Cli, BadOptionValuesExitWithStatusTwoNamingTheOption) {
  const std::string meshes = quoted(kMeshes + "cube.obj") + " " + quoted(kMeshes + "cube.obj");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"check " + meshes + " --at 0 0 nan", "--at"},
      {"check " + meshes + " --at 0 0 inf", "--at"},
      {"check " + meshes + " --at 0 zero 0", "--at"},
      {"build " + meshes + " --perturbation -1", "--perturbation"},
      {"build " + meshes + " --seed -1", "--seed: must be a whole number"},
      {"build " + meshes + " --save ''", "--save: must not be empty"},
      {"generate --out x --seed -3", "--seed: must be a whole number"},
      {"slice " + meshes + " --theta nan --svg x.svg", "--theta: must be a finite number"},
      {"build " + meshes + " --perturbation nan", "--perturbation: must be a finite number, at least 0"},
      {"export " + meshes + " --ply out.ply --tolerance nan", "--tolerance: must be a finite number, at least 0"},
      {"info " + meshes + " --repair-tolerance inf", "--repair-tolerance: must be a finite number, at least 0"},
      {"build " + meshes + " --memory-limit nan", "--memory-limit: must be a finite number, at least 0"},
      {"build " + meshes + " --no-such-option", "--no-such-option"},
      {"no-such-command", "no-such-command"},
  };
  for (const auto& [arguments, option] : cases) {
    const CommandResult result = runFreespace(arguments);
    EXPECT_EQ(result.status, 2) << arguments << "\n" << result.err;
    EXPECT_NE(result.err.find(option), std::string::npos) << arguments << "\n" << result.err;
  }
  EXPECT_EQ(runFreespace("check --help").status, 0);
}

TEST(Cli, PipesAndDevicesAsInputAreRefusedNotWaitedOn) {
  TempDir dir;
  const std::string fifo = dir.file("pipe.obj");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string cube = quoted(kMeshes + "cube.obj");
  for (const std::string& arguments : {"info " + quoted(fifo) + " " + cube, "info --cfg " + quoted(fifo),
                                       "locate " + quoted(fifo) + " --at 0 0 0", "info /dev/zero " + cube}) {
    // Under a time limit: reading a FIFO nobody writes to would wait for ever.
    const CommandResult result = runFreespace(arguments, 20);
    EXPECT_EQ(result.status, 2) << arguments << "\n" << result.err;
    EXPECT_NE(result.err.find("not a regular file"), std::string::npos) << arguments << "\n" << result.err;
  }
}

TEST(Cli, EveryCommandHasHelp) {
  for (const char* command : {"", "check", "info", "generate"}) {
    const CommandResult result = runFreespace(std::string(command) + " --help");
    EXPECT_EQ(result.status, 0) << command;
    EXPECT_NE(result.out.find("Usage"), std::string::npos) << command;
  }
}
