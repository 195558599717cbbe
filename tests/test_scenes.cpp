// The scene generator and the mesh writer: every scene's meshes validate and are
// built as designed (components, holes, heights, widths of the openings measured
// from the meshes against widths measured from the robot), every coordinate is
// exact, starts and goals are clear, and every format round-trips exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <set>

#include "command_runner.h"
#include "containment_oracle.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/input_error.h"
#include "freespace/io/mesh_reader.h"
#include "freespace/io/mesh_writer.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/scenes/scene_generator.h"
#include "temp_dir.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

const std::map<std::string, Scene>& allScenes() {
  static const std::map<std::string, Scene> scenes = [] {
    std::map<std::string, Scene> built;
    for (const std::string& name : sceneNames()) built.emplace(name, makeScene(name));
    return built;
  }();
  return scenes;
}

const Scene& scene(const std::string& name) { return allScenes().at(name); }

std::vector<Point3> componentVertices(const Mesh& mesh, std::uint32_t component) {
  std::set<std::uint32_t> used;
  for (std::size_t t = 0; t < mesh.triangles().size(); ++t) {
    if (mesh.triangleComponents()[t] == component) used.insert(mesh.triangles()[t].begin(), mesh.triangles()[t].end());
  }
  std::vector<Point3> vertices;
  for (std::uint32_t v : used) vertices.push_back(mesh.vertices()[v]);
  return vertices;
}

/// The component whose bounding box has the given top height.
std::uint32_t componentWithTop(const Mesh& mesh, double top) {
  for (std::uint32_t c = 0; c < mesh.componentCount(); ++c) {
    if (mesh.componentBounds()[c].max().z() == top) return c;
  }
  ADD_FAILURE() << "no component with top " << top;
  return 0;
}

double turn(const Point2& o, const Point2& a, const Point2& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

/// Convex hull of the points' projection on the floor, counter-clockwise (Andrew's
/// monotone chain).
std::vector<Point2> floorHull(const std::vector<Point3>& points) {
  std::vector<Point2> p;
  for (const Point3& v : points) p.emplace_back(v.x(), v.y());
  std::sort(p.begin(), p.end(), [](const Point2& a, const Point2& b) {
    return std::make_pair(a.x(), a.y()) < std::make_pair(b.x(), b.y());
  });
  std::vector<Point2> hull;
  for (int pass = 0; pass < 2; ++pass) {  // lower chain, then upper chain
    const std::size_t chainStart = hull.size();
    for (const Point2& q : p) {
      while (hull.size() >= chainStart + 2 && turn(hull[hull.size() - 2], hull.back(), q) <= 0) hull.pop_back();
      hull.push_back(q);
    }
    hull.pop_back();
    std::reverse(p.begin(), p.end());
  }
  return hull;
}

/// Smallest width of the points' projection on the floor: over the edges of the
/// convex hull, the largest distance of a hull point from the edge's line.
double minimumWidth(const std::vector<Point3>& points) {
  const std::vector<Point2> hull = floorHull(points);
  double width = INFINITY;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point2 a = hull[i];
    const Point2 edge = hull[(i + 1) % hull.size()] - a;
    double farthest = 0;
    for (const auto& q : hull) farthest = std::max(farthest, std::abs(turn(a, a + edge, q)) / edge.norm());
    width = std::min(width, farthest);
  }
  return width;
}

/// Whether a prism component is non-convex: its top face covers less than the
/// convex hull of its corners.
bool nonConvexPrism(const Mesh& mesh, std::uint32_t component) {
  const double top = mesh.componentBounds()[component].max().z();
  double topArea = 0;
  for (std::size_t t = 0; t < mesh.triangles().size(); ++t) {
    const TriangleIndices& corners = mesh.triangles()[t];
    const Point3& a = mesh.vertices()[corners[0]];
    const Point3& b = mesh.vertices()[corners[1]];
    const Point3& c = mesh.vertices()[corners[2]];
    if (mesh.triangleComponents()[t] == component && a.z() == top && b.z() == top && c.z() == top) {
      topArea += turn(a.head<2>(), b.head<2>(), c.head<2>()) / 2;
    }
  }
  const std::vector<Point2> hull = floorHull(componentVertices(mesh, component));
  double hullArea = 0;
  for (std::size_t i = 1; i + 1 < hull.size(); ++i) hullArea += turn(hull[0], hull[i], hull[i + 1]) / 2;
  return topArea < hullArea - 1e-9;
}

/// Length of the longest run of the segment from `from` to `to` that is outside the
/// world at every one of `heights`, sampled every 1/128 (exact for openings whose
/// ends lie on the 1/64 grid when `from` does).
double longestOpening(const Mesh& world, const Point2& from, const Point2& to, const std::vector<double>& heights) {
  const double step = 1.0 / 128;
  const auto samples = static_cast<int>(std::lround((to - from).norm() / step));
  const Point2 direction = (to - from).normalized();
  int run = 0;
  int longest = 0;
  for (int k = 0; k < samples; ++k) {
    const Point2 at = from + (k + 0.5) * step * direction;
    const bool open = std::none_of(heights.begin(), heights.end(),
                                   [&](double z) { return insideMesh(world, Point3(at.x(), at.y(), z)); });
    run = open ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  return longest * step;
}

/// Sum of the genera of the components (a wall ring around rooms has genus 1),
/// from the Euler characteristic of the closed surface.
long genus(const Mesh& mesh) {
  const auto vertices = static_cast<long>(mesh.vertices().size());
  const auto faces = static_cast<long>(mesh.triangles().size());
  const long euler = vertices - faces * 3 / 2 + faces;
  return (2 * static_cast<long>(mesh.componentCount()) - euler) / 2;
}

/// Triangles as corner positions, each starting at its smallest corner (keeping
/// the orientation), sorted: equal for meshes with the same triangles however
/// their vertices are numbered.
std::vector<std::array<std::array<double, 3>, 3>> canonicalTriangles(const Mesh& mesh) {
  std::vector<std::array<std::array<double, 3>, 3>> triangles;
  for (const TriangleIndices& t : mesh.triangles()) {
    std::array<std::array<double, 3>, 3> corners;
    for (int k = 0; k < 3; ++k) {
      const Point3& v = mesh.vertices()[t[k]];
      corners[k] = {v.x(), v.y(), v.z()};
    }
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    triangles.push_back(corners);
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

}  // namespace

// ---------------------------------------------------------------------------------
// Every scene

TEST(Scenes, EveryNamedSceneIsBuiltWithItsProblem) {
  const std::vector<std::string> required{"room_door",   "maze",           "keyhole",  "keyhole_narrow",
                                          "cage",        "table",          "overhang", "random_polyhedra",
                                          "turn_around", "tetra_floorplan"};
  for (const std::string& name : required) EXPECT_TRUE(allScenes().count(name)) << name;
  for (const auto& [name, s] : allScenes()) {
    EXPECT_EQ(s.name, name);
    EXPECT_EQ(s.problem.name, name);
    EXPECT_EQ(s.problem.robot, name + "_robot.obj");
    EXPECT_EQ(s.problem.world, name + "_world.obj");
    EXPECT_FALSE(s.description.empty()) << name;
    EXPECT_FALSE(s.problem.planners.empty()) << name;
    EXPECT_EQ(s.problem.timeLimit, 10);
    EXPECT_EQ(s.problem.runCount, 10u);
    ASSERT_TRUE(s.problem.volume.has_value()) << name;
    const Box3 world = s.world.bounds();
    EXPECT_TRUE(s.problem.volume->contains(Eigen::AlignedBox2d(world.min().head<2>(), world.max().head<2>()))) << name;
    for (const Pose2& pose : {s.problem.start, s.problem.goal}) {
      EXPECT_TRUE(s.problem.volume->contains(Point2(pose.x, pose.y))) << name;
      EXPECT_GE(pose.theta, -M_PI) << name << ": OMPL's SO2 bounds are [-pi, pi)";
      EXPECT_LT(pose.theta, M_PI) << name;
    }
  }
}

TEST(Scenes, MeshesValidateAgainAsTheyAre) {
  for (const auto& [name, s] : allScenes()) {
    for (const Mesh* mesh : {&s.robot, &s.world}) {
      const TriangleSoup soup{mesh->vertices(), mesh->triangles()};
      std::vector<std::string> warnings;
      EXPECT_NO_THROW(Mesh::fromSoup(soup, name, &warnings)) << name;
      EXPECT_TRUE(warnings.empty()) << name << ": " << (warnings.empty() ? "" : warnings.front());
    }
  }
}

TEST(Scenes, EveryCoordinateIsAFloatOnTheGrid) {
  for (const auto& [name, s] : allScenes()) {
    for (const Mesh* mesh : {&s.robot, &s.world}) {
      for (const Point3& v : mesh->vertices()) {
        for (int k = 0; k < 3; ++k) {
          EXPECT_EQ(static_cast<double>(static_cast<float>(v[k])), v[k]) << name;
          EXPECT_EQ(std::floor(v[k] * 64), v[k] * 64) << name << ": " << v[k] << " is not a multiple of 1/64";
        }
      }
    }
  }
}

TEST(Scenes, RobotsTurnAboutTheAverageOfTheirVertices) {
  // Both of the vertices as written (a soup's with its duplicates) and of the solid's.
  for (const auto& [name, s] : allScenes()) {
    for (const std::vector<Point3>& vertices : {writtenSoup(s.robot, s.robotSoup).vertices, s.robot.vertices()}) {
      Point3 sum = Point3::Zero();
      for (const Point3& v : vertices) sum += v;
      EXPECT_EQ(sum.x(), 0) << name;
      EXPECT_EQ(sum.y(), 0) << name;
    }
    EXPECT_EQ(s.robot.bounds().min().z(), 0) << name << ": robots stand on the floor";
  }
}

TEST(Scenes, ComponentsAndEnclosedRegionsAreAsDesigned) {
  struct Design {
    std::size_t robotComponents;
    std::size_t worldComponents;  // 0: depends on the seed
    long worldGenus;              // regions the walls enclose completely; -1: depends on the seed
  };
  // The solids of the soup scenes: soup_maze's are overlapping layers of walls,
  // soup_pieces' every box apart (the two sharing a face as one box).
  const std::map<std::string, Design> designs{
      {"room_door", {1, 1, 0}},
      {"maze", {1, 0, 1}},
      {"keyhole", {1, 1, 1}},
      {"keyhole_narrow", {1, 1, 1}},
      {"keyhole_wide", {1, 1, 1}},
      {"keyhole_tight", {1, 1, 1}},
      {"cage", {1, 1, 1}},
      {"table", {1, 2, 1}},
      {"table_tall", {1, 2, 1}},
      {"overhang", {2, 2, 1}},
      {"random_polyhedra", {1, 17, 1}},
      {"turn_around", {1, 1, 1}},
      {"flip_window", {1, 1, 1}},
      {"tetra_floorplan", {1, 0, 1}},
      {"soup_maze", {1, 0, -1}},
      {"soup_pieces", {1, 14, 0}},
      {"soup_open_sheet", {1, 1, 0}},
      {"soup_crack", {1, 1, 0}},
  };
  for (const auto& [name, s] : allScenes()) {
    ASSERT_TRUE(designs.count(name)) << name;
    const Design& design = designs.at(name);
    EXPECT_EQ(s.robot.componentCount(), design.robotComponents) << name;
    if (design.worldComponents > 0) {
      EXPECT_EQ(s.world.componentCount(), design.worldComponents) << name;
    }
    EXPECT_EQ(genus(s.robot), 0) << name;
    if (design.worldGenus >= 0) {
      EXPECT_EQ(genus(s.world), design.worldGenus) << name;
    }
  }
}

TEST(Scenes, StartAndGoalAreClearByAtLeastATenth) {
  for (const auto& [name, s] : allScenes()) {
    const ExactCollisionChecker exact(s.robot, s.world);
    const FclCollisionChecker fcl(s.robot, s.world);
    for (const Pose2& pose : {s.problem.start, s.problem.goal}) {
      EXPECT_FALSE(exact.inCollision(pose)) << name << " at " << pose.x << " " << pose.y << " " << pose.theta;
      EXPECT_GE(fcl.distance(pose), 0.1) << name << " at " << pose.x << " " << pose.y << " " << pose.theta;
    }
  }
}

TEST(Scenes, FloorPlanScenesHaveWallsAsHighAsTheRobot) {
  for (const std::string name : {"room_door", "maze", "keyhole", "keyhole_narrow", "cage", "turn_around",
                                 "tetra_floorplan", "table", "table_tall"}) {
    const Mesh& walls = scene(name).world;
    const double wallTop = walls.componentBounds()[0].max().z();
    EXPECT_EQ(wallTop, scene(name).robot.bounds().max().z()) << name;
  }
}

// ---------------------------------------------------------------------------------
// Scene designs, measured on the meshes

TEST(Scenes, KeyholeSlotIsWiderThanTheBarAndTheNarrowOneAHairNarrower) {
  for (const std::string name : {"keyhole", "keyhole_narrow"}) {
    const Scene& s = scene(name);
    const double barWidth = minimumWidth(s.robot.vertices());
    EXPECT_EQ(barWidth, 0.5);
    const double slot = longestOpening(s.world, {-4, 0}, {4, 0}, {0.375});
    if (name == "keyhole") {
      EXPECT_EQ(slot, 0.75);
      // Lying parallel to the wall (theta = 0) the bar is far wider than the slot.
      EXPECT_GT(s.robot.bounds().sizes().x(), slot);
      EXPECT_EQ(s.problem.start.theta, 0);
    } else {
      EXPECT_LT(slot, barWidth);
      EXPECT_EQ(barWidth - slot, 1.0 / 64);
    }
  }
}

TEST(Scenes, CageHasNoGap) {
  const Scene& s = scene("cage");
  const Pose2& start = s.problem.start;
  for (const Point2& direction : {Point2(1, 0), Point2(-1, 0), Point2(0, 1), Point2(0, -1)}) {
    const Point2 from(start.x, start.y);
    EXPECT_LT(longestOpening(s.world, from, from + 10 * direction, {0.25}), 10);
  }
  EXPECT_FALSE(s.expectSolvable);
}

TEST(Scenes, TableLetsOnlyTheLowRobotUnder) {
  for (const std::string name : {"table", "table_tall"}) {
    const Scene& s = scene(name);
    const std::uint32_t table = componentWithTop(s.world, 0.875);
    std::set<double> heights;
    for (const Point3& v : componentVertices(s.world, table)) heights.insert(v.z());
    ASSERT_EQ(heights.size(), 3u) << "floor, underside, top";
    const double underside = *std::next(heights.begin());
    EXPECT_EQ(underside, 0.75);

    const double robotTop = s.robot.bounds().max().z();
    std::vector<double> robotHeights;
    for (double z = 1.0 / 16; z < robotTop; z += 1.0 / 8) robotHeights.push_back(z);
    const double opening = longestOpening(s.world, {-4, 0}, {4, 0}, robotHeights);
    const double robotWidth = minimumWidth(s.robot.vertices());
    if (name == "table") {
      EXPECT_LT(robotTop, underside);
      EXPECT_EQ(opening, 2);
      EXPECT_LT(robotWidth, opening);
      EXPECT_TRUE(s.expectSolvable);
    } else {
      EXPECT_GT(robotTop, underside);
      EXPECT_EQ(opening, 0.25) << "the gaps beside the legs";
      EXPECT_LT(opening, robotWidth / 2);
      EXPECT_FALSE(s.expectSolvable);
    }
  }
}

TEST(Scenes, OverhangRobotPassesOnlyWithItsPlateOverTheLowWall) {
  const Scene& s = scene("overhang");
  const Mesh& robot = s.robot;
  const std::uint32_t plate = componentWithTop(robot, 0.875);
  const std::uint32_t base = componentWithTop(robot, 0.5);
  const double plateBottom = robot.componentBounds()[plate].min().z();
  const double baseTop = robot.componentBounds()[base].max().z();
  const std::uint32_t lowWall = componentWithTop(s.world, 0.375);
  const double lowWallTop = s.world.componentBounds()[lowWall].max().z();
  EXPECT_LT(lowWallTop, plateBottom);
  EXPECT_GT(lowWallTop, 0);
  EXPECT_GT(baseTop, lowWallTop);
  // Plate overhangs the base.
  EXPECT_FALSE(robot.componentBounds()[base].contains(robot.componentBounds()[plate]));

  // The partition's openings along x = 0: at the base's heights (below the low
  // wall's top) and at the plate's heights.
  const double atFloor = longestOpening(s.world, {0, -3}, {0, 5}, {0.125, 0.25});
  const double atPlate = longestOpening(s.world, {0, -3}, {0, 5}, {0.6875, 0.8125});
  const double baseWidth = minimumWidth(componentVertices(robot, base));
  const double plateWidth = minimumWidth(componentVertices(robot, plate));
  EXPECT_EQ(atFloor, 1.25);
  EXPECT_EQ(atPlate, 2.75);
  EXPECT_LT(baseWidth, atFloor);
  EXPECT_GT(plateWidth, atFloor) << "the plate cannot use the door alone";
  EXPECT_LT(plateWidth, atPlate);
}

TEST(Scenes, TurnAroundCorridorIsTooNarrowToTurnIn) {
  const Scene& s = scene("turn_around");
  const Pose2& start = s.problem.start;
  const Pose2& goal = s.problem.goal;
  EXPECT_EQ(goal.x, start.x);
  EXPECT_EQ(goal.y, start.y);
  EXPECT_NEAR(std::abs(goal.theta - start.theta), M_PI, 1e-15);
  const double corridor = longestOpening(s.world, {start.x, -1.5}, {start.x, 1.5}, {0.25});
  const Box3 robot = s.robot.bounds();
  EXPECT_EQ(corridor, 1.75);
  EXPECT_LT(robot.sizes().y(), corridor) << "fits lengthwise";
  EXPECT_GT(robot.sizes().x(), corridor) << "cannot stand across";
}

TEST(Scenes, RandomPolyhedraAreNonConvexAndAtSeveralHeights) {
  const Mesh& world = scene("random_polyhedra").world;
  std::set<double> bottoms;
  int nonConvex = 0;
  for (std::uint32_t c = 1; c < world.componentCount(); ++c) {  // component 0: the room
    bottoms.insert(world.componentBounds()[c].min().z());
    nonConvex += nonConvexPrism(world, c);
  }
  EXPECT_EQ(nonConvex, 16);
  EXPECT_GE(bottoms.size(), 2u);
  EXPECT_GT(world.bounds().max().z(), scene("random_polyhedra").robot.bounds().max().z()) << "some above the robot";
}

TEST(Scenes, RandomScenesDependOnTheSeedOnly) {
  for (const std::string name : {"maze", "random_polyhedra", "tetra_floorplan", "soup_maze"}) {
    EXPECT_EQ(canonicalTriangles(makeScene(name, 7).world), canonicalTriangles(makeScene(name, 7).world)) << name;
    EXPECT_NE(canonicalTriangles(makeScene(name, 7).world), canonicalTriangles(makeScene(name, 8).world)) << name;
  }
}

TEST(Scenes, MazeStaysSmall) { EXPECT_LE(scene("maze").world.triangles().size(), 3000u); }

TEST(Scenes, TetraFloorplanFamilyScalesWithTheRoomCount) {
  std::size_t previous = 0;
  for (unsigned rooms : {1u, 5u, 12u, 40u}) {
    const Scene s = makeScene("tetra_floorplan_" + std::to_string(rooms));
    EXPECT_EQ(s.name, "tetra_floorplan_" + std::to_string(rooms));
    EXPECT_EQ(genus(s.world), 1) << rooms << " rooms: all rooms joined, none open to the outside";
    EXPECT_GT(s.world.triangles().size(), previous);
    previous = s.world.triangles().size();
  }
  EXPECT_EQ(canonicalTriangles(makeScene("tetra_floorplan_8").world),
            canonicalTriangles(makeScene("tetra_floorplan").world));
}

TEST(Scenes, HouseMixedFamilyPutsTheHouseAmongWallsOfThreeHeights) {
  const Scene s = makeScene("house_mixed_9");
  EXPECT_EQ(s.name, "house_mixed_9");
  EXPECT_EQ(s.robot.triangles().size(), 14u);
  std::set<double> tops;
  for (const Point3& v : s.world.vertices()) tops.insert(v.z());
  EXPECT_EQ(tops, (std::set<double>{0, 0.375, 0.75, 1.25}));
  EXPECT_NE(s.problem.start.x, s.problem.goal.x);
}

TEST(Scenes, BenchmarkRobotsHaveTheirFacetCountsAndVolumes) {
  const Mesh house = makeHouseRobot();
  EXPECT_EQ(house.triangles().size(), 14u);
  // Box 0.75 x 0.75 x 0.5 and a pyramid of height 0.375 on it.
  EXPECT_DOUBLE_EQ(house.volume(), 0.75 * 0.75 * 0.5 + 0.75 * 0.75 * 0.375 / 3);
  for (unsigned teeth = 1; teeth <= 4; ++teeth) {
    const Mesh fishbone = makeFishboneRobot(teeth);
    EXPECT_EQ(fishbone.triangles().size(), 32 * teeth - 20) << teeth << " teeth";
    // Teeth 0.125 x 0.75, the spine 0.25 wide between them, all 0.5 high.
    EXPECT_DOUBLE_EQ(fishbone.volume(), (teeth * 0.125 * 0.75 + (teeth - 1) * 0.125 * 0.25) * 0.5);
  }
  EXPECT_THROW(makeFishboneRobot(0), std::invalid_argument);
}

TEST(Scenes, FloorPlanWallsTakeEachOfSeveralHeights) {
  FloorPlanLayout layout;
  layout.rooms = 9;
  layout.columns = 3;
  layout.wallHeights = {0.375, 0.75, 1.25};
  const Mesh walls = makeCheckedMesh(makeFloorPlan(layout, 3).walls, "walls");
  std::set<double> tops;
  for (const Point3& v : walls.vertices()) tops.insert(v.z());
  EXPECT_EQ(tops, (std::set<double>{0, 0.375, 0.75, 1.25}));
  // One wall height: the same floor plan as without the list.
  layout.wallHeights = {layout.wallHeight};
  FloorPlanLayout single = layout;
  single.wallHeights.clear();
  EXPECT_EQ(canonicalTriangles(makeCheckedMesh(makeFloorPlan(layout, 3).walls, "a")),
            canonicalTriangles(makeCheckedMesh(makeFloorPlan(single, 3).walls, "b")));
}

TEST(Scenes, NamesAreChecked) {
  EXPECT_TRUE(isSceneName("maze"));
  EXPECT_TRUE(isSceneName("tetra_floorplan_12"));
  EXPECT_TRUE(isSceneName("house_mixed_160"));
  EXPECT_FALSE(isSceneName("house_mixed_"));
  EXPECT_FALSE(isSceneName("tetra_floorplan_"));
  EXPECT_FALSE(isSceneName("tetra_floorplan_x"));
  EXPECT_FALSE(isSceneName("labyrinth"));
  EXPECT_THROW(makeScene("labyrinth"), std::invalid_argument);
}

// ---------------------------------------------------------------------------------
// Primitives

TEST(Primitives, ExtrudedNonConvexPolygonIsClosedWithItsVolume) {
  const Polygon2 comb{{0, 0},    {3, 0},    {3, 2},      {2.5, 2},   {2.5, 0.5}, {1.75, 0.5},
                      {1.75, 2}, {1.25, 2}, {1.25, 0.5}, {0.5, 0.5}, {0.5, 2},   {0, 2}};
  // Area: the 3 x 0.5 spine plus three 0.5 wide, 1.5 high teeth. Either orientation
  // gives an outward surface (makeCheckedMesh rejects any repair).
  const Mesh clockwise = makeCheckedMesh(extrudePolygon(Polygon2(comb.rbegin(), comb.rend()), 1, 1.5), "comb");
  const Mesh counterClockwise = makeCheckedMesh(extrudePolygon(comb, 1, 1.5), "comb");
  EXPECT_EQ(counterClockwise.volume(), (1.5 + 3 * 0.75) * 0.5);
  EXPECT_EQ(clockwise.volume(), counterClockwise.volume());
  EXPECT_EQ(counterClockwise.vertices().size(), 2 * comb.size()) << "no vertex added";
}

TEST(Primitives, CornersOnStraightEdgesAreKept) {
  // A square with extra corners in the middle of two edges, as walls meeting in a
  // T give: the caps must use them, or the sides would have T-junctions.
  const Polygon2 square{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 1}};
  const Mesh prism = makeCheckedMesh(extrudePolygon(square, 0, 1), "square");
  EXPECT_EQ(prism.vertices().size(), 12u);
  EXPECT_EQ(prism.triangles().size(), 2 * 6 + 2 * 4u);
  EXPECT_EQ(prism.volume(), 4);
}

TEST(Primitives, RectangleUnionEnclosingARegionIsARing) {
  const std::vector<Box2> frame = roomWallRectangles(Box2(Point2(0, 0), Point2(4, 3)), 0.5);
  const Mesh ring = makeCheckedMesh(extrudeRectangleUnion(frame, 0, 2), "ring");
  EXPECT_EQ(ring.componentCount(), 1u);
  EXPECT_EQ(genus(ring), 1);
  EXPECT_DOUBLE_EQ(ring.volume(), (5 * 4 - 4 * 3) * 2.0);
  EXPECT_EQ(ring.vertices().size(), 16u) << "only the corners of the two outlines";
}

TEST(Primitives, RectangleUnionOfNestedRingsHasOneComponentPerRing) {
  std::vector<Box2> rectangles = roomWallRectangles(Box2(Point2(0, 0), Point2(10, 10)), 1);
  const std::vector<Box2> inner = roomWallRectangles(Box2(Point2(3, 3), Point2(7, 7)), 1);
  rectangles.insert(rectangles.end(), inner.begin(), inner.end());
  rectangles.emplace_back(Point2(4.5, 4.5), Point2(5.5, 5.5));  // an island in the inner ring
  const Mesh nested = makeCheckedMesh(extrudeRectangleUnion(rectangles, 0, 1), "nested rings");
  EXPECT_EQ(nested.componentCount(), 3u);
  EXPECT_EQ(genus(nested), 2);
  EXPECT_DOUBLE_EQ(nested.volume(), (144 - 100) + (36 - 16) + 1);
}

namespace {

/// Rectangles on a 16 x 16 raster of half-unit cells, and what their union should be,
/// found on the raster by flood fills: an independent check of the outlines, holes
/// and cap triangulations of extrudeRectangleUnion.
class RasterUnion {
 public:
  static constexpr int kCells = 16;
  static constexpr double kCell = 0.5;

  explicit RasterUnion(const std::vector<Box2>& rectangles) {
    for (const Box2& r : rectangles) {
      for (int i = cellIndex(r.min().x()); i < cellIndex(r.max().x()); ++i) {
        for (int j = cellIndex(r.min().y()); j < cellIndex(r.max().y()); ++j) filled_[i + 1][j + 1] = true;
      }
    }
  }

  int cellCount() const {
    int count = 0;
    for (const auto& column : filled_) count += static_cast<int>(std::count(column.begin(), column.end(), true));
    return count;
  }

  /// Two filled cells meeting only at a corner.
  bool touchesAtACorner() const {
    for (int i = 0; i + 1 < kPadded; ++i) {
      for (int j = 0; j + 1 < kPadded; ++j) {
        const bool a = filled_[i][j], b = filled_[i + 1][j], c = filled_[i][j + 1], d = filled_[i + 1][j + 1];
        if ((a && d && !b && !c) || (b && c && !a && !d)) return true;
      }
    }
    return false;
  }

  /// Connected regions of filled (or empty) cells through shared sides; the empty
  /// region around everything counts too.
  int regions(bool filled) const {
    std::array<std::array<bool, kPadded>, kPadded> seen{};
    int count = 0;
    for (int i = 0; i < kPadded; ++i) {
      for (int j = 0; j < kPadded; ++j) {
        if (filled_[i][j] != filled || seen[i][j]) continue;
        ++count;
        std::vector<std::pair<int, int>> stack{{i, j}};
        seen[i][j] = true;
        while (!stack.empty()) {
          const auto [x, y] = stack.back();
          stack.pop_back();
          for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= kPadded || v >= kPadded || seen[u][v] || filled_[u][v] != filled) continue;
            seen[u][v] = true;
            stack.emplace_back(u, v);
          }
        }
      }
    }
    return count;
  }

 private:
  static constexpr int kPadded = kCells + 2;  // an empty border all around
  static int cellIndex(double coordinate) { return static_cast<int>(std::lround(coordinate / kCell)); }

  std::array<std::array<bool, kPadded>, kPadded> filled_{};
};

}  // namespace

TEST(Primitives, RandomRectangleUnionsMatchTheirRaster) {
  std::mt19937 random(2024);
  int checkedUnions = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<Box2> rectangles;
    const int count = 1 + static_cast<int>(random() % 12);
    for (int k = 0; k < count; ++k) {
      const int x0 = static_cast<int>(random() % 15), y0 = static_cast<int>(random() % 15);
      const int x1 = x0 + 1 + static_cast<int>(random() % (16 - x0)),
                y1 = y0 + 1 + static_cast<int>(random() % (16 - y0));
      rectangles.emplace_back(Point2(x0, y0) * RasterUnion::kCell,
                              Point2(std::min(x1, 16), std::min(y1, 16)) * RasterUnion::kCell);
    }
    const RasterUnion raster(rectangles);
    if (raster.touchesAtACorner()) {
      EXPECT_THROW(extrudeRectangleUnion(rectangles, 0, 1), std::invalid_argument) << "trial " << trial;
      continue;
    }
    const Mesh mesh = makeCheckedMesh(extrudeRectangleUnion(rectangles, 0, 1), "union");
    EXPECT_EQ(mesh.volume(), raster.cellCount() * RasterUnion::kCell * RasterUnion::kCell) << "trial " << trial;
    EXPECT_EQ(static_cast<int>(mesh.componentCount()), raster.regions(true)) << "trial " << trial;
    EXPECT_EQ(genus(mesh), raster.regions(false) - 1) << "trial " << trial << ": one hole per enclosed region";
    ++checkedUnions;
  }
  EXPECT_GT(checkedUnions, 200);
}

TEST(Primitives, RectanglesTouchingOnlyAtACornerAreRejected) {
  const std::vector<Box2> corner{Box2(Point2(0, 0), Point2(1, 1)), Box2(Point2(1, 1), Point2(2, 2))};
  EXPECT_THROW(extrudeRectangleUnion(corner, 0, 1), std::invalid_argument);
}

TEST(Primitives, WallOpeningsAreCutOut) {
  const std::vector<Box2> wall = wallRectangles({0, 0}, {10, 0}, 0.5, {{2, 3}, {6, 8}});
  ASSERT_EQ(wall.size(), 3u);
  EXPECT_EQ(wall[0].min(), Point2(-0.25, -0.25));
  EXPECT_EQ(wall[0].max(), Point2(2, 0.25));
  EXPECT_EQ(wall[1].min().x(), 3);
  EXPECT_EQ(wall[2].max().x(), 10.25);
  EXPECT_THROW(wallRectangles({0, 0}, {1, 1}, 0.5), std::invalid_argument);
}

TEST(Primitives, TableIsOneOutwardSolid) {
  const Mesh table = makeCheckedMesh(makeTable(Box2(Point2(0, 0), Point2(2, 1)), 0.25, 0.5, 0.75), "table");
  EXPECT_EQ(table.componentCount(), 1u);
  EXPECT_DOUBLE_EQ(table.volume(), (2 * 0.25 + 2 * 0.25 * 0.5) * 1);
  EXPECT_EQ(table.bounds().max(), Point3(2, 1, 0.75));
}

TEST(Primitives, StarObstaclesAreNonConvexAndStayInTheirDiscs) {
  const std::vector<Point2> centres{{0, 0}, {3, 0}, {0, 3}, {3, 3}};
  const Mesh stars = makeCheckedMesh(makeStarObstacles(centres, 1, 2, 11), "stars");
  ASSERT_EQ(stars.componentCount(), centres.size());
  for (std::uint32_t c = 0; c < stars.componentCount(); ++c) {
    const std::vector<Point3> vertices = componentVertices(stars, c);
    const Box3& bounds = stars.componentBounds()[c];
    const Point2 middle = bounds.center().head<2>();
    const Point2 centre = *std::min_element(centres.begin(), centres.end(), [&](const Point2& a, const Point2& b) {
      return (a - middle).norm() < (b - middle).norm();
    });
    for (const Point3& v : vertices) EXPECT_LE((v.head<2>() - centre).norm(), 1.0);
    EXPECT_GE(bounds.min().z(), 0);
    EXPECT_LE(bounds.max().z(), 2);
    EXPECT_TRUE(nonConvexPrism(stars, c));
  }
  EXPECT_THROW(makeStarObstacles({{0, 0}, {1.5, 0}}, 1, 2, 1), std::invalid_argument);
}

// ---------------------------------------------------------------------------------
// Mesh writer

TEST(MeshWriter, EveryFormatRoundTripsExactly) {
  const TempDir dir;
  const std::vector<std::pair<std::string, const Mesh*>> meshes{{"maze_world", &scene("maze").world},
                                                                {"overhang_robot", &scene("overhang").robot},
                                                                {"stars", &scene("random_polyhedra").world},
                                                                {"tetrahedron", &scene("tetra_floorplan").robot}};
  for (const std::string format : {"obj", "stl", "ply", "off", "dae", "vtk"}) {
    for (const auto& [name, mesh] : meshes) {
      const std::string path = dir.file(name + "." + format);
      writeMesh(*mesh, path);
      const Mesh read = loadMesh(path);
      EXPECT_EQ(canonicalTriangles(read), canonicalTriangles(*mesh)) << path;
      EXPECT_EQ(read.volume(), mesh->volume()) << path;
      EXPECT_EQ(read.componentCount(), mesh->componentCount()) << path;
    }
  }
}

TEST(MeshWriter, ObjIsWrittenWithoutAMaterialFile) {
  const TempDir dir;
  writeMesh(scene("cage").robot, dir.file("robot.obj"));
  EXPECT_TRUE(std::filesystem::exists(dir.file("robot.obj")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("robot.mtl")));
  EXPECT_EQ(readWholeFile(dir.file("robot.obj")).find("mtllib"), std::string::npos);
}

TEST(MeshWriter, RefusesToOverwriteUnlessAsked) {
  const TempDir dir;
  const std::string path = dir.file("box.stl");
  writeMesh(scene("keyhole").robot, path);
  try {
    writeMesh(scene("cage").robot, path);
    FAIL() << "overwrote " << path;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_NE(error.problem().find("already exists"), std::string::npos) << error.what();
  }
  EXPECT_EQ(canonicalTriangles(loadMesh(path)), canonicalTriangles(scene("keyhole").robot));
  writeMesh(scene("cage").robot, path, true);
  EXPECT_EQ(canonicalTriangles(loadMesh(path)), canonicalTriangles(scene("cage").robot));
}

TEST(MeshWriter, ReportsUnwritableFilesAndUnknownFormats) {
  const TempDir dir;
  for (const std::string& path : {dir.file("missing/folder/mesh.vtk"), dir.file("missing/folder/mesh.obj")}) {
    try {
      writeMesh(scene("cage").robot, path);
      FAIL() << "wrote " << path;
    } catch (const InputError& error) {
      EXPECT_NE(error.problem().find("cannot write"), std::string::npos) << error.what();
    }
  }
  EXPECT_THROW(writeMesh(scene("cage").robot, dir.file("mesh.xyz")), InputError);
}

// ---------------------------------------------------------------------------------
// Writing scenes

TEST(WriteScene, WritesMeshesAndAProblemThatLoadBack) {
  const TempDir dir;
  const Scene& s = scene("overhang");
  const std::string cfg = writeScene(s, dir.file("scenes"), "dae");
  EXPECT_EQ(cfg, dir.file("scenes/overhang.cfg"));
  const LoadedProblem loaded = loadProblem(cfg);
  EXPECT_EQ(loaded.problem.robot, "overhang_robot.dae");
  EXPECT_EQ(loaded.problem.world, "overhang_world.dae");
  EXPECT_EQ(loaded.problem.start.x, s.problem.start.x);
  EXPECT_EQ(loaded.problem.start.theta, s.problem.start.theta);
  EXPECT_EQ(loaded.problem.goal.y, s.problem.goal.y);
  EXPECT_EQ(loaded.problem.volume->min(), s.problem.volume->min());
  EXPECT_EQ(loaded.problem.planners, s.problem.planners);
  EXPECT_EQ(loaded.robotCentre, Point3::Zero()) << "OMPL.app's re-centring leaves the robot in place";
  EXPECT_EQ(canonicalTriangles(loaded.robot), canonicalTriangles(s.robot));
  EXPECT_EQ(canonicalTriangles(loaded.world), canonicalTriangles(s.world));

  EXPECT_THROW(writeScene(s, dir.file("scenes"), "dae"), InputError);
  EXPECT_NO_THROW(writeScene(s, dir.file("scenes"), "dae", true));
}

TEST(WriteScene, RenamedSceneWritesUnderTheNewName) {
  const TempDir dir;
  const Scene renamed = renamedScene(scene("cage"), "cage_copy");
  writeScene(renamed, dir.file(""), "ply");
  const PlanarProblem problem = readProblem(dir.file("cage_copy.cfg"));
  EXPECT_EQ(problem.name, "cage_copy");
  EXPECT_EQ(problem.robot, "cage_copy_robot.ply");
  EXPECT_TRUE(std::filesystem::exists(dir.file("cage_copy_world.ply")));
}

// ---------------------------------------------------------------------------------
// Command line

TEST(GenerateCommand, WritesTheChosenScenesAndRejectsUnknownNames) {
  if (!std::filesystem::exists(FREESPACE_CLI)) GTEST_SKIP() << "command line tool not built";
  const TempDir dir;
  const CommandResult written =
      runFreespace("generate --out '" + dir.file("out") + "' --scene cage keyhole --format stl");
  ASSERT_EQ(written.status, 0) << written.err;
  EXPECT_NE(written.out.find("cage.cfg"), std::string::npos) << written.out;
  EXPECT_NE(written.out.find("keyhole.cfg"), std::string::npos) << written.out;
  EXPECT_TRUE(std::filesystem::exists(dir.file("out/keyhole_world.stl")));

  const CommandResult again = runFreespace("generate --out '" + dir.file("out") + "' --scene cage");
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;
  EXPECT_EQ(runFreespace("generate --out '" + dir.file("out") + "' --scene cage --force").status, 0);

  const CommandResult unknown = runFreespace("generate --out '" + dir.file("out") + "' --scene labyrinth");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("labyrinth"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("turn_around"), std::string::npos) << "lists the valid names: " << unknown.err;
}
