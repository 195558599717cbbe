#pragma once

#include <vector>

#include "freespace/scenes/scene_generator.h"

namespace freespace::detail {

/// Twice the signed area of a polygon (positive when counter-clockwise).
double twiceSignedArea(const Polygon2& polygon);

/// The polygon with its corners in counter-clockwise (or clockwise) order.
Polygon2 counterClockwise(Polygon2 polygon);
Polygon2 clockwise(Polygon2 polygon);

/// Triangulates a region given by a counter-clockwise outer polygon and clockwise
/// holes. Triangles are counter-clockwise and index the concatenation of the outer
/// polygon's corners followed by each hole's corners; no new vertex is added.
/// Holes are joined to the outer boundary by bridge edges, then ears are clipped.
/// Throws std::logic_error when the input is not a valid region.
std::vector<TriangleIndices> triangulateRegion(const Polygon2& outer, const std::vector<Polygon2>& holes);

}  // namespace freespace::detail
