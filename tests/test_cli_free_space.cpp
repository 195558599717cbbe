// The build and locate commands on bundled scenes. Locate's answers are compared
// with independent knowledge: the scene's start and goal are free and lie in one
// cell exactly when the scene was designed solvable, and a batch of configurations
// gets the exact collision test's answers (the check command).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "command_runner.h"

using namespace freespace::testing;

namespace {

const std::string kProblems = std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/";

std::vector<nlohmann::json> jsonLines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

/// The JSON answers of `command --json --cfg CFG` (a bundled problem) on a batch file
/// holding `batch`; empty after a failure, which it reports.
std::vector<nlohmann::json> batchAnswers(const std::string& command, const std::string& cfg, const std::string& batch) {
  TempDir dir;
  std::ofstream(dir.file("batch.txt")) << batch;
  const CommandResult result =
      runFreespace(command + " --json --cfg '" + kProblems + cfg + "' --batch '" + dir.file("batch.txt") + "'");
  EXPECT_EQ(result.status, 0) << result.err;
  return result.status == 0 ? jsonLines(result.out) : std::vector<nlohmann::json>{};
}

}  // namespace

TEST(CliFreeSpace, BuildPrintsTheStatisticsAsJson) {
  const CommandResult result = runFreespace("build --json --cfg '" + kProblems + "keyhole.cfg'");
  ASSERT_EQ(result.status, 0) << result.err;
  const nlohmann::json statistics = nlohmann::json::parse(result.out);
  for (const char* key : {"patches", "edges", "vertices", "shells", "cells", "free_cells", "seconds", "stage_seconds",
                          "predicates", "peak_memory_mb", "perturbation"}) {
    EXPECT_TRUE(statistics.contains(key)) << key;
  }
  EXPECT_GT(statistics["patches"].get<int>(), 0);
  EXPECT_GE(statistics["shells"].get<int>(), statistics["free_shells"].get<int>());
  EXPECT_GE(statistics["free_cells"].get<int>(), 1);
  EXPECT_GT(statistics["predicates"]["ef"]["levels"]["double"].get<long>(), 0);
  EXPECT_EQ(statistics["perturbation"]["seed"], 1);
  EXPECT_GE(statistics["graph"]["nodes"].get<int>(), statistics["free_cells"].get<int>());
  EXPECT_GE(statistics["graph"]["critical_angles"].get<int>(), 0);
  EXPECT_TRUE(statistics["graph"].contains("edges"));
}

// Locate names the node of the cell graph of each free configuration: the start and
// the goal of a problem in one node when a translation at one angle joins them
// (keyhole: both at theta 0 in front of and behind the wall, not joined that way).
TEST(CliFreeSpace, LocateNamesTheNodeOfFreeConfigurations) {
  const std::vector<nlohmann::json> answers =
      batchAnswers("locate", "keyhole.cfg", "0 -2.25 0\n0 -2.0 0\n0 0 0\n0 2.25 0\n");
  ASSERT_EQ(answers.size(), 4u);
  EXPECT_TRUE(answers[0].contains("node"));
  EXPECT_EQ(answers[0]["node"], answers[1]["node"]);  // within the start's clearance
  EXPECT_FALSE(answers[2].contains("node"));          // blocked
  EXPECT_TRUE(answers[3].contains("node"));
  EXPECT_NE(answers[0]["node"], answers[3]["node"]);  // the wall lies between them at theta 0
}

TEST(CliFreeSpace, LocateSeparatesTheNarrowKeyholesStartAndGoal) {
  for (const auto& [cfg, solvable] : {std::pair<std::string, bool>{"keyhole.cfg", true}, {"keyhole_narrow.cfg", false}}) {
    // Start, goal, and configurations across the scene, for the exact test to judge.
    const std::string batch = "# start and goal\n0 -2.25 0\n0 2.25 0\n0 0 0\n0 0 1.5707963267948966\n0.5 0.1 0.3\n-1 0 2\n3 3 0\n";
    const std::vector<nlohmann::json> answers = batchAnswers("locate", cfg, batch), exact = batchAnswers("check", cfg, batch);
    ASSERT_EQ(answers.size(), 7u);
    ASSERT_EQ(exact.size(), 7u);
    for (std::size_t i = 0; i < answers.size(); ++i) EXPECT_EQ(answers[i]["free"], exact[i]["exact_free"]) << i;
    ASSERT_TRUE(answers[0]["free"].get<bool>() && answers[1]["free"].get<bool>());
    EXPECT_EQ(answers[0]["cell"] == answers[1]["cell"], solvable) << cfg;
  }
}

// Clearance on the keyhole: free or blocked as the exact test (check) says, positive
// exactly when free, certified to 1e-12 relative, with its contact; the start can
// slide 1.5 south before its edge meets the frame (less the perturbation).
TEST(CliFreeSpace, ClearanceIsSignedByTheExactTestAndNamesItsContact) {
  const std::string batch = "0 -2.25 0\n0 0 0\n3 3 0.5\n-1 0 2\n";
  const std::vector<nlohmann::json> answers = batchAnswers("clearance", "keyhole.cfg", batch),
                                    exact = batchAnswers("check", "keyhole.cfg", batch);
  ASSERT_EQ(answers.size(), 4u);
  for (std::size_t i = 0; i < answers.size(); ++i) {
    EXPECT_EQ(answers[i]["free"], exact[i]["exact_free"]) << i;
    const double lower = answers[i]["clearance_lower"], upper = answers[i]["clearance_upper"];
    EXPECT_LE(lower, upper) << i;
    EXPECT_EQ(lower > 0, answers[i]["free"].get<bool>()) << i;
    EXPECT_LE(upper - lower, 1e-12 * std::abs(upper)) << i;
    EXPECT_TRUE(answers[i].contains("clearance")) << i;
    EXPECT_TRUE(answers[i]["contact"].contains("kind")) << i;
  }
  const CommandResult text = runFreespace("clearance --cfg '" + kProblems + "keyhole.cfg' --at 0 -2.25 0");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("free, cell 1, clearance 1.49999"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("certified in ["), std::string::npos) << text.out;
}

TEST(CliFreeSpace, ClearanceRefusesABadConfiguration) {
  const CommandResult result = runFreespace("clearance --cfg '" + kProblems + "keyhole.cfg' --at 0 nan 0");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("--at"), std::string::npos) << result.err;
}

TEST(CliFreeSpace, LocateWithoutConfigurationsIsAnError) {
  const CommandResult result = runFreespace("locate --cfg '" + kProblems + "keyhole.cfg'");
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.err.find("--at X Y THETA or --batch FILE"), std::string::npos) << result.err;
}

// A build stopped by `signal` after one and a half seconds: its exit status, what it
// printed on stderr and how long it took.
struct StoppedBuild {
  int status;
  std::string err;
  double seconds;
};

StoppedBuild buildStoppedBy(const std::string& signal) {
  TempDir dir;
  // The tetrahedron in a floor plan of 1,024 rooms (35,216 facets) takes about half a
  // second to load and check, and seconds to build.
  EXPECT_EQ(runFreespace("generate --out '" + dir.file("scene") + "' --scene tetra_floorplan_1024").status, 0);
  const auto start = std::chrono::steady_clock::now();
  // --foreground: one signal, to the tool alone. Otherwise timeout sends it to its
  // process group as well, the tool gets it twice, and a second signal means "stop
  // now" (an exit without the message) when the first has not yet been handled.
  const std::string command = "timeout --foreground --preserve-status -s " + signal + " 1.5 '" + FREESPACE_CLI +
                              "' build --cfg '" + dir.file("scene/tetra_floorplan_1024.cfg") + "' >'" +
                              dir.file("out") + "' 2>'" + dir.file("err") + "'";
  const int raw = std::system(command.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, readWholeFile(dir.file("err")), seconds};
}

TEST(CliFreeSpace, InterruptStopsABuildWithStatus130) {
  const StoppedBuild stopped = buildStoppedBy("INT");
  EXPECT_EQ(stopped.status, 130);
  EXPECT_EQ(stopped.err, "cancelled\n");
  EXPECT_LT(stopped.seconds, 3.0);
}

TEST(CliFreeSpace, TerminationStopsABuildWithStatus143) {
  const StoppedBuild stopped = buildStoppedBy("TERM");
  EXPECT_EQ(stopped.status, 143);
  EXPECT_EQ(stopped.err, "cancelled\n");
  EXPECT_LT(stopped.seconds, 3.0);
}

TEST(CliFreeSpace, SliceDrawsTheCellsAndNeverOverwrites) {
  TempDir dir;
  const std::string svg = dir.file("cage.svg");
  const std::string command = "slice --cfg '" + kProblems + "cage.cfg' --theta 0.3 --resolution 40 --robot-at 0 0 --svg '" + svg + "'";
  const CommandResult first = runFreespace(command);
  ASSERT_EQ(first.status, 0) << first.err;
  const std::string picture = readWholeFile(svg);
  EXPECT_EQ(picture.rfind("<svg", 0), 0u);
  // A title, axes in the meshes' units, and a legend naming what is drawn.
  EXPECT_NE(picture.find(">Free space slice at theta = 0.3 rad"), std::string::npos);
  EXPECT_NE(picture.find(", 2 free cells</text>"), std::string::npos);
  EXPECT_NE(picture.find(">x (the meshes' units)</text>"), std::string::npos);
  EXPECT_NE(picture.find(">y (the meshes' units)</text>"), std::string::npos);
  for (const char* entry : {">blocked (robot touches or overlaps)<", ">free, cell 0 (unbounded)<", ">free, cell 1<",
                            ">boundary of cell 1<", ">the robot at the point given<"}) {
    EXPECT_NE(picture.find(entry), std::string::npos) << entry;
  }
  // Each face is labelled with its node: the cage's inside and outside at this angle.
  EXPECT_NE(picture.find(">node N: a face of the cell graph's node N<"), std::string::npos);
  std::size_t labels = 0;
  for (std::size_t at = picture.find(">node "); at != std::string::npos; at = picture.find(">node ", at + 1)) ++labels;
  EXPECT_EQ(labels, 3u);  // and the legend's
  // The caged robot's cell and the outside both have boundary pieces drawn.
  EXPECT_NE(picture.find("stroke=\"#1f77b4\""), std::string::npos);
  EXPECT_NE(picture.find("stroke=\"#ff7f0e\""), std::string::npos);
  EXPECT_NE(picture.find("<polygon"), std::string::npos);
  const CommandResult second = runFreespace(command);
  EXPECT_EQ(second.status, 2);
  EXPECT_EQ(second.err, "error: " + svg + ": already exists (not overwritten)\n");
  EXPECT_EQ(readWholeFile(svg), picture);
}

// The graph as JSON: edges join nodes of one cell, every cell has a node, and the
// keyhole's start and goal (the bar along the wall, theta 0, on either side of it)
// lie in two nodes whose angles hold 0.
TEST(CliFreeSpace, GraphPrintsNodesAndEdges) {
  const CommandResult result = runFreespace("graph --json --cfg '" + kProblems + "keyhole.cfg'");
  ASSERT_EQ(result.status, 0) << result.err;
  const nlohmann::json graph = nlohmann::json::parse(result.out);
  const nlohmann::json& nodes = graph["nodes"];
  std::set<int> cells;
  for (const nlohmann::json& node : nodes) cells.insert(node["cell"].get<int>());
  EXPECT_EQ(cells, (std::set<int>{0, 1}));
  for (const nlohmann::json& edge : graph["edges"]) {
    EXPECT_EQ(nodes[edge["from"].get<int>()]["cell"], nodes[edge["to"].get<int>()]["cell"]);
  }
  const std::vector<nlohmann::json> ends = batchAnswers("locate", "keyhole.cfg", "0 -2.25 0\n0 2.25 0\n");
  ASSERT_EQ(ends.size(), 2u);
  EXPECT_NE(ends[0]["node"], ends[1]["node"]);
  // The route from the start's node to the goal's: the bar must turn to pass the slot,
  // so it leaves the start's node (theta about 0) and comes back to theta about 0.
  const nlohmann::json& route = graph["problem"]["route"];
  ASSERT_TRUE(route.is_array());
  EXPECT_EQ(route.front(), ends[0]["node"]);
  EXPECT_EQ(route.back(), ends[1]["node"]);
  EXPECT_GE(route.size(), 3u);
  const CommandResult narrow = runFreespace("graph --cfg '" + kProblems + "keyhole_narrow.cfg'");
  ASSERT_EQ(narrow.status, 0) << narrow.err;
  EXPECT_NE(narrow.out.find("no route (they lie in different cells"), std::string::npos) << narrow.out;
  for (const nlohmann::json& end : ends) {
    const nlohmann::json& node = nodes[end["node"].get<int>()];
    ASSERT_FALSE(node["from"].is_null());
    EXPECT_LT(node["from"].get<double>(), 0);
    EXPECT_GT(node["to"].get<double>(), 0);
  }
}

// The keyhole at theta 0 has three faces (outside, and the bar lying along the wall on
// either side of it: the slot lets it through only end first); at a quarter turn the
// two sides are one face.
TEST(CliFreeSpace, SliceLabelsEveryFaceWithItsNode) {
  TempDir dir;
  for (const auto& [theta, faces] : {std::pair<std::string, std::size_t>{"0", 3}, {"1.5707963", 2}}) {
    const std::string svg = dir.file("keyhole" + theta + ".svg");
    const CommandResult result =
        runFreespace("slice --cfg '" + kProblems + "keyhole.cfg' --theta " + theta + " --resolution 60 --svg '" + svg +
                     "'");
    ASSERT_EQ(result.status, 0) << result.err;
    const std::string picture = readWholeFile(svg);
    std::set<std::string> labels;
    for (std::size_t at = picture.find(">node "); at != std::string::npos; at = picture.find(">node ", at + 1)) {
      labels.insert(picture.substr(at, picture.find('<', at) - at));
    }
    labels.erase(">node N: a face of the cell graph's node N");
    EXPECT_EQ(labels.size(), faces) << theta;
  }
}

TEST(CliFreeSpace, BuildRejectsEveryMalformedMeshNamingTheFile) {
  const std::string meshes = std::string(FREESPACE_TEST_DATA) + "/meshes/";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(meshes)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("bad_", 0) != 0) continue;
    const CommandResult result = runFreespace("build '" + meshes + "box.off' '" + entry.path().string() + "'");
    EXPECT_EQ(result.status, 2) << name << ": " << result.err;
    EXPECT_EQ(result.err.rfind("error: " + entry.path().string() + ": ", 0), 0u) << result.err;
    ++checked;
  }
  EXPECT_GE(checked, 15);
}

TEST(CliFreeSpace, CoincidentHeightsWithoutPerturbationAreAnError) {
  const CommandResult result = runFreespace("build --perturbation 0 --cfg '" + kProblems + "cage.cfg'");
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err.rfind("error: " + kProblems + "cage.cfg: ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find("same height"), std::string::npos) << result.err;
}

TEST(CliFreeSpace, ExportWritesAPlyMeshAndNeverOverwrites) {
  TempDir dir;
  const std::string ply = dir.file("keyhole.ply");
  const std::string command = "export --cfg '" + kProblems + "keyhole.cfg' --ply '" + ply + "'";
  const CommandResult first = runFreespace(command);
  ASSERT_EQ(first.status, 0) << first.err;
  const std::string mesh = readWholeFile(ply);
  EXPECT_EQ(mesh.rfind("ply\nformat ascii 1.0\n", 0), 0u);
  EXPECT_NE(mesh.find("end_header\n"), std::string::npos);
  const CommandResult second = runFreespace(command);
  EXPECT_EQ(second.status, 2);
  EXPECT_EQ(second.err, "error: " + ply + ": already exists (not overwritten)\n");
  EXPECT_EQ(readWholeFile(ply), mesh);
}

TEST(CliFreeSpace, LocateReadsASavedFreeSpace) {
  TempDir dir;
  const std::string saved = dir.file("keyhole_narrow.fspace");
  const CommandResult built = runFreespace("build --cfg '" + kProblems + "keyhole_narrow.cfg' --save '" + saved + "'");
  ASSERT_EQ(built.status, 0) << built.err;
  std::ofstream(dir.file("batch.txt")) << "0 -2.25 0\n0 2.25 0\n0.5 0.1 0.3\n";
  const std::string batch = " --batch '" + dir.file("batch.txt") + "' --json";
  const CommandResult fromFile = runFreespace("locate '" + saved + "'" + batch);
  ASSERT_EQ(fromFile.status, 0) << fromFile.err;
  const CommandResult fromScene = runFreespace("locate --cfg '" + kProblems + "keyhole_narrow.cfg'" + batch);
  ASSERT_EQ(fromScene.status, 0) << fromScene.err;
  EXPECT_EQ(fromFile.out, fromScene.out);
  const CommandResult again = runFreespace("build --cfg '" + kProblems + "keyhole_narrow.cfg' --save '" + saved + "'");
  EXPECT_EQ(again.status, 2);
  EXPECT_EQ(again.err, "error: " + saved + ": already exists (not overwritten)\n");
}

// plan: a solved problem's JSON (the keys the issue names), its path file read back
// equal to the waypoints; an infeasible one exits 0 with its proof; bad starts, and
// a saved space of other meshes, exit 2 naming them.
TEST(CliFreeSpace, PlanPrintsThePathAndItsBoundsAndWritesThePathFile) {
  TempDir dir;
  const std::string pathFile = dir.file("flip.path");
  const CommandResult result =
      runFreespace("plan --json --cfg '" + kProblems + "flip_window.cfg' --path-out '" + pathFile + "'");
  ASSERT_EQ(result.status, 0) << result.err;
  const nlohmann::json plan = nlohmann::json::parse(result.out);
  EXPECT_EQ(plan["status"], "solved");
  for (const char* key : {"clearance_lower", "clearance_upper", "length", "waypoints", "seconds"}) {
    EXPECT_TRUE(plan.contains(key)) << key;
  }
  EXPECT_GE(plan["clearance_lower"].get<double>(), 0.98 * plan["clearance_upper"].get<double>());
  std::ifstream in(pathFile);
  std::size_t lines = 0;
  for (double x, y, theta; in >> x >> y >> theta; ++lines) {
    ASSERT_LT(lines, plan["waypoints"].size());
    EXPECT_EQ(x, plan["waypoints"][lines][0].get<double>());
    EXPECT_EQ(theta, plan["waypoints"][lines][2].get<double>());
  }
  EXPECT_EQ(lines, plan["waypoints"].size());
  const CommandResult again =
      runFreespace("plan --cfg '" + kProblems + "flip_window.cfg' --path-out '" + pathFile + "'");
  EXPECT_EQ(again.status, 2);
  EXPECT_EQ(again.err, "error: " + pathFile + ": already exists (not overwritten)\n");
}

// plan --svg: a picture with its title, the path's line, the robot's outlines along
// it (coloured, so several fills), the legend and axes; never overwritten without --force.
TEST(CliFreeSpace, PlanDrawsThePath) {
  TempDir dir;
  const std::string svg = dir.file("overhang.svg");
  const std::string command =
      "plan --cfg '" + kProblems + "overhang.cfg' --seconds-limit 0.5 --svg '" + svg + "'";
  const CommandResult result = runFreespace(command);
  ASSERT_EQ(result.status, 0) << result.err;
  const std::string picture = readWholeFile(svg);
  EXPECT_EQ(picture.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(picture.find("<title>Path: clearance "), std::string::npos);
  EXPECT_NE(picture.find("<polyline fill=\"none\""), std::string::npos);
  EXPECT_NE(picture.find("the robot along it, by clearance:"), std::string::npos);
  EXPECT_NE(picture.find("x (the meshes' units)"), std::string::npos);
  std::set<std::string> fills;
  for (std::size_t at = picture.find("<g fill=\"#"); at != std::string::npos; at = picture.find("<g fill=\"#", at + 1)) {
    fills.insert(picture.substr(at + 9, 7));
  }
  EXPECT_GE(fills.size(), 5u);  // footprint (2), start, goal and outlines of several clearances
  EXPECT_EQ(picture.substr(picture.size() - 7), "</svg>\n");
  const CommandResult again = runFreespace(command);
  EXPECT_EQ(again.status, 2);
  EXPECT_EQ(readWholeFile(svg), picture);
}

TEST(CliFreeSpace, PlanProvesInfeasibilityAndRefusesBadInput) {
  const CommandResult infeasible = runFreespace("plan --cfg '" + kProblems + "keyhole_narrow.cfg'");
  EXPECT_EQ(infeasible.status, 0) << infeasible.err;
  EXPECT_EQ(infeasible.out.rfind("infeasible: the start lies in free cell ", 0), 0u) << infeasible.out;
  const std::string meshes = "'" + kProblems + "flip_window_robot.obj' '" + kProblems + "flip_window_world.obj'";
  const CommandResult blocked = runFreespace("plan " + meshes + " --start 0 0 1.5707963 --goal 0 0 3.0790926535897931");
  EXPECT_EQ(blocked.status, 2);
  EXPECT_EQ(blocked.err.rfind("error: --start: the robot at (0, 0, 1.5707963", 0), 0u) << blocked.err;
  const CommandResult noGoal = runFreespace("plan " + meshes + " --start 0 0 3");
  EXPECT_EQ(noGoal.status, 2);
  const CommandResult outside = runFreespace("plan --cfg '" + kProblems + "flip_window.cfg' --goal 50 0 3");
  EXPECT_EQ(outside.status, 2);
  EXPECT_NE(outside.err.find("--goal: (50, 0, 3) lies outside the volume"), std::string::npos) << outside.err;
  const CommandResult notANumber = runFreespace("plan --cfg '" + kProblems + "flip_window.cfg' --goal nan 0 3");
  EXPECT_EQ(notANumber.status, 2);

  TempDir dir;
  const std::string saved = dir.file("keyhole_narrow.fspace");
  ASSERT_EQ(runFreespace("build --cfg '" + kProblems + "keyhole_narrow.cfg' --save '" + saved + "'").status, 0);
  const CommandResult other = runFreespace("plan --cfg '" + kProblems + "flip_window.cfg' --space '" + saved + "'");
  EXPECT_EQ(other.status, 2);
  EXPECT_EQ(other.err.rfind("error: " + saved + ": was built from another robot", 0), 0u) << other.err;
  const CommandResult same = runFreespace("plan --cfg '" + kProblems + "keyhole_narrow.cfg' --space '" + saved + "'");
  EXPECT_EQ(same.status, 0) << same.err;
  EXPECT_EQ(same.out.rfind("infeasible", 0), 0u);
}
