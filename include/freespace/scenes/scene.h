#pragma once

#include <optional>
#include <string>
#include <vector>

#include "freespace/geometry/mesh.h"
#include "freespace/problem/planar_problem.h"

namespace freespace {

/// A generated test scene: robot and environment meshes and a planar problem on them.
/// `expectSolvable` records what the scene was designed for (a path exists or not);
/// it is a design intent checked by later planners, not an output of the code.
///
/// A scene may be written as raw triangle soups (imitations of modelling tools'
/// files, see soup_variants.h): then `robot` and `world` hold the solids the soups
/// are meant to show, as checked meshes of closed, outward components (which may
/// overlap), the oracle for the loader that turns the soups into solids.
struct Scene {
  std::string name;
  Mesh robot;
  Mesh world;
  std::optional<TriangleSoup> robotSoup;  // written instead of `robot` when present
  std::optional<TriangleSoup> worldSoup;  // written instead of `world` when present
  PlanarProblem problem;                  // robot/world fields hold the file names the scene writes
  bool expectSolvable = true;
  std::string description;
};

/// The triangles writeScene writes for one of a scene's meshes: its soup when it has
/// one, else the mesh's own.
inline TriangleSoup writtenSoup(const Mesh& mesh, const std::optional<TriangleSoup>& soup) {
  return soup ? *soup : TriangleSoup{mesh.vertices(), mesh.triangles()};
}

}  // namespace freespace
