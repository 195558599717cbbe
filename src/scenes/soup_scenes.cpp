// The named scenes written as triangle soups (soup_variants.h): OMPL.app-style
// planar problems whose files imitate what modelling tools export. Each scene's
// robot and world meshes hold the solids the soups are meant to show.

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "floor_plan_walls.h"
#include "freespace/scenes/soup_variants.h"
#include "named_scenes.h"

namespace freespace {
namespace {

using detail::kPi;

constexpr double kWallThickness = 0.25;
/// Copies of a point then differ by at most 4 float steps per coordinate, under
/// 5e-7 of the maze's width: within a millionth of its diagonal, a distance a
/// loader can be expected to weld.
constexpr unsigned kNoiseUlps = 2;
/// About what one room of the soup maze adds (its walls' pieces, 24 triangles each
/// when written double-sided), measured: the soup_maze_<N> family's scale.
constexpr double kMazeTrianglesPerRoom = 78;

Scene assembleSoupScene(const std::string& name, const SoupRobot& robot, const TriangleSoup& worldSoup,
                        const TriangleSoup& worldSolid, const Pose2& start, const Pose2& goal,
                        const std::string& description) {
  Scene scene = detail::assembleScene(name, robot.solid, worldSolid, start, goal, true, description);
  scene.robotSoup = robot.soup;
  scene.worldSoup = worldSoup;
  return scene;
}

Box3 standing(const Box2& footprint, double height) {
  return Box3(Point3(footprint.min().x(), footprint.min().y(), 0),
              Point3(footprint.max().x(), footprint.max().y(), height));
}

/// Wall pieces standing on the floor as they are written, and the solid they show.
class WallPieces {
 public:
  void addBox(const Box2& footprint, double height) { add(makeBox(standing(footprint, height)), footprint, height); }

  /// A piece whose solid is footprint x [0, height], written as `soup`.
  void add(const TriangleSoup& soup, const Box2& footprint, double height) {
    written_.push_back(soup);
    levels_[height].push_back(footprint);
  }

  TriangleSoup written() const { return joinParts(written_); }

  /// Layers, one per wall height from the lowest: the union of the footprints of
  /// the walls at least that high, extruded from one grid step below the previous
  /// height (from the floor for the first) up to it. The layers overlap, so no two
  /// share a vertex, whereas unions of one height each would share edges where
  /// walls of different heights meet.
  TriangleSoup solid() const {
    std::vector<TriangleSoup> layers;
    double bottom = 0;
    for (auto level = levels_.begin(); level != levels_.end(); ++level) {
      layers.push_back(extrudeRectangleUnion(footprintsFrom(level), bottom, level->first));
      bottom = level->first - kSceneGrid;
    }
    return joinParts(layers);
  }

 private:
  using Levels = std::map<double, std::vector<Box2>>;  // footprints by wall height

  /// The footprints of the walls at least as high as `level`.
  std::vector<Box2> footprintsFrom(Levels::const_iterator level) const {
    std::vector<Box2> footprints;
    for (; level != levels_.end(); ++level) {
      footprints.insert(footprints.end(), level->second.begin(), level->second.end());
    }
    return footprints;
  }

  std::vector<TriangleSoup> written_;
  Levels levels_;
};

/// Rooms of 4 x 4 joined by doors 2 wide: passages more than 2.5 times as wide as
/// the car robot (0.75).
FloorPlanLayout soupMazeLayout(unsigned rooms) {
  FloorPlanLayout layout;
  layout.rooms = rooms;
  layout.columns = static_cast<unsigned>(std::ceil(std::sqrt(static_cast<double>(rooms))));
  layout.cellSize = 4;
  layout.wallThickness = kWallThickness;
  layout.wallHeights = {0.5, 0.75};
  layout.doorWidth = 2;
  layout.extraDoors = rooms / 5;
  return layout;
}

/// A second layer, as high as the lower walls, glued face to face to the outer
/// faces of the outline walls along the whole south and west sides (which every
/// floor plan has): along the south a T-junction wall split at its middle, along
/// the west one long box standing on the south layer's end.
void addOutlineLayers(WallPieces& walls, const FloorPlanLayout& layout) {
  const auto rows = (layout.rooms + layout.columns - 1) / layout.columns;
  const double outside = -kWallThickness / 2;  // the outline walls' outer faces at x = outside and y = outside
  const double east = layout.columns * layout.cellSize + kWallThickness / 2;
  const double north = rows * layout.cellSize + kWallThickness / 2;
  const double low = layout.wallHeights.front();
  const double layerStart = outside - kWallThickness;
  const Box2 southOuter(Point2(layerStart, outside - 2 * kWallThickness), Point2(east, layerStart));
  const Box2 south(southOuter.min(), Point2(east, outside));
  walls.add(tJunctionWall(standing(southOuter, low), (layerStart + east) / 2, kWallThickness), south, low);
  walls.addBox(Box2(Point2(layerStart, outside), Point2(outside, north)), low);
}

}  // namespace

namespace detail {

Scene soupMazeScene(const std::string& name, unsigned rooms, std::uint64_t seed) {
  const FloorPlanLayout layout = soupMazeLayout(rooms);
  const PlannedFloorPlan plan = planFloorPlan(layout, seed);
  WallPieces walls;
  for (const PlannedWall& wall : plan.walls) {
    for (const Box2& piece : wallRectangles(wall.from, wall.to, kWallThickness, wall.openings)) {
      walls.addBox(piece, wall.height);
    }
  }
  addOutlineLayers(walls, layout);
  const TriangleSoup written = withFloatNoise(doubleSided(walls.written()), seed, kNoiseUlps);
  const Point2& first = plan.roomCentres.front();
  const Point2& last = plan.roomCentres.back();
  return assembleSoupScene(
      name, makeGluedCarRobot(0.375), written, walls.solid(), {first.x(), first.y(), 0}, {last.x(), last.y(), kPi / 2},
      "Car robot (1.5 x 0.75, 0.375 high; four glued prisms) in a floor plan of " + std::to_string(rooms) +
          " rooms of 4 x 4 whose walls are separate boxes, 0.5 or 0.75 high at random, crossing at the corners, "
          "joined by 2 wide doors along a random spanning tree plus loops (seeded); outside the south and west "
          "outline a second layer glued face to face (along the south a T-junction wall: a long box and two "
          "short ones without their touching faces). Every triangle is written twice, once in each orientation, "
          "and the walls with float noise of up to 2 ulps (seeded). The solid (the scene's world) is the union of "
          "the boxes, as overlapping layers: all walls up to 0.5, the high ones from 0.484375 to 0.75. From the "
          "first room to the last. Solvable.");
}

Scene soupPiecesScene() {
  // A closed 8 x 8 room: west and east walls over the whole outer length, south and
  // north walls reaching to their middles with both ends buried in them.
  const Box3 west(Point3(-4.25, -4.25, 0), Point3(-4, 4.25, 1));
  const Box3 east(Point3(4, -4.25, 0), Point3(4.25, 4.25, 1));
  const Box3 south(Point3(-4.125, -4.25, 0), Point3(4.125, -4, 0.75));
  const Box3 north(Point3(-4.125, 4, 0), Point3(4.125, 4.25, 0.75));
  // In the middle two walls of different heights crossing, and in the quarters they
  // leave, pairs of boxes touching along a face, along part of an edge and at a
  // corner, and a pair interpenetrating; all within 1.5 of the centre, so a ring
  // 2.5 wide stays free around them.
  const Box3 crossX(Point3(-1.5, -0.125, 0), Point3(1.5, 0.125, 0.5));
  const Box3 crossY(Point3(-0.125, -1.5, 0), Point3(0.125, 1.5, 0.75));
  const Box3 faceBox(Point3(-1.25, -1.25, 0), Point3(-0.875, -0.5, 0.5));
  const Box3 edgeBox(Point3(0.375, -1.25, 0), Point3(0.75, -0.875, 0.5));
  const Box3 vertexBox(Point3(0.375, 0.375, 0), Point3(0.75, 0.75, 0.375));
  const Box3 overlapA(Point3(-1.25, 0.5, 0), Point3(-0.75, 1, 0.5));
  const Box3 overlapB(Point3(-1, 0.75, 0.25), Point3(-0.5, 1.25, 0.75));
  // A beam from the west wall across the ring, above the robot.
  const Box3 beam(Point3(-4, -0.125, 0.625), Point3(-1.5, 0.125, 0.875));

  std::vector<TriangleSoup> closed;
  for (const Box3& box : {west, east, crossX, crossY, overlapA, overlapB, beam}) closed.push_back(makeBox(box));
  closed.push_back(touchingBoxes(edgeBox, Contact::edge));
  closed.push_back(touchingBoxes(vertexBox, Contact::vertex));
  // A stray triangle under the floor, as left where a modeller triangulated a
  // bottom past its outline: it encloses nothing, but the robot never reaches it.
  const TriangleSoup strayUnderFloor{{{-3, -3, -kSceneGrid}, {3, -3, -kSceneGrid}, {0, 3, -kSceneGrid}}, {{0, 1, 2}}};
  std::vector<TriangleSoup> written = closed;
  for (const TriangleSoup& piece : {wallWithBuriedEnds(south), wallWithBuriedEnds(north),
                                    touchingBoxes(faceBox, Contact::face), strayUnderFloor}) {
    written.push_back(piece);
  }
  // The boxes that share a face are one box in the solid.
  const Box3 facePair = faceBox.merged(faceBox.translated(Point3(faceBox.sizes().x(), 0, 0)));
  std::vector<TriangleSoup> solid = closed;
  for (const Box3& box : {south, north, facePair}) solid.push_back(makeBox(box));

  return assembleSoupScene(
      "soup_pieces", doubleSidedRobot(makeBarRobot(2, 0.5, 0.5)), doubleSided(joinParts(written)), joinParts(solid),
      {-2.75, -2.75, 0}, {2.75, 2.75, kPi / 2},
      "Bar robot 2 x 0.5 x 0.5 in a closed 8 x 8 room: west and east walls 1 high over the whole length, south "
      "and north walls 0.75 high reaching to the middle of them with their end caps missing (buried: each piece "
      "open, the union closed). In the middle walls 0.5 and 0.75 high cross, and in the quarters they leave two "
      "boxes share a face, two touch along part of an edge, two at a corner and two interpenetrate; a beam from "
      "the west wall at z 0.625 to 0.875 spans the free ring around them above the robot, and a stray "
      "triangle lies 1/64 under the floor, where the robot never reaches (it encloses nothing and is not part of "
      "the solid). Every triangle is written twice, once in each orientation, without noise; the solid is the union of the boxes. From the "
      "south-west of the ring to the north-east. Solvable.");
}

Scene soupOpenSheetScene() {
  const Box3 wall(Point3(-0.125, -2, 0), Point3(0.125, 2, 0.75));
  return assembleSoupScene(
      "soup_open_sheet", doubleSidedRobot(makeBarRobot(2, 0.5, 0.5)), openSheetBesideBox(wall), makeBox(wall),
      {-3, 0, 0}, {3, 0, 0},
      "Bar robot 2 x 0.5 x 0.5 (double-sided) on either side of a 4 long wall box; 0.25 east of the wall stands "
      "a sheet as long and as high as the wall: a lone double-sided quad of zero thickness. Loading the world must "
      "fail: the sheet encloses nothing. The solid (the scene's world) is the wall alone; with it the robot goes "
      "round the wall. Solvable.");
}

Scene soupCrackScene() {
  // 16 long, so the gap of one grid step is about 1e-3 of the box's size.
  const Box3 wall(Point3(-0.25, -8, 0), Point3(0.25, 8, 1));
  return assembleSoupScene(
      "soup_crack", doubleSidedRobot(makeBarRobot(2, 0.5, 0.5)), tornSeamBox(wall, kSceneGrid), makeBox(wall),
      {-3, 0, 0}, {3, 0, 0},
      "Bar robot 2 x 0.5 x 0.5 (double-sided) on either side of a 16 long wall box whose seam between its top and "
      "east faces is torn open: the two faces stop 1/64 short of their common edge, leaving a crack about 1e-3 of "
      "the box's size wide along its whole length. Loading the world must fail: the crack is far wider than "
      "float noise, so the box is not closed. The solid (the scene's world) is the whole box; with it the robot "
      "goes round the wall. Solvable.");
}

}  // namespace detail

Scene makeSoupMazeScene(unsigned thousandTriangles, std::uint64_t seed) {
  if (thousandTriangles == 0) throw std::invalid_argument("soup_maze: needs at least a thousand triangles");
  const auto rooms = static_cast<unsigned>(std::lround(thousandTriangles * 1000 / kMazeTrianglesPerRoom));
  return detail::soupMazeScene("soup_maze_" + std::to_string(thousandTriangles), rooms, seed);
}

}  // namespace freespace
