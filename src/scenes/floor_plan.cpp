// Multi-room floor plans: square rooms on a grid, joined by doors along a random
// spanning tree (so every room can be reached) plus a few loops.

#include <cmath>
#include <map>
#include <stdexcept>

#include "floor_plan_walls.h"
#include "freespace/scenes/scene_generator.h"
#include "seeded_random.h"

namespace freespace {
namespace {

constexpr double kDoorPositionStep = 1.0 / 16;

/// A wall between two rooms, or between a room and the outside (second room -1).
struct WallSegment {
  Point2 from;
  Point2 to;
  int room = -1;
  int neighbour = -1;
  bool hasDoor = false;
};

class RoomGrid {
 public:
  explicit RoomGrid(const FloorPlanLayout& layout) : layout_(layout) {}

  int roomAt(int column, int row) const {
    if (column < 0 || row < 0 || column >= static_cast<int>(layout_.columns)) return -1;
    const int room = row * static_cast<int>(layout_.columns) + column;
    return room < static_cast<int>(layout_.rooms) ? room : -1;
  }

  Point2 corner(int column, int row) const { return {column * layout_.cellSize, row * layout_.cellSize}; }

  Point2 centre(int room) const { return corner(column(room), row(room)) + Point2::Constant(layout_.cellSize / 2); }

  /// Every wall once: the south and west walls of each room, and its north and east
  /// walls where no room lies beyond them.
  std::vector<WallSegment> walls() const {
    std::vector<WallSegment> walls;
    for (int room = 0; room < static_cast<int>(layout_.rooms); ++room) {
      const int c = column(room);
      const int r = row(room);
      walls.push_back({corner(c, r), corner(c + 1, r), room, roomAt(c, r - 1)});
      walls.push_back({corner(c, r), corner(c, r + 1), room, roomAt(c - 1, r)});
      if (roomAt(c, r + 1) < 0) walls.push_back({corner(c, r + 1), corner(c + 1, r + 1), room, -1});
      if (roomAt(c + 1, r) < 0) walls.push_back({corner(c + 1, r), corner(c + 1, r + 1), room, -1});
    }
    return walls;
  }

 private:
  int column(int room) const { return room % static_cast<int>(layout_.columns); }
  int row(int room) const { return room / static_cast<int>(layout_.columns); }

  const FloorPlanLayout& layout_;
};

/// Randomised depth-first search from room 0: a door in every wall it crosses.
void addSpanningTreeDoors(std::vector<WallSegment>& walls, unsigned rooms, detail::SeededRandom& random) {
  std::vector<bool> visited(rooms, false);
  std::vector<int> stack{0};
  visited[0] = true;
  while (!stack.empty()) {
    const int room = stack.back();
    std::vector<std::size_t> ways;  // walls from `room` to an unvisited room
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const WallSegment& wall = walls[w];
      if (wall.neighbour < 0) continue;
      const int other = wall.room == room ? wall.neighbour : wall.neighbour == room ? wall.room : -1;
      if (other >= 0 && !visited[static_cast<std::size_t>(other)]) ways.push_back(w);
    }
    if (ways.empty()) {
      stack.pop_back();
      continue;
    }
    WallSegment& wall =
        walls[ways[static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(ways.size()) - 1))]];
    wall.hasDoor = true;
    const int next = wall.room == room ? wall.neighbour : wall.room;
    visited[static_cast<std::size_t>(next)] = true;
    stack.push_back(next);
  }
}

void addExtraDoors(std::vector<WallSegment>& walls, unsigned count, detail::SeededRandom& random) {
  std::vector<std::size_t> candidates;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (walls[w].neighbour >= 0 && !walls[w].hasDoor) candidates.push_back(w);
  }
  for (unsigned k = 0; k < count && !candidates.empty(); ++k) {
    const auto pick = static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(candidates.size()) - 1));
    walls[candidates[pick]].hasDoor = true;
    candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(pick));
  }
}

/// A door of the layout's width near the middle of the wall: it is moved by at most
/// a quarter of the free wall length beside it, so a robot can line up with it.
Opening doorOpening(const WallSegment& wall, const FloorPlanLayout& layout, detail::SeededRandom& random) {
  const int along = wall.from.y() == wall.to.y() ? 0 : 1;
  const double middle = (wall.from[along] + wall.to[along]) / 2;
  const double freeLength = layout.cellSize - layout.wallThickness - layout.doorWidth;
  const double maxShift = std::floor(freeLength / 4 / kDoorPositionStep) * kDoorPositionStep;
  const double centre = middle + random.onGrid(-maxShift, maxShift, kDoorPositionStep);
  return {centre - layout.doorWidth / 2, centre + layout.doorWidth / 2};
}

double randomHeight(const std::vector<double>& heights, detail::SeededRandom& random) {
  return heights[static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(heights.size()) - 1))];
}

/// Every wall with its door cut out, one union extruded to one height.
TriangleSoup wallsOfOneHeight(const std::vector<detail::PlannedWall>& walls, const FloorPlanLayout& layout) {
  std::vector<Box2> rectangles;
  for (const detail::PlannedWall& wall : walls) {
    const std::vector<Box2> pieces = wallRectangles(wall.from, wall.to, layout.wallThickness, wall.openings);
    rectangles.insert(rectangles.end(), pieces.begin(), pieces.end());
  }
  return extrudeRectangleUnion(rectangles, 0, layout.wallHeight);
}

/// Each wall at its own height, between square posts at the grid's nodes, each
/// post as high as the highest wall it holds. Walls reach one grid step into the
/// posts, so the solids overlap without sharing an edge.
TriangleSoup wallsOfSeveralHeights(const std::vector<detail::PlannedWall>& walls, const FloorPlanLayout& layout) {
  const double thickness = layout.wallThickness;
  std::map<std::pair<double, double>, double> posts;  // node -> height
  std::vector<TriangleSoup> parts;
  for (const detail::PlannedWall& wall : walls) {
    const Point2 direction = (wall.to - wall.from).normalized();
    // wallRectangles adds half the thickness past both ends.
    const double inset = thickness - kSceneGrid;
    const std::vector<Box2> pieces =
        wallRectangles(wall.from + inset * direction, wall.to - inset * direction, thickness, wall.openings);
    parts.push_back(extrudeRectangleUnion(pieces, 0, wall.height));
    for (const Point2& node : {wall.from, wall.to}) {
      double& post = posts[{node.x(), node.y()}];
      post = std::max(post, wall.height);
    }
  }
  for (const auto& [node, height] : posts) {
    const Point3 corner(node.first - thickness / 2, node.second - thickness / 2, 0);
    parts.push_back(makeBox(Box3(corner, corner + Point3(thickness, thickness, height))));
  }
  return joinParts(parts);
}

}  // namespace

namespace detail {

PlannedFloorPlan planFloorPlan(const FloorPlanLayout& layout, std::uint64_t seed) {
  if (layout.rooms == 0 || layout.columns == 0 ||
      !(layout.doorWidth > 0 && layout.doorWidth + layout.wallThickness < layout.cellSize)) {
    throw std::invalid_argument("floor plan: needs rooms, columns, and doors narrower than a room");
  }
  SeededRandom random(seed);
  const RoomGrid grid(layout);
  std::vector<WallSegment> walls = grid.walls();
  addSpanningTreeDoors(walls, layout.rooms, random);
  addExtraDoors(walls, layout.extraDoors, random);

  PlannedFloorPlan plan;
  for (const WallSegment& wall : walls) {
    PlannedWall& planned = plan.walls.emplace_back();
    planned.from = wall.from;
    planned.to = wall.to;
    if (wall.hasDoor) planned.openings.push_back(doorOpening(wall, layout, random));
    planned.height = layout.wallHeights.size() > 1 ? randomHeight(layout.wallHeights, random) : layout.wallHeight;
  }
  for (unsigned room = 0; room < layout.rooms; ++room) plan.roomCentres.push_back(grid.centre(static_cast<int>(room)));
  return plan;
}

}  // namespace detail

FloorPlan makeFloorPlan(const FloorPlanLayout& layout, std::uint64_t seed) {
  detail::PlannedFloorPlan plan = detail::planFloorPlan(layout, seed);
  const TriangleSoup walls =
      layout.wallHeights.size() > 1 ? wallsOfSeveralHeights(plan.walls, layout) : wallsOfOneHeight(plan.walls, layout);
  return {walls, std::move(plan.roomCentres)};
}

}  // namespace freespace
