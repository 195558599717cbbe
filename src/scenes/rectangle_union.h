#pragma once

#include <vector>

#include "freespace/scenes/scene_generator.h"

namespace freespace::detail {

/// The union of axis-aligned rectangles as polygonal regions: one per connected
/// piece, outer outline counter-clockwise, holes clockwise, corners only where the
/// outline turns. Rectangles of zero area are ignored. Throws std::invalid_argument
/// when two pieces touch at a single corner (the union would not be a manifold).
std::vector<PolygonWithHoles> rectangleUnionRegions(const std::vector<Box2>& rectangles);

}  // namespace freespace::detail
