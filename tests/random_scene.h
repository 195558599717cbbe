#pragma once

// Random tetrahedra scenes for property tests (RapidCheck): coordinates on a grid of
// 1e-6, the robot reaching past the environment's heights so that VF, FV and EE
// contacts all occur.

#include <rapidcheck.h>

#include <memory>
#include <optional>

#include "freespace/geometry/mesh_topology.h"
#include "freespace/geometry/patch.h"
#include "freespace/geometry/patch_geometry.h"
#include "freespace/geometry/patch_segment.h"
#include "freespace/input_error.h"
#include "freespace/numbers/algebraic_angle.h"
#include "test_meshes.h"

namespace freespace::testing {

inline Point3 randomPoint(double zLow, double zHigh) {
  const auto coordinate = [](double low, double high) {
    return low + (high - low) * *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 1000001)) / 1e6;
  };
  return {coordinate(-1, 1), coordinate(-1, 1), coordinate(zLow, zHigh)};
}

inline std::optional<Mesh> randomTetrahedron(double zLow, double zHigh) {
  try {
    return tetrahedronMesh(randomPoint(zLow, zHigh), randomPoint(zLow, zHigh), randomPoint(zLow, zHigh),
                           randomPoint(zLow, zHigh));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// Random tetrahedra as robot and environment, the robot reaching past the
/// environment's heights so that VF, FV and EE contacts all occur, with their
/// topology.
struct RandomScene {
  RandomScene(Mesh robotMesh, Mesh worldMesh)
      : robot(std::move(robotMesh)),
        world(std::move(worldMesh)),
        robotTopology(robot, statistics),
        worldTopology(world, statistics),
        algebra(statistics) {}

  /// The general position the construction needs (requireDistinctHeights).
  bool hasDistinctHeights() const {
    try {
      requireDistinctHeights(robot, world, "random scene");
      return true;
    } catch (const InputError&) {
      return false;
    }
  }

  /// Every VF, FV and EE patch.
  std::vector<Patch> allPatches() {
    std::vector<Patch> patches = vertexFacetPatches(robot, robotTopology, world, worldTopology, algebra);
    const std::vector<Patch> edgePatches = edgeEdgePatches(robot, robotTopology, world, worldTopology, algebra);
    patches.insert(patches.end(), edgePatches.begin(), edgePatches.end());
    return patches;
  }

  /// Every patch with its segment and input points.
  std::vector<PatchGeometry> allPatchGeometries() {
    return patchGeometries(allPatches(), robot, robotTopology, world, worldTopology, statistics);
  }

  Mesh robot;
  Mesh world;
  PredicateStatistics statistics;
  MeshTopology robotTopology;
  MeshTopology worldTopology;
  AngleAlgebra algebra;
};

inline std::unique_ptr<RandomScene> randomScene() {
  std::optional<Mesh> robot = randomTetrahedron(0.1, 1.2);
  std::optional<Mesh> world = randomTetrahedron(0.0, 1.0);
  RC_PRE(robot.has_value() && world.has_value());
  return std::make_unique<RandomScene>(std::move(*robot), std::move(*world));
}

/// Random tetrahedra moved by the given offsets in (x, y), as one mesh of several
/// components (apart when the offsets are at least 2.1 apart).
inline Mesh randomTetrahedraAt(const std::vector<std::array<double, 2>>& offsets, double zLow, double zHigh) {
  std::vector<TriangleSoup> parts;
  for (const auto& [dx, dy] : offsets) {
    const std::optional<Mesh> part = randomTetrahedron(zLow, zHigh);
    RC_PRE(part.has_value());
    TriangleSoup soup{{}, part->triangles()};
    for (const Point3& v : part->vertices()) soup.vertices.push_back(v + Point3(dx, dy, 0));
    parts.push_back(std::move(soup));
  }
  return Mesh::fromSoup(joinSoups(parts), "random tetrahedra");
}

/// A robot of random tetrahedra among random obstacle tetrahedra, at the given
/// offsets, so that the robot can touch several obstacles at once.
inline std::unique_ptr<RandomScene> randomSceneAmong(const std::vector<std::array<double, 2>>& robotOffsets,
                                                     const std::vector<std::array<double, 2>>& worldOffsets) {
  Mesh robot = randomTetrahedraAt(robotOffsets, 0.1, 1.2);
  Mesh world = randomTetrahedraAt(worldOffsets, 0.0, 1.0);
  return std::make_unique<RandomScene>(std::move(robot), std::move(world));
}

/// A random robot tetrahedron between two random obstacle tetrahedra, so that the
/// robot can touch both at once and patches cross.
inline std::unique_ptr<RandomScene> randomTwoObstacleScene() {
  return randomSceneAmong({{0, 0}}, {{-1.1, 0}, {1.1, 0}});
}

/// A robot of two random tetrahedra among four random obstacle tetrahedra, so that
/// it can touch three features at once and patch curves meet at vertices.
inline std::unique_ptr<RandomScene> randomCrowdedScene() {
  return randomSceneAmong({{0, -1.05}, {0, 1.05}}, {{-2.1, -1.05}, {2.1, -1.05}, {-2.1, 1.05}, {2.1, 1.05}});
}

}  // namespace freespace::testing
