#pragma once

// Test scenes: meshes built from a few primitives (extruded polygons, unions of
// axis-aligned rectangles, boxes), environments and robots made of them, and the
// named scenes written as OMPL.app problems.
//
// Exactness: every coordinate the generator produces lies on a grid of
// kSceneGrid = 1/64 units, so it is exact as a float and as a short decimal and
// every mesh format round-trips it exactly. Every mesh goes through Mesh::fromSoup.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "freespace/geometry/mesh.h"
#include "freespace/scenes/scene.h"

namespace freespace {

using Point2 = Eigen::Vector2d;
using Box2 = Eigen::AlignedBox2d;
/// A simple polygon: its corners in order, either orientation.
using Polygon2 = std::vector<Point2>;

inline constexpr double kSceneGrid = 1.0 / 64;

// ---------------------------------------------------------------------------------
// Primitives. Each returns a closed, outward oriented surface.

/// A polygonal region: a simple outer polygon and disjoint simple holes inside it
/// (orientations are normalised).
struct PolygonWithHoles {
  Polygon2 outer;
  std::vector<Polygon2> holes;
};

/// The prism region x [z0, z1]; the caps are triangulated by ear clipping.
TriangleSoup extrudeRegion(const PolygonWithHoles& region, double z0, double z1);
/// The prism polygon x [z0, z1]; the polygon may be non-convex.
TriangleSoup extrudePolygon(const Polygon2& outline, double z0, double z1);
/// A side profile: `profile` is drawn in the (x, z) plane and extruded along y
/// from y0 to y1 (tables, arches).
TriangleSoup extrudeProfileXZ(const Polygon2& profile, double y0, double y1);
TriangleSoup makeBox(const Box3& box);

/// The union of axis-aligned rectangles (overlaps allowed; rectangles that touch
/// only at a corner are rejected) extruded over [z0, z1]: one prism per connected
/// piece of the union, with a hole wherever the union encloses a region, and no
/// vertices other than the corners of the union's outline.
TriangleSoup extrudeRectangleUnion(const std::vector<Box2>& rectangles, double z0, double z1);

/// Disjoint parts as one soup of several components.
TriangleSoup joinParts(const std::vector<TriangleSoup>& parts);
TriangleSoup translateSoup(const TriangleSoup& soup, const Point3& offset);

/// Mesh::fromSoup for generated soups: a repair (such as a flipped component) is a
/// generator bug and throws std::logic_error.
Mesh makeCheckedMesh(const TriangleSoup& soup, const std::string& name);

// ---------------------------------------------------------------------------------
// Walls and environments.

/// An interval [from, to] of the coordinate running along a wall.
struct Opening {
  double from = 0;
  double to = 0;
};

/// A straight axis-aligned wall whose centre line runs from `from` to `to`, as the
/// rectangles left after cutting the openings out. The wall extends half its
/// thickness past both ends, so walls whose centre lines meet at a corner overlap
/// and their union closes the corner.
std::vector<Box2> wallRectangles(const Point2& from, const Point2& to, double thickness,
                                 const std::vector<Opening>& openings = {});

enum class Side { west, east, south, north };

struct Door {
  Side side = Side::east;
  Opening opening;  // along the side: y for west/east, x for south/north
};

/// The four walls around the rectangle `interior` (outside it) with doors cut out.
std::vector<Box2> roomWallRectangles(const Box2& interior, double thickness, const std::vector<Door>& doors = {});

/// A table: a top slab of the given footprint over [underside, top], standing on two
/// panel legs of thickness `legThickness` at its west and east ends. Built as a
/// side profile extruded along y, so it is one closed solid.
TriangleSoup makeTable(const Box2& footprint, double legThickness, double underside, double top);

/// A rectangular grid of square rooms (cells of `cellSize`; walls of `wallThickness`
/// centred on the grid lines) filled row by row from the south-west corner up to
/// `rooms` rooms. Doors of `doorWidth` join the rooms along a random spanning tree
/// plus `extraDoors` random loops; there is no door to the outside, so all the
/// rooms together form one enclosed region.
struct FloorPlanLayout {
  unsigned rooms = 16;
  unsigned columns = 4;
  double cellSize = 3.5;
  double wallThickness = 0.25;
  double wallHeight = 0.5;
  /// When not empty, each wall (a room's side) takes one of these heights at
  /// random instead of wallHeight; walls of different heights overlap at corners.
  std::vector<double> wallHeights;
  double doorWidth = 1.25;
  unsigned extraDoors = 3;
};

struct FloorPlan {
  TriangleSoup walls;
  std::vector<Point2> roomCentres;  // in room order (row by row from the south-west)
};

FloorPlan makeFloorPlan(const FloorPlanLayout& layout, std::uint64_t seed);

/// One random star-shaped (non-convex) prism per centre: 3 to 5 points, within
/// `maxRadius` (at least 0.5) of its centre, over a random height range within
/// [0, maxTop]. Centres must be more than 2 maxRadius apart.
TriangleSoup makeStarObstacles(const std::vector<Point2>& centres, double maxRadius, double maxTop, std::uint64_t seed);

// ---------------------------------------------------------------------------------
// Robots. Each stands on z = 0 and has the average of its distinct vertices at
// x = y = 0, so re-centring it as OMPL.app does (loadProblem) leaves it in place and
// a pose is the position of that point (robots written as soups, soup_variants.h,
// have the average of the soup's vertices as written there, duplicates included).
// "Width" below is along y, "length" along x.

/// A bar of length x width x height (convex; its smallest width is `width`).
Mesh makeBarRobot(double length, double width, double height);
/// L: a 1.75 long arm along x and a 1 long arm along y, both 0.5 thick.
Mesh makeLRobot(double height);
/// T: a 2.5 long, 0.5 wide stem along -x and a 0.5 thick, 1.5 wide head at +x.
Mesh makeTRobot(double height);
/// U: 2.5 long, 1.5 wide, open towards +x with a 0.5 wide, 1.5 deep notch.
Mesh makeURobot(double height);
/// A tetrahedron: a triangle of minimum width 0.75 on the floor, apex at z = 0.75.
Mesh makeTetrahedronRobot();
/// A house: a 0.75 x 0.75 box over z in [0, 0.5] under a pyramid roof with its apex
/// at z = 0.875; 14 facets (convex).
Mesh makeHouseRobot();
/// A fishbone: a spine 0.25 wide along x with `teeth` teeth 0.125 wide and 0.75 long
/// across it, 0.125 apart, extruded over z in [0, 0.5]; 32 teeth - 20 facets
/// (non-convex; one tooth is a box).
Mesh makeFishboneRobot(unsigned teeth);
/// A genuinely 3D robot of two components: a 1 x 1 base over z in [0, 0.5] and a
/// 2 x 2 plate over z in [0.625, 0.875] that overhangs the base by 1 towards +y.
Mesh makeOverhangRobot();

// ---------------------------------------------------------------------------------
// Named scenes.

/// The named scenes makeScene builds, in a fixed order.
std::vector<std::string> sceneNames();

/// Builds a named scene. "tetra_floorplan_<N>" builds makeTetraFloorplanScene(N);
/// "tetra_floorplan" has 8 rooms. "soup_maze_<N>" builds makeSoupMazeScene(N);
/// "house_mixed_<N>" builds makeHouseMixedScene(N);
/// "soup_maze" has 16 rooms. The soup_* scenes are written as triangle soups
/// (Scene::robotSoup, Scene::worldSoup; soup_variants.h). Scenes with random parts
/// (maze, random_polyhedra, tetra_floorplan, soup_maze) depend on `seed`; the others
/// ignore it. Throws std::invalid_argument for an unknown name.
Scene makeScene(const std::string& name, std::uint64_t seed = 1);
bool isSceneName(const std::string& name);

/// "tetra_floorplan_<rooms>": a tetrahedron robot in a floor plan of `rooms` rooms
/// (3 x 3 cells, doors 1 wide), from the first room to the last; a family for
/// scaling benchmarks.
Scene makeTetraFloorplanScene(unsigned rooms, std::uint64_t seed = 1);

/// The floor plan of the house_mixed family: `rooms` rooms of 3 x 3 with doors 1
/// wide, walls of three heights (0.375, 0.75, 1.25) chosen at random per wall.
FloorPlanLayout mixedHeightLayout(unsigned rooms);

/// "house_mixed_<rooms>": the house robot in the mixed-height floor plan of `rooms`
/// rooms, from the first room to the last; a family for construction and
/// persistence benchmarks (house_mixed_160 has about 8,700 facets).
Scene makeHouseMixedScene(unsigned rooms, std::uint64_t seed = 1);

/// "soup_maze_<thousands>": a soup maze (soup_maze with more rooms) written as about
/// `thousandTriangles` thousand triangles; a family for loading benchmarks.
Scene makeSoupMazeScene(unsigned thousandTriangles, std::uint64_t seed = 1);

/// The same scene under another name (and file names).
Scene renamedScene(Scene scene, const std::string& name);

/// Writes "<name>_robot.<ext>", "<name>_world.<ext>" and "<name>.cfg" into
/// `directory` (created if needed): the scene's soups where it has them, else its
/// meshes (writtenSoup); the problem's robot and world fields name the written
/// files. Refuses (InputError) to overwrite any of them unless `overwrite`.
/// Returns the path of the .cfg.
std::string writeScene(const Scene& scene, const std::string& directory, const std::string& meshExtension = "obj",
                       bool overwrite = false);

}  // namespace freespace
