#pragma once

#include <string>

#include "freespace/geometry/mesh.h"

namespace freespace {

/// Reads the triangles of a legacy VTK file (ASCII, DATASET POLYDATA) from its
/// `content`; `path` only names the file in errors. POLYGONS are triangulated as
/// fans and TRIANGLE_STRIPS split into triangles, in both the classic cell layout
/// ("k i0 ... ik-1" records) and the OFFSETS/CONNECTIVITY layout of version 5;
/// VERTICES, LINES, FIELD and METADATA blocks are skipped, and reading stops at
/// POINT_DATA or CELL_DATA (only attributes follow). Errors (InputError) give the
/// line number where they can.
TriangleSoup readLegacyVtk(const std::string& path, const std::string& content);

}  // namespace freespace
