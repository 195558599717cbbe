// Axis-aligned walls, rooms and tables.

#include <algorithm>
#include <stdexcept>

#include "freespace/scenes/scene_generator.h"

namespace freespace {

std::vector<Box2> wallRectangles(const Point2& from, const Point2& to, double thickness,
                                 const std::vector<Opening>& openings) {
  if (from == to || (from.x() != to.x() && from.y() != to.y())) {
    throw std::invalid_argument("wall: the centre line must be a non-empty axis-aligned segment");
  }
  // Work in (along, across) coordinates: along is x for a wall parallel to x.
  const int along = from.y() == to.y() ? 0 : 1;
  const int across = 1 - along;
  const double half = thickness / 2;
  const double start = std::min(from[along], to[along]) - half;
  const double end = std::max(from[along], to[along]) + half;

  std::vector<Opening> sorted = openings;
  std::sort(sorted.begin(), sorted.end(), [](const Opening& a, const Opening& b) { return a.from < b.from; });
  std::vector<Box2> rectangles;
  auto addPiece = [&](double pieceFrom, double pieceTo) {
    if (pieceTo <= pieceFrom) return;
    Point2 low, high;
    low[along] = pieceFrom;
    high[along] = pieceTo;
    low[across] = from[across] - half;
    high[across] = from[across] + half;
    rectangles.emplace_back(low, high);
  };
  double pieceStart = start;
  for (const Opening& opening : sorted) {
    if (!(opening.from < opening.to) || opening.from < start || opening.to > end) {
      throw std::invalid_argument("wall: an opening must be a non-empty interval within the wall");
    }
    addPiece(pieceStart, opening.from);
    pieceStart = std::max(pieceStart, opening.to);
  }
  addPiece(pieceStart, end);
  return rectangles;
}

std::vector<Box2> roomWallRectangles(const Box2& interior, double thickness, const std::vector<Door>& doors) {
  const double half = thickness / 2;
  const Point2 low = interior.min() - Point2(half, half);  // corners of the walls' centre lines
  const Point2 high = interior.max() + Point2(half, half);
  auto openingsOn = [&](Side side) {
    std::vector<Opening> openings;
    for (const Door& door : doors) {
      if (door.side == side) openings.push_back(door.opening);
    }
    return openings;
  };
  std::vector<Box2> rectangles;
  auto addWall = [&](const Point2& from, const Point2& to, Side side) {
    const std::vector<Box2> wall = wallRectangles(from, to, thickness, openingsOn(side));
    rectangles.insert(rectangles.end(), wall.begin(), wall.end());
  };
  addWall(low, {low.x(), high.y()}, Side::west);
  addWall({high.x(), low.y()}, high, Side::east);
  addWall(low, {high.x(), low.y()}, Side::south);
  addWall({low.x(), high.y()}, high, Side::north);
  return rectangles;
}

TriangleSoup makeTable(const Box2& footprint, double legThickness, double underside, double top) {
  if (!(0 < underside && underside < top) || !(2 * legThickness < footprint.sizes().x())) {
    throw std::invalid_argument("table: needs 0 < underside < top and legs narrower than the top");
  }
  const double x0 = footprint.min().x();
  const double x1 = footprint.max().x();
  // Side view (x, z): a slab on two legs, like the letter "n".
  const Polygon2 profile{{x0, 0},
                         {x0 + legThickness, 0},
                         {x0 + legThickness, underside},
                         {x1 - legThickness, underside},
                         {x1 - legThickness, 0},
                         {x1, 0},
                         {x1, top},
                         {x0, top}};
  return extrudeProfileXZ(profile, footprint.min().y(), footprint.max().y());
}

}  // namespace freespace
