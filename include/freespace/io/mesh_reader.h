#pragma once

#include <string>
#include <vector>

#include "freespace/geometry/mesh.h"
#include "freespace/geometry/mesh_preparation.h"

namespace freespace {

/// A mesh file as read, before any checking or repair.
struct ImportedMesh {
  TriangleSoup soup;
  /// The average of every vertex the import returned, duplicates included: where
  /// OMPL.app puts a robot's centre (see importMesh).
  Point3 vertexAverage = Point3::Zero();
};

/// Reads the triangles of a mesh file without checking them. OBJ, STL, PLY, OFF and
/// COLLADA (.dae) go through assimp with OMPL.app's import flags (GenNormals,
/// Triangulate, JoinIdenticalVertices, SortByPType, OptimizeGraph) and every node
/// transform applied; positions and their average are computed in single precision
/// as OMPL.app computes them, so the soup holds OMPL.app's triangles and
/// vertexAverage is OMPL.app's robot centre to the bit. Legacy VTK POLYDATA ASCII
/// (.vtk) has its own reader (POINTS and POLYGONS, polygons triangulated as fans;
/// vertexAverage is the average of its points). Throws InputError naming the file
/// on any read error.
ImportedMesh importMesh(const std::string& path);

/// The triangles of importMesh.
TriangleSoup readTriangleSoup(const std::string& path);

/// The mesh a file shows: readTriangleSoup followed by prepareMesh (repair and solid
/// interpretation; every change is appended to `warnings`).
Mesh loadMesh(const std::string& path, std::vector<std::string>* warnings = nullptr,
              const PreparationSettings& settings = {}, PreparationReport* report = nullptr);

}  // namespace freespace
