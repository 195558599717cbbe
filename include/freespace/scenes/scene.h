#pragma once

#include <string>
#include <vector>

#include "freespace/geometry/mesh.h"
#include "freespace/problem/planar_problem.h"

namespace freespace {

/// A generated test scene: robot and environment meshes and a planar problem on them.
/// `expectSolvable` records what the scene was designed for (a path exists or not);
/// it is a design intent checked by later planners, not an output of the code.
struct Scene {
  std::string name;
  Mesh robot;
  Mesh world;
  PlanarProblem problem;  // robot/world fields hold the file names the scene writes
  bool expectSolvable = true;
  std::string description;
};

}  // namespace freespace
