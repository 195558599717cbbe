// The exported boundary mesh against FCL: every vertex of the PLY lies on the
// boundary of free space, so FCL (an independent collision library) finds the robot
// there touching the environment (distance about zero); the faces index existing
// vertices and both of the cage's cells have boundary.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/exports/boundary_ply.h"
#include "freespace/problem/planar_problem.h"

using namespace freespace;

TEST(BoundaryPly, VerticesLieOnTheFreeSpaceBoundary) {
  const LoadedProblem problem = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/cage.cfg");
  const FreeSpace space(problem.robot, problem.world);
  std::stringstream ply;
  writeBoundaryPly(space, {}, ply);
  std::string line, reachWord;
  std::size_t vertexCount = 0, faceCount = 0;
  double reach = 0;
  while (std::getline(ply, line) && line != "end_header") {
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    if (first == "element" && second == "vertex") words >> vertexCount;
    if (first == "element" && second == "face") words >> faceCount;
    if (first == "comment") reach = std::stod(line.substr(line.rfind(' ') + 1));
  }
  ASSERT_GT(vertexCount, 0u);
  ASSERT_GT(faceCount, 0u);
  ASSERT_GT(reach, 0);
  const FclCollisionChecker fcl(space.meshes().robot, space.meshes().world);
  std::set<std::string> colours;
  double worst = 0;
  for (std::size_t i = 0; i < vertexCount; ++i) {
    double x, y, z;
    int red, green, blue;
    ply >> x >> y >> z >> red >> green >> blue;
    colours.insert(std::to_string(red) + "," + std::to_string(green) + "," + std::to_string(blue));
    if (i % 37 != 0) continue;
    const double scale = space.meshes().scale;  // the PLY is in the input's coordinates
    const Pose2 pose{x * scale, y * scale, z / reach};
    if (!fcl.inCollision(pose)) worst = std::max(worst, fcl.distance(pose));
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_EQ(colours.size(), 2u);
  for (std::size_t i = 0; i < faceCount; ++i) {
    std::size_t corners, a, b, c;
    ply >> corners >> a >> b >> c;
    ASSERT_EQ(corners, 3u);
    ASSERT_LT(std::max({a, b, c}), vertexCount);
  }
}

// A scene of 1e-30 is exported in its own units: the theta axis is scaled by the
// robot's reach as at ordinary size (not by a floor on it).
TEST(BoundaryPly, ATinySceneKeepsItsReach) {
  const LoadedProblem problem = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/cage.cfg");
  const auto reachOf = [&](double factor) {
    TriangleSoup robot{{}, problem.robot.triangles()}, world{{}, problem.world.triangles()};
    for (const Point3& p : problem.robot.vertices()) robot.vertices.push_back(p * factor);
    for (const Point3& p : problem.world.vertices()) world.vertices.push_back(p * factor);
    const FreeSpace space(Mesh::fromSoup(robot, "robot"), Mesh::fromSoup(world, "world"));
    std::stringstream ply;
    writeBoundaryPly(space, {}, ply);
    std::string line;
    while (std::getline(ply, line) && line.rfind("comment", 0) != 0) {
    }
    return std::stod(line.substr(line.rfind(' ') + 1));
  };
  const double tiny = std::ldexp(1.0, -100);
  EXPECT_NEAR(reachOf(tiny) / tiny, reachOf(1), 1e-9 * reachOf(1));
}
