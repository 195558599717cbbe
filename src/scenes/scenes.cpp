// The named test scenes. Each places a robot and an environment so that the start
// and goal are clear of the walls by at least 0.1, and states what it was designed
// to show (solvable or not) and why.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <utility>

#include "freespace/input_error.h"
#include "freespace/io/mesh_writer.h"
#include "freespace/scenes/scene_generator.h"
#include "named_scenes.h"

namespace freespace {
namespace {

using detail::assembleScene;
using detail::kPi;

constexpr double kWallThickness = 0.25;
constexpr unsigned kDefaultTetraRooms = 8;
constexpr unsigned kDefaultSoupMazeRooms = 16;
const std::string kTetraFloorplan = "tetra_floorplan";
const std::string kSoupMaze = "soup_maze";
const std::string kHouseMixed = "house_mixed";

/// The planning volume: the environment and the robot's reach around the start
/// and the goal, with a margin, rounded outwards to quarter units.
Box2 planningVolume(const Mesh& robot, const Mesh& world, const Pose2& start, const Pose2& goal) {
  const double reach = robot.horizontalReach();
  const Box3 worldBounds = world.bounds();
  Box2 volume(worldBounds.min().head<2>(), worldBounds.max().head<2>());
  for (const Pose2& pose : {start, goal}) {
    volume.extend(Point2(pose.x - reach, pose.y - reach));
    volume.extend(Point2(pose.x + reach, pose.y + reach));
  }
  const double margin = 0.5;
  const double step = 0.25;
  return Box2(((volume.min().array() - margin) / step).floor() * step,
              ((volume.max().array() + margin) / step).ceil() * step);
}

}  // namespace

namespace detail {

Scene assembleScene(const std::string& name, Mesh robot, const TriangleSoup& world, const Pose2& start,
                    const Pose2& goal, bool solvable, const std::string& description) {
  Scene scene;
  scene.robot = std::move(robot);
  scene.world = makeCheckedMesh(world, name + "_world");
  scene.expectSolvable = solvable;
  scene.description = description;
  PlanarProblem& problem = scene.problem;
  problem.start = start;
  problem.goal = goal;
  problem.volume = planningVolume(scene.robot, scene.world, start, goal);
  problem.timeLimit = 10;
  problem.runCount = 10;
  problem.planners = {{"rrtconnect", {}}, {"prm", {}}};
  return renamedScene(std::move(scene), name);
}

}  // namespace detail

namespace {

TriangleSoup walls(const std::vector<Box2>& rectangles, double height) {
  return extrudeRectangleUnion(rectangles, 0, height);
}

std::vector<Box2> concatenate(std::vector<Box2> a, const std::vector<Box2>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

Scene roomDoorScene() {
  const double height = 0.5;
  const Box2 interior(Point2(-3, -3), Point2(3, 3));
  const Door door{Side::east, {-0.875, 0.875}};
  return assembleScene("room_door", makeURobot(height),
                       walls(roomWallRectangles(interior, kWallThickness, {door}), height), {-1, 0, kPi / 2},
                       {5.5, 0, 0}, true,
                       "U robot (2.5 x 1.5, height 0.5) turned sideways inside a closed 6 x 6 room with walls as "
                       "high as the robot; it must turn and leave through a 1.75 wide door in the east wall to "
                       "reach the goal outside. Solvable.");
}

Scene mazeScene(std::uint64_t seed) {
  FloorPlanLayout layout;
  layout.rooms = 16;
  layout.columns = 4;
  layout.cellSize = 3.5;
  layout.wallHeight = 0.5;
  layout.doorWidth = 1.25;
  layout.extraDoors = 3;
  const FloorPlan plan = makeFloorPlan(layout, seed);
  return assembleScene("maze", makeLRobot(layout.wallHeight), plan.walls,
                       {plan.roomCentres.front().x(), plan.roomCentres.front().y(), 0},
                       {plan.roomCentres.back().x(), plan.roomCentres.back().y(), kPi / 2}, true,
                       "L robot (1.75 x 1, height 0.5, smallest width 1) in a 4 x 4 grid of 3.5 rooms whose walls "
                       "are as high as the robot, joined by 1.25 wide doors along a random spanning tree plus 3 "
                       "loops (seeded); from the south-west room to the north-east one. Solvable.");
}

/// A closed 8 x 8 room split in two by a wall along y = 0 whose only opening is a
/// slot of `slotWidth` near x = 0; the bar (3 long) lies parallel to the wall on both
/// sides.
Scene keyholeScene(const std::string& name, double slotWidth, double barWidth, bool solvable,
                   const std::string& description) {
  const double height = 0.75;
  const Box2 interior(Point2(-4, -4), Point2(4, 4));
  const double slotStart = -std::floor(slotWidth / 2 / kSceneGrid) * kSceneGrid;
  const std::vector<Box2> partition =
      wallRectangles({-4, 0}, {4, 0}, kWallThickness, {{slotStart, slotStart + slotWidth}});
  return assembleScene(name, makeBarRobot(3, barWidth, height),
                       walls(concatenate(roomWallRectangles(interior, kWallThickness), partition), height),
                       {0, -2.25, 0}, {0, 2.25, 0}, solvable, description);
}

Scene cageScene() {
  const double height = 0.5;
  const Box2 interior(Point2(-2.5, -2.5), Point2(2.5, 2.5));
  return assembleScene("cage", makeTRobot(height), walls(roomWallRectangles(interior, kWallThickness), height),
                       {0, 0, 0}, {5, 0, 0}, false,
                       "T robot inside a closed 5 x 5 cage of walls as high as the robot, with room to turn but no "
                       "gap; the goal is outside. No path.");
}

/// A closed 8 x 8 room split by a wall along y = 0 with a 3 wide opening; a table
/// (2.5 x 1, underside 0.75, top 0.875) stands in the opening with its legs 0.25
/// from the wall ends, so the way through is under the table, 2 wide.
Scene tableScene(const std::string& name, double robotHeight, bool solvable, const std::string& description) {
  const Box2 interior(Point2(-4, -4), Point2(4, 4));
  const std::vector<Box2> partition = wallRectangles({-4, 0}, {4, 0}, kWallThickness, {{-1.5, 1.5}});
  const TriangleSoup table = makeTable(Box2(Point2(-1.25, -0.5), Point2(1.25, 0.5)), 0.25, 0.75, 0.875);
  const TriangleSoup room = walls(concatenate(roomWallRectangles(interior, kWallThickness), partition), robotHeight);
  return assembleScene(name, makeLRobot(robotHeight), joinParts({room, table}), {0, -2.5, 0}, {0, 2.5, kPi / 2},
                       solvable, description);
}

/// A wall along x = 0 splits a closed room. Its opening spans y in [0, 2.75]: the
/// part [0, 1.25] is a door, the part [1.25, 2.5] holds a wall only 0.375 high.
/// The robot's 1 wide base fits only the door and its 2 x 2 plate only the whole
/// opening, so it passes with the plate over the low wall.
Scene overhangScene() {
  const double height = 0.875;
  const Box2 interior(Point2(-4, -3), Point2(4, 5));
  const std::vector<Box2> partition = wallRectangles({0, -3}, {0, 5}, kWallThickness, {{0, 2.75}});
  const TriangleSoup tall = walls(concatenate(roomWallRectangles(interior, kWallThickness), partition), height);
  const TriangleSoup low = walls({Box2(Point2(-0.125, 1.25), Point2(0.125, 2.5))}, 0.375);
  return assembleScene("overhang", makeOverhangRobot(), joinParts({tall, low}), {-2, -1, kPi / 2}, {2, 3, 0}, true,
                       "Robot with a 1 x 1 base (z 0 to 0.5) under a 2 x 2 plate (z 0.625 to 0.875) that "
                       "overhangs one side by 1. A wall splits the room; its opening is 1.25 wide at floor level "
                       "(a door) and 2.75 wide above a 0.375 high low wall next to the door, so the robot gets "
                       "through only with its base in the door and its plate over the low wall. Solvable.");
}

Scene randomPolyhedraScene(std::uint64_t seed) {
  const double height = 0.75;
  const Box2 interior(Point2(-6, -6), Point2(6, 6));
  // One obstacle in each 3 x 3 cell, within 0.875 of the cell's centre: the lanes
  // along the cell borders stay 1.25 wide, more than the robot's 1.01 diameter.
  std::vector<Point2> centres;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) centres.emplace_back(-4.5 + 3 * i, -4.5 + 3 * j);
  }
  const TriangleSoup obstacles = makeStarObstacles(centres, 0.875, 1.5, seed);
  const TriangleSoup room = walls(roomWallRectangles(interior, kWallThickness), height);
  return assembleScene("random_polyhedra", makeTetrahedronRobot(), joinParts({room, obstacles}), {-3, -3, 0},
                       {3, 3, kPi / 2}, true,
                       "Tetrahedron robot (apex at 0.75) in a closed 12 x 12 room among 16 random star-shaped "
                       "prisms (seeded) at random heights between 0 and 1.5, some above the apex or cutting its "
                       "slanted faces; 1.25 wide lanes between them keep a path open. Solvable.");
}

/// A 6 x 6 room with a 1.75 wide corridor leaving it eastwards and ending 5.75
/// further on.
Scene turnAroundScene() {
  const double height = 0.5;
  const Box2 room(Point2(-6, -3), Point2(0, 3));
  const double halfWidth = 0.875;
  const double centreLine = halfWidth + kWallThickness / 2;  // of the corridor's side walls
  const double start = kWallThickness / 2;                   // x of the room's east wall centre line
  const double end = 6 + kWallThickness / 2;                 // x of the dead end's centre line
  std::vector<Box2> rectangles = roomWallRectangles(room, kWallThickness, {{Side::east, {-halfWidth, halfWidth}}});
  rectangles = concatenate(rectangles, wallRectangles({start, centreLine}, {end, centreLine}, kWallThickness));
  rectangles = concatenate(rectangles, wallRectangles({start, -centreLine}, {end, -centreLine}, kWallThickness));
  rectangles = concatenate(rectangles, wallRectangles({end, -centreLine}, {end, centreLine}, kWallThickness));
  return assembleScene("turn_around", makeTRobot(height), walls(rectangles, height), {3.5, 0, 0}, {3.5, 0, -kPi}, true,
                       "T robot (3 long, head 1.5 wide) at the dead end of a 1.75 wide corridor, head first; the "
                       "goal is the same place turned by pi (theta = -pi: OMPL's SO2 bounds are [-pi, pi)). The "
                       "corridor is too narrow to turn in, so the robot must back out into the 6 x 6 room, turn there "
                       "and drive back in. Solvable.");
}

/// A bar 3 x 0.5 in a closed box 3.25 x 1 just larger than it: it turns by at most
/// about 0.17 radians either way from lying along x, so its headings about 0 and
/// about pi are apart (it cannot turn round in the box).
Scene flipWindowScene() {
  const double height = 0.5;
  const Box2 interior(Point2(-1.625, -0.5), Point2(1.625, 0.5));
  const double tilt = 0.0625;
  return assembleScene("flip_window", makeBarRobot(3, 0.5, height),
                       walls(roomWallRectangles(interior, kWallThickness), height), {0, 0, kPi - tilt},
                       {0, 0, -kPi + tilt}, true,
                       "Bar robot 3 x 0.5 in a closed 3.25 x 1 box of walls as high as it: it can turn by at "
                       "most about 0.17 radians either way from lying along x. The start is turned 0.0625 short "
                       "of pi, the goal 0.0625 past it (theta = -pi + 0.0625): the only way is the short turn "
                       "through theta = pi, OMPL's wrap-around. Solvable.");
}

using SceneBuilder = std::function<Scene(std::uint64_t seed)>;

const std::vector<std::pair<std::string, SceneBuilder>>& sceneBuilders() {
  static const std::vector<std::pair<std::string, SceneBuilder>> builders{
      {"room_door", [](std::uint64_t) { return roomDoorScene(); }},
      {"maze", mazeScene},
      {"keyhole",
       [](std::uint64_t) {
         return keyholeScene("keyhole", 0.75, 0.5, true,
                             "Bar robot 3 x 0.5 x 0.75 lying parallel to a wall that splits a closed 8 x 8 room; "
                             "the wall's only opening is a 0.75 wide slot, so the bar must turn by 90 degrees, "
                             "pass end first and turn back. Walls as high as the robot. Solvable.");
       }},
      {"keyhole_narrow",
       [](std::uint64_t) {
         return keyholeScene("keyhole_narrow", 0.5 - kSceneGrid, 0.5, false,
                             "As keyhole, with the slot 1/64 narrower than the bar's 0.5 width (0.484375): the "
                             "convex bar cannot pass a gap narrower than its smallest width. No path.");
       }},
      {"keyhole_wide",
       [](std::uint64_t) {
         return keyholeScene("keyhole_wide", 101 * kSceneGrid, 100 * kSceneGrid, true,
                             "As keyhole with a bar 1.5625 (100/64) wide and a slot 1% wider (101/64): the bar "
                             "passes end first, turned within about 0.005 radians of a quarter turn. Solvable.");
       }},
      {"keyhole_tight",
       [](std::uint64_t) {
         return keyholeScene("keyhole_tight", 99 * kSceneGrid, 100 * kSceneGrid, false,
                             "As keyhole with a bar 1.5625 (100/64) wide and a slot 1% narrower (99/64): the convex "
                             "bar cannot pass a gap narrower than its smallest width. No path.");
       }},
      {"cage", [](std::uint64_t) { return cageScene(); }},
      {"table",
       [](std::uint64_t) {
         return tableScene("table", 0.5, true,
                           "L robot 0.5 high; a wall splits a closed 8 x 8 room and a table (underside 0.75, "
                           "legs 0.25 from the wall ends) stands in its 3 wide opening, so the way through is "
                           "under the table. Solvable.");
       }},
      {"table_tall",
       [](std::uint64_t) {
         return tableScene("table_tall", 1, false,
                           "As table with the L robot 1 high, taller than the table's 0.75 underside; the gaps "
                           "beside the legs are 0.25, narrower than the robot's 0.5 arms. No path.");
       }},
      {"overhang", [](std::uint64_t) { return overhangScene(); }},
      {"random_polyhedra", randomPolyhedraScene},
      {"turn_around", [](std::uint64_t) { return turnAroundScene(); }},
      {"flip_window", [](std::uint64_t) { return flipWindowScene(); }},
      {kTetraFloorplan,
       [](std::uint64_t seed) {
         return renamedScene(makeTetraFloorplanScene(kDefaultTetraRooms, seed), kTetraFloorplan);
       }},
      {kSoupMaze, [](std::uint64_t seed) { return detail::soupMazeScene(kSoupMaze, kDefaultSoupMazeRooms, seed); }},
      {"soup_pieces", [](std::uint64_t) { return detail::soupPiecesScene(); }},
      {"soup_open_sheet", [](std::uint64_t) { return detail::soupOpenSheetScene(); }},
      {"soup_crack", [](std::uint64_t) { return detail::soupCrackScene(); }},
  };
  return builders;
}

/// N in "<family>_<N>" (a scene of the family's size N), or 0 when the name has
/// another form.
unsigned familySize(const std::string& name, const std::string& family) {
  const std::string prefix = family + "_";
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0 || name.size() > prefix.size() + 6) {
    return 0;
  }
  const std::string digits = name.substr(prefix.size());
  if (!std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) return 0;
  return static_cast<unsigned>(std::stoul(digits));
}

std::string lowerCaseExtension(std::string extension) {
  if (!extension.empty() && extension.front() == '.') extension.erase(0, 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace

std::vector<std::string> sceneNames() {
  std::vector<std::string> names;
  for (const auto& [name, builder] : sceneBuilders()) names.push_back(name);
  return names;
}

bool isSceneName(const std::string& name) {
  const std::vector<std::string> names = sceneNames();
  return std::find(names.begin(), names.end(), name) != names.end() || familySize(name, kTetraFloorplan) > 0 ||
         familySize(name, kSoupMaze) > 0 || familySize(name, kHouseMixed) > 0;
}

Scene makeScene(const std::string& name, std::uint64_t seed) {
  for (const auto& [known, builder] : sceneBuilders()) {
    if (known == name) return builder(seed);
  }
  if (const unsigned rooms = familySize(name, kTetraFloorplan); rooms > 0) {
    return renamedScene(makeTetraFloorplanScene(rooms, seed), name);
  }
  if (const unsigned thousands = familySize(name, kSoupMaze); thousands > 0) {
    return renamedScene(makeSoupMazeScene(thousands, seed), name);
  }
  if (const unsigned rooms = familySize(name, kHouseMixed); rooms > 0) return makeHouseMixedScene(rooms, seed);
  throw std::invalid_argument("unknown scene '" + name + "'");
}

Scene makeTetraFloorplanScene(unsigned rooms, std::uint64_t seed) {
  if (rooms == 0) throw std::invalid_argument("tetra_floorplan: needs at least one room");
  FloorPlanLayout layout;
  layout.rooms = rooms;
  layout.columns = static_cast<unsigned>(std::ceil(std::sqrt(static_cast<double>(rooms))));
  layout.cellSize = 3;
  layout.wallHeight = 0.75;  // the tetrahedron's apex
  layout.doorWidth = 1;
  layout.extraDoors = rooms / 5;
  const FloorPlan plan = makeFloorPlan(layout, seed);
  return assembleScene(kTetraFloorplan + "_" + std::to_string(rooms), makeTetrahedronRobot(), plan.walls,
                       {plan.roomCentres.front().x(), plan.roomCentres.front().y(), 0},
                       {plan.roomCentres.back().x(), plan.roomCentres.back().y(), kPi / 2}, true,
                       "Tetrahedron robot (smallest width 0.75, apex as high as the walls) in a floor plan of " +
                           std::to_string(rooms) +
                           " rooms of 3 x 3 joined by 1 wide doors along a random spanning tree plus loops "
                           "(seeded); from the first room to the last. Solvable.");
}

FloorPlanLayout mixedHeightLayout(unsigned rooms) {
  FloorPlanLayout layout;
  layout.rooms = rooms;
  layout.columns = static_cast<unsigned>(std::ceil(std::sqrt(static_cast<double>(rooms))));
  layout.cellSize = 3;
  layout.wallHeights = {0.375, 0.75, 1.25};  // under the house's eaves, under its apex, above it
  layout.doorWidth = 1;
  layout.extraDoors = rooms / 5;
  return layout;
}

Scene makeHouseMixedScene(unsigned rooms, std::uint64_t seed) {
  if (rooms == 0) throw std::invalid_argument("house_mixed: needs at least one room");
  const FloorPlan plan = makeFloorPlan(mixedHeightLayout(rooms), seed);
  return assembleScene(kHouseMixed + "_" + std::to_string(rooms), makeHouseRobot(), plan.walls,
                       {plan.roomCentres.front().x(), plan.roomCentres.front().y(), 0},
                       {plan.roomCentres.back().x(), plan.roomCentres.back().y(), kPi / 2}, true,
                       "House robot (14 facets, 0.75 wide, apex at 0.875) in a floor plan of " + std::to_string(rooms) +
                           " rooms of 3 x 3 joined by 1 wide doors (seeded), walls of three heights (0.375, "
                           "0.75, 1.25); from the first room to the last. Solvable.");
}

Scene renamedScene(Scene scene, const std::string& name) {
  scene.name = name;
  scene.problem.name = name;
  scene.problem.robot = name + "_robot.obj";
  scene.problem.world = name + "_world.obj";
  return scene;
}

std::string writeScene(const Scene& scene, const std::string& directory, const std::string& meshExtension,
                       bool overwrite) {
  namespace fs = std::filesystem;
  const std::string extension = lowerCaseExtension(meshExtension);
  PlanarProblem problem = scene.problem;
  problem.robot = scene.name + "_robot." + extension;
  problem.world = scene.name + "_world." + extension;
  const fs::path folder(directory);
  const std::string robotPath = (folder / problem.robot).string();
  const std::string worldPath = (folder / problem.world).string();
  const std::string cfgPath = (folder / (scene.name + ".cfg")).string();
  if (!overwrite) {
    for (const std::string& path : {robotPath, worldPath, cfgPath}) {
      if (fs::exists(path)) throw InputError(path, "already exists (not overwritten)");
    }
  }
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw InputError(directory, "cannot create directory: " + error.message());
  writeSoup(writtenSoup(scene.robot, scene.robotSoup), robotPath, overwrite);
  writeSoup(writtenSoup(scene.world, scene.worldSoup), worldPath, overwrite);
  writeProblem(problem, cfgPath, overwrite);
  return cfgPath;
}

}  // namespace freespace
