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
/// COLLADA (.dae) go through assimp (Triangulate and SortByPType; vertices are welded
/// by the repair, not the import) with every node transform applied, positions in
/// single precision as OMPL.app computes them; vertexAverage comes from a second
/// import with OMPL.app's flags (GenNormals, Triangulate, JoinIdenticalVertices,
/// SortByPType, OptimizeGraph), averaged as OMPL.app averages, so that it is OMPL.app's
/// robot centre to the bit. Legacy VTK POLYDATA ASCII (.vtk) has its own reader
/// (POINTS and POLYGONS, polygons triangulated as fans; vertexAverage is the average
/// of its points). Throws InputError naming the file on any read error.
ImportedMesh importMesh(const std::string& path);

/// The triangles of importMesh (one import: no centre).
TriangleSoup readTriangleSoup(const std::string& path);

/// The mesh a file shows: readTriangleSoup followed by prepareMesh (repair and solid
/// interpretation; every change is appended to `warnings`).
Mesh loadMesh(const std::string& path, std::vector<std::string>* warnings = nullptr,
              const PreparationSettings& settings = {}, PreparationReport* report = nullptr);

}  // namespace freespace
