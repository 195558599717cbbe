// Loading a problem's meshes (the .cfg itself is read in planar_problem.cpp).
#include "freespace/problem/planar_problem.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <limits>

#include "freespace/io/mesh_reader.h"

namespace freespace {

namespace fs = std::filesystem;

namespace {

std::array<double, 2> heightsOf(const TriangleSoup& soup) {
  std::array<double, 2> heights{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const TriangleIndices& triangle : soup.triangles) {
    for (auto corner : triangle) {
      heights[0] = std::min(heights[0], soup.vertices[corner].z());
      heights[1] = std::max(heights[1], soup.vertices[corner].z());
    }
  }
  return heights;
}

// Triangles of one body that enclose nothing but lie beyond the other's heights can
// never touch it: each is prepared knowing the other's heights.
void prepareRobotAndWorld(const TriangleSoup& robot, const std::string& robotPath, const TriangleSoup& world,
                          const std::string& worldPath, const PreparationSettings& settings,
                          std::vector<std::string>* warnings, LoadedProblem& loaded) {
  PreparationSettings robotSettings = settings, worldSettings = settings;
  robotSettings.solid.otherBodyHeights = heightsOf(world);
  worldSettings.solid.otherBodyHeights = heightsOf(robot);
  loaded.robot = prepareMesh(robot, robotPath, robotSettings, &loaded.robotPreparation, warnings);
  loaded.world = prepareMesh(world, worldPath, worldSettings, &loaded.worldPreparation, warnings);
}

}  // namespace

LoadedProblem loadRobotAndWorld(const std::string& robotPath, const std::string& worldPath,
                                std::vector<std::string>* warnings, const PreparationSettings& settings) {
  LoadedProblem loaded;
  loaded.problem.robot = robotPath;
  loaded.problem.world = worldPath;
  prepareRobotAndWorld(readTriangleSoup(robotPath), robotPath, readTriangleSoup(worldPath), worldPath, settings,
                       warnings, loaded);
  return loaded;
}

LoadedProblem loadProblem(const std::string& cfgPath, std::vector<std::string>* warnings,
                          const PreparationSettings& settings) {
  LoadedProblem loaded;
  loaded.cfgPath = cfgPath;
  loaded.problem = readProblem(cfgPath, warnings);
  const fs::path folder = fs::path(cfgPath).parent_path();
  const std::string robotPath = (folder / loaded.problem.robot).string();
  const std::string worldPath = (folder / loaded.problem.world).string();

  // The centre comes from the vertices as imported, before any repair, or a state of
  // the .cfg would place the robot elsewhere than OMPL.app does.
  ImportedMesh robot = importMesh(robotPath);
  loaded.robotCentre = Point3(robot.vertexAverage.x(), robot.vertexAverage.y(), 0);
  for (Point3& vertex : robot.soup.vertices) vertex -= loaded.robotCentre;
  prepareRobotAndWorld(robot.soup, robotPath, readTriangleSoup(worldPath), worldPath, settings, warnings, loaded);
  return loaded;
}

}  // namespace freespace
