// Robots for the test scenes. OMPL.app turns a robot about the average of its
// vertices, so each robot is moved to put that average at x = y = 0; the shapes are
// chosen so that the average lies on the scene grid and the move is exact.

#include <cmath>
#include <set>
#include <stdexcept>
#include <tuple>

#include "freespace/scenes/scene_generator.h"
#include "freespace/scenes/soup_variants.h"

namespace freespace {
namespace {

bool onSceneGrid(double value) { return std::floor(value / kSceneGrid) == value / kSceneGrid; }

Mesh centredRobot(const TriangleSoup& soup, const std::string& name) {
  std::set<std::tuple<double, double, double>> distinct;
  for (const Point3& v : soup.vertices) distinct.emplace(v.x(), v.y(), v.z());
  double sumX = 0;
  double sumY = 0;
  for (const auto& [x, y, z] : distinct) {
    sumX += x;
    sumY += y;
  }
  const auto count = static_cast<double>(distinct.size());
  const Point2 average(sumX / count, sumY / count);
  if (average.x() * count != sumX || average.y() * count != sumY || !onSceneGrid(average.x()) ||
      !onSceneGrid(average.y())) {
    throw std::invalid_argument(name + ": the average of its vertices is not on the scene grid");
  }
  return makeCheckedMesh(translateSoup(soup, Point3(-average.x(), -average.y(), 0)), name);
}

}  // namespace

Mesh makeBarRobot(double length, double width, double height) {
  return centredRobot(makeBox(Box3(Point3(0, 0, 0), Point3(length, width, height))), "bar robot");
}

Mesh makeLRobot(double height) {
  const Polygon2 outline{{0, 0}, {1.75, 0}, {1.75, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}};
  return centredRobot(extrudePolygon(outline, 0, height), "L robot");
}

Mesh makeTRobot(double height) {
  const Polygon2 outline{{-2, -0.25}, {0.5, -0.25}, {0.5, -0.75}, {1, -0.75},
                         {1, 0.75},   {0.5, 0.75},  {0.5, 0.25},  {-2, 0.25}};
  return centredRobot(extrudePolygon(outline, 0, height), "T robot");
}

Mesh makeURobot(double height) {
  const Polygon2 outline{{-1.5, -0.75}, {1, -0.75}, {1, -0.25}, {-0.5, -0.25},
                         {-0.5, 0.25},  {1, 0.25},  {1, 0.75},  {-1.5, 0.75}};
  return centredRobot(extrudePolygon(outline, 0, height), "U robot");
}

Mesh makeTetrahedronRobot() {
  TriangleSoup soup;
  soup.vertices = {{0.5, 0, 0}, {-0.25, 0.4375, 0}, {-0.25, -0.4375, 0}, {0, 0, 0.75}};
  soup.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  return centredRobot(soup, "tetrahedron robot");
}

Mesh makeHouseRobot() {
  const double a = 0.375, eaves = 0.5, apex = 0.875;
  TriangleSoup soup;
  soup.vertices = {{-a, -a, 0},     {a, -a, 0},     {a, a, 0},     {-a, a, 0},   {-a, -a, eaves},
                   {a, -a, eaves}, {a, a, eaves}, {-a, a, eaves}, {0, 0, apex}};
  soup.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7},
                    {2, 7, 6}, {3, 0, 4}, {3, 4, 7}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}};
  return centredRobot(soup, "house robot");
}

Mesh makeFishboneRobot(unsigned teeth) {
  if (teeth == 0) throw std::invalid_argument("fishbone robot: needs a tooth");
  const double tooth = 0.125, spine = 0.125, reach = 0.375;
  // Along y < 0 from left to right, the teeth and the notches between them; the
  // side y > 0 is its mirror image, walked back.
  Polygon2 lower;
  for (unsigned i = 0; i < teeth; ++i) {
    const double x = 2 * tooth * i;
    if (i > 0) lower.push_back({x, -spine});
    lower.push_back({x, -reach});
    lower.push_back({x + tooth, -reach});
    if (i + 1 < teeth) lower.push_back({x + tooth, -spine});
  }
  Polygon2 outline = lower;
  for (auto corner = lower.rbegin(); corner != lower.rend(); ++corner) outline.push_back({corner->x(), -corner->y()});
  return centredRobot(extrudePolygon(outline, 0, 0.5), "fishbone robot");
}

Mesh makeOverhangRobot() {
  const TriangleSoup base = makeBox(Box3(Point3(-0.5, -0.5, 0), Point3(0.5, 0.5, 0.5)));
  const TriangleSoup plate = makeBox(Box3(Point3(-1, -0.5, 0.625), Point3(1, 1.5, 0.875)));
  return centredRobot(joinParts({base, plate}), "overhang robot");
}

SoupRobot makeGluedCarRobot(double height) {
  const Polygon2 outline{{-0.75, -0.375}, {0, -0.375}, {0.75, -0.375}, {0.75, 0.375}, {0, 0.375}, {-0.75, 0.375}};
  const TriangleSoup soup = doubleSided(gluedPrisms(outline, 0, height));
  Point3 sum = Point3::Zero();
  for (const Point3& v : soup.vertices) sum += v;
  if (sum.x() != 0 || sum.y() != 0) {
    throw std::logic_error("glued car robot: its triangulation is not symmetric, so its vertices are off centre");
  }
  return {soup, makeCheckedMesh(extrudePolygon(outline, 0, height), "glued car robot")};
}

}  // namespace freespace
