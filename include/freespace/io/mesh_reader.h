#pragma once

#include <string>
#include <vector>

#include "freespace/geometry/mesh.h"

namespace freespace {

/// Reads the triangles of a mesh file without checking them. OBJ, STL, PLY, OFF and
/// COLLADA (.dae) go through assimp with every node transform applied; legacy VTK
/// POLYDATA ASCII (.vtk) has its own reader (POINTS and POLYGONS, polygons
/// triangulated as fans). Throws InputError naming the file on any read error.
TriangleSoup readTriangleSoup(const std::string& path);

/// readTriangleSoup followed by Mesh::fromSoup.
Mesh loadMesh(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace freespace
