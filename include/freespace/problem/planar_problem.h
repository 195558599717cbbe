#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "freespace/geometry/mesh.h"
#include "freespace/geometry/mesh_preparation.h"

namespace freespace {

/// A configuration of the robot: translation (x, y) and rotation theta (radians)
/// about the robot's own vertical axis.
struct Pose2 {
  double x = 0;
  double y = 0;
  double theta = 0;
};

/// One "key = value" line of a .cfg section.
struct ConfigEntry {
  std::string key;
  std::string value;
  bool operator==(const ConfigEntry& other) const { return key == other.key && value == other.value; }
};

/// A planner of the [planner] section, as OMPL.app's benchmark reads it: a key
/// without a dot starts one ("rrtstar ="), and "rrtstar.<parameter> = value" lines
/// set parameters of the latest "rrtstar" (one is started if there is none yet), so a
/// planner type may appear several times with different parameters.
struct PlannerEntry {
  std::string type;
  std::vector<ConfigEntry> parameters;  // in file order ("name", "tree_pruning", ...)
  bool operator==(const PlannerEntry& other) const { return type == other.type && parameters == other.parameters; }
};

/// An OMPL.app planar problem (.cfg file). Mesh paths are stored as written in the
/// file (relative to the .cfg's folder) and resolved by loadProblem.
struct PlanarProblem {
  std::string name;
  std::string robot;
  std::string world;
  Pose2 start;
  Pose2 goal;
  std::optional<Eigen::AlignedBox2d> volume;  // volume.min.x/y, volume.max.x/y
  std::string objective;                       // optional
  std::optional<double> objectiveThreshold;    // objective.threshold
  double timeLimit = 10.0;                     // [benchmark] time_limit (s)
  double memLimit = 10000.0;                   // [benchmark] mem_limit (MB)
  unsigned runCount = 10;                      // [benchmark] run_count
  /// The other [benchmark] lines (output, save_paths, ...), in file order.
  std::vector<ConfigEntry> benchmarkSettings;
  std::vector<PlannerEntry> planners;          // in file order
};

/// Reads a .cfg with OMPL.app's parser (Boost.Program_options' configuration file
/// syntax: "key = value" lines under "[section]" headers, '#' comments). Missing
/// required keys (robot, world, start.x/y/theta, goal.x/y/theta), a key repeated in
/// [problem] and malformed values are InputError; unknown sections and keys (such as
/// OMPL.app's keys for other kinds of robots) are appended to `warnings`. In
/// [benchmark] a repeated key takes its last value.
PlanarProblem readProblem(const std::string& cfgPath, std::vector<std::string>* warnings = nullptr);

/// Writes a .cfg that readProblem (and OMPL.app) reads back. Refuses to overwrite an
/// existing file unless `overwrite` is set.
void writeProblem(const PlanarProblem& problem, const std::string& cfgPath, bool overwrite = false);

/// A problem with its meshes loaded. As in OMPL.app, the robot is re-centred at the
/// average of the vertices the import returned (ImportedMesh::vertexAverage, before
/// any repair) with the centre's z set to 0: centre = (mean x, mean y, 0) is
/// subtracted, so the robot turns about the vertical line through that average and
/// its heights are unchanged.
struct LoadedProblem {
  PlanarProblem problem;
  std::string cfgPath;
  Mesh robot;
  Mesh world;
  Point3 robotCentre = Point3::Zero();  // subtracted from the robot's vertices
  PreparationReport robotPreparation;   // what repair and interpretation changed
  PreparationReport worldPreparation;
};

/// Loads a robot and a world from mesh files (loadMesh, with `settings`), each
/// prepared knowing the heights the other's triangles span
/// (SolidSettings::otherBodyHeights); warnings and every change made to the meshes
/// are appended to `warnings`. The problem holds the two paths only.
LoadedProblem loadRobotAndWorld(const std::string& robotPath, const std::string& worldPath,
                                std::vector<std::string>* warnings = nullptr, const PreparationSettings& settings = {});

/// Reads the .cfg and loads its meshes as loadRobotAndWorld does, the robot placed
/// as OMPL.app places it (see LoadedProblem).
LoadedProblem loadProblem(const std::string& cfgPath, std::vector<std::string>* warnings = nullptr,
                          const PreparationSettings& settings = {});

}  // namespace freespace
