#pragma once

#include <array>
#include <optional>
#include <vector>

#include "freespace/topology/slice_faces.h"

namespace freespace {

/// A path of straight translations inside one face of a slice (sliceFaces), from
/// `from` to `to`: through the constrained Delaunay triangulation of the face's loops,
/// from triangle to triangle across edges that are not on its boundary, by the middles
/// of the edges crossed. Points are in the face's (the construction's) coordinates.
/// None when an end lies outside the face or on its boundary, or no chain of triangles
/// joins them. The face's corners are rounded: certify the motions (MotionChecker).
std::optional<std::vector<std::array<double, 2>>> pathInFace(const SliceFace& face, const std::array<double, 2>& from,
                                                             const std::array<double, 2>& to);

}  // namespace freespace
