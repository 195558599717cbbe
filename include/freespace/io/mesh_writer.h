#pragma once

#include <string>

#include "freespace/geometry/mesh.h"

namespace freespace {

/// Writes triangles exactly as given: duplicate and reversed triangles, shared or
/// repeated vertices, open or crossing surfaces (test data for the loader's repairs).
/// The format follows the extension: .obj, .stl, .ply and .dae (COLLADA) through
/// assimp's exporters, which store coordinates as floats; .off and .vtk (legacy
/// POLYDATA ASCII) by the project's own writers, as exact doubles. Checks
/// only that coordinates are finite and indices in range (InputError otherwise).
/// Refuses (InputError) to overwrite an existing file unless `overwrite`.
void writeSoup(const TriangleSoup& soup, const std::string& path, bool overwrite = false);

/// writeSoup of the mesh's vertices and triangles.
void writeMesh(const Mesh& mesh, const std::string& path, bool overwrite = false);

}  // namespace freespace
