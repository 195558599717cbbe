#pragma once

#include <cstdint>
#include <vector>

#include "freespace/scenes/scene_generator.h"

namespace freespace::detail {

/// One wall of a floor plan (a room's side) before it is built: its centre line
/// from grid node to grid node, its door (if any) and its height.
struct PlannedWall {
  Point2 from;
  Point2 to;
  std::vector<Opening> openings;  // none or the door
  double height = 0;
};

struct PlannedFloorPlan {
  std::vector<PlannedWall> walls;
  std::vector<Point2> roomCentres;  // in room order (row by row from the south-west)
};

/// The walls makeFloorPlan builds for the same layout and seed, each wall once:
/// doors along a random spanning tree plus loops, each wall's height the layout's
/// wallHeight or, when wallHeights has several, one of them at random.
PlannedFloorPlan planFloorPlan(const FloorPlanLayout& layout, std::uint64_t seed);

}  // namespace freespace::detail
