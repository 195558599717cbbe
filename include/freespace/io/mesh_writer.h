#pragma once

#include <string>

#include "freespace/geometry/mesh.h"

namespace freespace {

/// Writes a mesh; the format follows the extension: .obj, .stl, .ply, .off and .dae
/// (COLLADA) through assimp's exporters, .vtk (legacy POLYDATA ASCII) by the project's
/// own writer. Refuses (InputError) to overwrite an existing file unless `overwrite`.
void writeMesh(const Mesh& mesh, const std::string& path, bool overwrite = false);

}  // namespace freespace
