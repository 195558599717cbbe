// Repair and solid interpretation of triangle soups, checked against independent
// oracles: the union of the boxes a soup was made from (membership by coordinates,
// volume by inclusion and exclusion), and the winding number of the result's
// surface at random points (a solid angle sum in doubles, nothing of the code under
// test).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>

#include "freespace/geometry/mesh_preparation.h"
#include "freespace/input_error.h"
#include "test_meshes.h"

namespace freespace {
namespace {

using testing::boxSoup;
using testing::joinSoups;

constexpr double kPi = 3.14159265358979323846;

// Every triangle followed by its reversed copy, as modelling tools export.
TriangleSoup doubleSided(const TriangleSoup& soup) {
  TriangleSoup result{soup.vertices, {}};
  for (const TriangleIndices& t : soup.triangles) {
    result.triangles.push_back(t);
    result.triangles.push_back({t[0], t[2], t[1]});
  }
  return result;
}

// The soup without the triangles whose corners all have coordinate `axis` equal to
// `value` (a face left out).
TriangleSoup withoutFace(TriangleSoup soup, int axis, double value) {
  soup.triangles.erase(std::remove_if(soup.triangles.begin(), soup.triangles.end(),
                                      [&](const TriangleIndices& t) {
                                        return std::all_of(t.begin(), t.end(), [&](std::uint32_t v) {
                                          return soup.vertices[v][axis] == value;
                                        });
                                      }),
                       soup.triangles.end());
  return soup;
}

// The winding number of a closed oriented surface around p: the sum of the solid
// angles of its triangles (Van Oosterom and Strackee's formula) over 4 pi.
double windingNumber(const Mesh& mesh, const Point3& p) {
  double total = 0;
  for (const TriangleIndices& t : mesh.triangles()) {
    const Point3 a = mesh.vertices()[t[0]] - p, b = mesh.vertices()[t[1]] - p, c = mesh.vertices()[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total / (4 * kPi);
}

bool insideMesh(const Mesh& mesh, const Point3& p) { return std::abs(windingNumber(mesh, p)) > 0.5; }

bool insideBoxes(const std::vector<Box3>& boxes, const Point3& p) {
  return std::any_of(boxes.begin(), boxes.end(), [&](const Box3& box) { return box.contains(p); });
}

// The mesh and the union of the boxes contain the same random points (away from the
// boxes' faces, where the two could disagree by rounding).
void expectSameSolid(const Mesh& mesh, const std::vector<Box3>& boxes, unsigned seed) {
  Box3 bounds;
  for (const Box3& box : boxes) bounds.extend(box);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-0.1, 1.1);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Point3 p = bounds.min() + (bounds.max() - bounds.min()).cwiseProduct(Point3(unit(random), unit(random), unit(random)));
    const bool nearFace = std::any_of(boxes.begin(), boxes.end(), [&](const Box3& box) {
      return (p - box.min()).cwiseAbs().minCoeff() < 1e-6 || (p - box.max()).cwiseAbs().minCoeff() < 1e-6;
    });
    if (nearFace) continue;
    EXPECT_EQ(insideMesh(mesh, p), insideBoxes(boxes, p)) << "at " << p.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 1900);
}

Mesh prepared(const TriangleSoup& soup, PreparationReport* report = nullptr, std::vector<std::string>* warnings = nullptr,
              bool ignoreOpen = false) {
  PreparationSettings settings;
  settings.solid.ignoreOpen = ignoreOpen;
  return prepareMesh(soup, "soup", settings, report, warnings);
}

std::string errorOf(const TriangleSoup& soup) {
  try {
    prepared(soup);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

Box3 box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return Box3(Point3(x0, y0, z0), Point3(x1, y1, z1));
}

TriangleSoup soupOf(const Box3& b) { return boxSoup(b.min(), b.max()); }

}  // namespace

TEST(SolidInterpretation, ADoubleSidedCubeIsTheCube) {
  PreparationReport report;
  const Mesh mesh = prepared(doubleSided(soupOf(box(0, 0, 0, 1, 1, 1))), &report);
  EXPECT_EQ(report.repair.reversedDuplicatesDropped, 12u);
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_DOUBLE_EQ(mesh.volume(), 1);
}

TEST(SolidInterpretation, BoxesGluedAlongAWallAreOneSolidWithoutTheWall) {
  // Two boxes sharing the face x = 1 (triangulated alike), double-sided: after the
  // doubles go, the shared face is one internal wall between two enclosed regions.
  const std::vector<Box3> boxes{box(0, 0, 0, 1, 1, 1), box(1, 0, 0, 2, 1, 1)};
  PreparationReport report;
  const Mesh mesh = prepared(doubleSided(joinSoups({soupOf(boxes[0]), soupOf(boxes[1])})), &report);
  EXPECT_EQ(mesh.componentCount(), 1u);
  EXPECT_DOUBLE_EQ(mesh.volume(), 2);
  EXPECT_EQ(report.solid.enclosedRegions, 2u);
  EXPECT_EQ(report.solid.internalTriangles, 2u);
  expectSameSolid(mesh, boxes, 1);
}

TEST(SolidInterpretation, InterpenetratingDoubleSidedBoxesAreTheirUnion) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> corner(0, 6), size(1, 4);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Box3> boxes;
    std::vector<TriangleSoup> soups;
    for (int i = 0; i < 5; ++i) {
      const Point3 low(corner(random), corner(random), corner(random));
      boxes.push_back(Box3(low, low + Point3(size(random), size(random), size(random))));
      soups.push_back(soupOf(boxes.back()));
    }
    const Mesh mesh = prepared(doubleSided(joinSoups(soups)));
    expectSameSolid(mesh, boxes, trial);
  }
}

TEST(SolidInterpretation, CrossingWallsGetNoPointsWhereTheyCrossTheCutsOfEachOthersFaces) {
  // Walls without bottoms (a soup), each face two triangles cut along a diagonal;
  // the other wall crosses the cuts at points such as (4, 4, 4/3), which only the
  // cut makes and doubles cannot hold. The solid's boundary has none of them: every
  // coordinate of its vertices is one of the boxes'.
  const std::vector<Box3> boxes{box(0, 4, 0, 9, 5, 3), box(4, 0, 0, 5, 9, 2)};
  const Mesh mesh =
      prepared(doubleSided(joinSoups({withoutFace(soupOf(boxes[0]), 2, 0), withoutFace(soupOf(boxes[1]), 2, 0)})));
  EXPECT_EQ(mesh.componentCount(), 1u);
  EXPECT_DOUBLE_EQ(mesh.volume(), 27 + 18 - 2);
  const std::array<std::set<double>, 3> coordinates{std::set<double>{0, 4, 5, 9}, std::set<double>{0, 4, 5, 9},
                                                    std::set<double>{0, 2, 3}};
  for (const Point3& vertex : mesh.vertices()) {
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_EQ(coordinates[axis].count(vertex[axis]), 1u) << "vertex " << vertex.transpose();
    }
  }
  expectSameSolid(mesh, boxes, 5);
}

TEST(SolidInterpretation, RandomCrossingWallsWithoutBottomsAreTheirUnion) {
  // Walls standing on z = 0 without their bottom faces (capped), double-sided, cut
  // along their faces' diagonals and crossing one another at random: the seams'
  // crossings are left out where nothing needs them, and the solid stays the union.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> corner(0, 6), length(1, 5), thickness(0.2, 1), height(1, 3);
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<Box3> boxes;
    std::vector<TriangleSoup> soups;
    for (int i = 0; i < 6; ++i) {
      const bool alongX = i % 2 == 0;
      const double x = corner(random), y = corner(random), along = length(random), across = thickness(random);
      boxes.push_back(box(x, y, 0, x + (alongX ? along : across), y + (alongX ? across : along), height(random)));
      soups.push_back(withoutFace(soupOf(boxes.back()), 2, 0));
    }
    const Mesh mesh = prepared(doubleSided(joinSoups(soups)));
    expectSameSolid(mesh, boxes, 20 + trial);
  }
}

TEST(SolidInterpretation, OpenEndedWallsBuriedInOneAnotherCloseTogether) {
  // An L of two walls, each without the end face that lies inside the other: the
  // soup's only closed region is their union.
  const Box3 west = box(0, 0, 0, 1, 6, 2), south = box(0, 0, 0, 6, 1, 2);
  const TriangleSoup soup = joinSoups({withoutFace(soupOf(west), 1, 0), withoutFace(soupOf(south), 0, 0)});
  const Mesh mesh = prepared(doubleSided(soup));
  EXPECT_EQ(mesh.componentCount(), 1u);
  EXPECT_NEAR(mesh.volume(), 12 + 12 - 2, 1e-12);
  expectSameSolid(mesh, {west, south}, 2);
}

TEST(SolidInterpretation, AMissingBottomIsCapped) {
  PreparationReport report;
  const Mesh mesh = prepared(doubleSided(withoutFace(soupOf(box(0, 0, 0, 4, 2, 1)), 2, 0)), &report);
  EXPECT_DOUBLE_EQ(mesh.volume(), 8);
  EXPECT_EQ(report.solid.capTriangles, 2u);
}

TEST(SolidInterpretation, ACourtyardIsNotCapped) {
  // Four walls (1 thick, 2 high) around a 10 x 10 courtyard, each without its top and
  // bottom: caps close each wall, but capping the courtyard's floor and sky would
  // fill it, and caps would make most of its boundary.
  const std::vector<Box3> walls{box(-1, -1, 0, 11, 0, 2), box(-1, 10, 0, 11, 11, 2), box(-1, 0, 0, 0, 10, 2),
                                box(10, 0, 0, 11, 10, 2)};
  std::vector<TriangleSoup> soups;
  for (const Box3& wall : walls) soups.push_back(withoutFace(withoutFace(soupOf(wall), 2, 0), 2, 2));
  const Mesh mesh = prepared(doubleSided(joinSoups(soups)));
  EXPECT_FALSE(insideMesh(mesh, Point3(5, 5, 1)));
  EXPECT_NEAR(mesh.volume(), (2 * 12 + 2 * 10) * 2, 1e-9) << "the walls' union: 44 of area, 2 high";
  expectSameSolid(mesh, walls, 3);
}

TEST(SolidInterpretation, BoxesTouchingAlongAnEdgeStaySeparateComponents) {
  const std::vector<Box3> boxes{box(0, 0, 0, 1, 1, 1), box(1, 1, 0, 2, 2, 1)};
  const Mesh mesh = prepared(doubleSided(joinSoups({soupOf(boxes[0]), soupOf(boxes[1])})));
  EXPECT_EQ(mesh.componentCount(), 2u);
  EXPECT_DOUBLE_EQ(mesh.volume(), 2);
  expectSameSolid(mesh, boxes, 4);
}

TEST(SolidInterpretation, AnOpenSheetIsAnErrorSayingWhereUnlessIgnored) {
  TriangleSoup sheet;
  sheet.vertices = {{5, 0, 0}, {6, 0, 0}, {6, 0, 1}, {5, 0, 1}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
  const TriangleSoup soup = joinSoups({soupOf(box(0, 0, 0, 1, 1, 1)), doubleSided(sheet)});
  EXPECT_EQ(errorOf(soup),
            "soup: 2 triangles enclose nothing (an open sheet, a zero-thickness wall or a crack wider than the "
            "tolerance): no volume lies behind them, between (5, 0, 0) and (6, 0, 1); --ignore-open drops them with "
            "a warning");
  std::vector<std::string> warnings;
  const Mesh mesh = prepared(soup, nullptr, &warnings, true);
  EXPECT_DOUBLE_EQ(mesh.volume(), 1);
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [](const std::string& warning) {
    return warning.find("2 triangles enclose nothing") != std::string::npos &&
           warning.find("dropped (--ignore-open)") != std::string::npos;
  }));
}

TEST(SolidInterpretation, AnOpenSheetBeyondTheOtherBodysHeightsIsDroppedAndReported) {
  // A stray sheet 0.5 under the floor of a unit box: a robot spanning heights [0, 2]
  // can never touch it; one reaching down to -1 can.
  TriangleSoup sheet;
  sheet.vertices = {{0, 0, -0.5}, {1, 0, -0.5}, {1, 1, -0.5}, {0, 1, -0.5}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
  const TriangleSoup soup = joinSoups({soupOf(box(0, 0, 0, 1, 1, 1)), doubleSided(sheet)});
  PreparationSettings settings;
  settings.solid.otherBodyHeights = {{0, 2}};
  PreparationReport report;
  std::vector<std::string> warnings;
  const Mesh mesh = prepareMesh(soup, "soup", settings, &report, &warnings);
  EXPECT_DOUBLE_EQ(mesh.volume(), 1);
  EXPECT_EQ(report.solid.outOfReach.sourceTriangles, 2u);
  EXPECT_EQ(report.solid.open.sourceTriangles, 0u);
  EXPECT_EQ(report.solid.outOfReach.bounds.max().z(), -0.5);
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [](const std::string& warning) {
    return warning.find("soup: 2 triangles that enclose nothing dropped where the other body can never touch them") == 0;
  }));
  settings.solid.otherBodyHeights = {{-1, 2}};
  EXPECT_THROW(prepareMesh(soup, "soup", settings), InputError);
  settings.solid.otherBodyHeights = {{-0.5, 2}};
  EXPECT_THROW(prepareMesh(soup, "soup", settings), InputError) << "a sheet at the other body's lowest height touches it";
}

TEST(SolidInterpretation, ACrackWiderThanTheToleranceIsAnError) {
  // A unit cube torn open along its edge x = 1, z = 1: the top stops at x = 0.999 and
  // the side x = 1 at z = 0.999, so the slot between them bends around the edge and
  // no plane caps it.
  TriangleSoup soup;
  const auto quad = [&soup](const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    const auto first = static_cast<std::uint32_t>(soup.vertices.size());
    soup.vertices.insert(soup.vertices.end(), {a, b, c, d});
    soup.triangles.push_back({first, first + 1, first + 2});
    soup.triangles.push_back({first, first + 2, first + 3});
  };
  quad({0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0});
  quad({0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1});
  quad({0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0});
  quad({0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0});
  quad({0, 0, 1}, {0.999, 0, 1}, {0.999, 1, 1}, {0, 1, 1});
  quad({1, 0, 0}, {1, 1, 0}, {1, 1, 0.999}, {1, 0, 0.999});
  EXPECT_NE(errorOf(soup).find("triangles enclose nothing"), std::string::npos) << errorOf(soup);
}

TEST(SoupRepair, WeldsFloatNoise) {
  // Two unit boxes each without its face at x = 1, glued there; the second box's
  // copies of the seam's corners are 3e-8 off (float noise), 1e-6 of the diagonal is
  // 2.4e-6.
  TriangleSoup soup = joinSoups({withoutFace(soupOf(box(0, 0, 0, 1, 1, 1)), 0, 1),
                                 withoutFace(soupOf(box(1, 0, 0, 2, 1, 1)), 0, 1)});
  for (std::size_t v = 8; v < soup.vertices.size(); ++v) {
    if (soup.vertices[v].x() == 1) soup.vertices[v].y() += 3e-8;
  }
  PreparationReport report;
  const Mesh mesh = prepared(soup, &report);
  EXPECT_EQ(report.repair.pointsWelded, 4u);
  EXPECT_NEAR(report.repair.largestWeldDistance, 3e-8, 1e-15);
  EXPECT_EQ(report.solid.soupTriangles, 0u) << "welded, the two open boxes make one closed surface";
  EXPECT_EQ(mesh.componentCount(), 1u);
  EXPECT_DOUBLE_EQ(mesh.volume(), 2);
}

TEST(SoupRepair, SnapsTJunctions) {
  // A 2 x 1 x 1 bar whose sides and bottom are split at x = 1 but whose top is one
  // quad: the corners (1, 0, 1) and (1, 1, 1) lie inside the top's long edges.
  TriangleSoup soup;
  for (int x = 0; x <= 2; ++x) {
    for (int y = 0; y <= 1; ++y) {
      for (int z = 0; z <= 1; ++z) soup.vertices.emplace_back(x, y, z);
    }
  }
  const auto at = [](int x, int y, int z) { return static_cast<std::uint32_t>(4 * x + 2 * y + z); };
  const auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    soup.triangles.push_back({a, b, c});
    soup.triangles.push_back({a, c, d});
  };
  for (int x = 0; x < 2; ++x) {
    quad(at(x, 0, 0), at(x, 1, 0), at(x + 1, 1, 0), at(x + 1, 0, 0));  // bottom
    quad(at(x, 0, 0), at(x + 1, 0, 0), at(x + 1, 0, 1), at(x, 0, 1));  // front
    quad(at(x, 1, 0), at(x, 1, 1), at(x + 1, 1, 1), at(x + 1, 1, 0));  // back
  }
  quad(at(0, 0, 0), at(0, 0, 1), at(0, 1, 1), at(0, 1, 0));
  quad(at(2, 0, 0), at(2, 1, 0), at(2, 1, 1), at(2, 0, 1));
  quad(at(0, 0, 1), at(2, 0, 1), at(2, 1, 1), at(0, 1, 1));  // top, one quad
  PreparationReport report;
  const Mesh mesh = prepared(soup, &report);
  EXPECT_EQ(report.repair.verticesSnapped, 2u);
  EXPECT_EQ(report.repair.trianglesSplit, 2u);
  EXPECT_EQ(report.solid.soupTriangles, 0u) << "snapped, the bar is one closed oriented surface";
  EXPECT_DOUBLE_EQ(mesh.volume(), 2);
}

TEST(SoupRepair, AClosedSurfaceWithNothingToRepairIsKeptAsItIs) {
  const TriangleSoup soup = joinSoups({soupOf(box(0, 0, 0, 1, 1, 1)), soupOf(box(2, 0, 0, 3, 1, 1))});
  PreparationReport report;
  std::vector<std::string> warnings;
  const Mesh mesh = prepared(soup, &report, &warnings);
  EXPECT_TRUE(report.changes().empty());
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(report.solid.closedComponents, 2u);
  EXPECT_EQ(report.repair.outputVertices, 16u);
  EXPECT_EQ(mesh.vertices(), soup.vertices);
  EXPECT_EQ(mesh.triangles(), soup.triangles);
}

TEST(SoupRepair, FloatNoiseOnAClosedSurfaceIsSnapped) {
  TriangleSoup soup = soupOf(box(0, 0, 0, 1, 1, 1));
  for (Point3& vertex : soup.vertices) {
    if (vertex == Point3(1, 1, 1)) vertex.x() += 3e-8;
  }
  PreparationReport report;
  const Mesh mesh = prepared(soup, &report);
  EXPECT_EQ(report.repair.coordinatesSnapped, 1u);
  for (const Point3& vertex : mesh.vertices()) EXPECT_TRUE(vertex.x() == 0 || vertex.x() == 1) << vertex.transpose();
}

TEST(SoupRepair, AnInsideOutClosedSurfaceIsTurnedAndReported) {
  TriangleSoup soup = soupOf(box(0, 0, 0, 1, 1, 1));
  for (TriangleIndices& triangle : soup.triangles) std::swap(triangle[1], triangle[2]);
  PreparationReport report;
  const Mesh mesh = prepared(soup, &report);
  EXPECT_EQ(report.solid.trianglesTurned, 12u);
  EXPECT_DOUBLE_EQ(mesh.volume(), 1);
}

TEST(SoupRepair, ClosedSurfacesTouchingAtAVertexGetVerticesOfTheirOwn) {
  const Mesh mesh = prepared(joinSoups({soupOf(box(0, 0, 0, 1, 1, 1)), soupOf(box(1, 1, 1, 2, 2, 2))}));
  EXPECT_EQ(mesh.componentCount(), 2u);
  EXPECT_EQ(mesh.vertices().size(), 16u) << "the shared corner (1, 1, 1) once for each box";
}

TEST(SolidInterpretation, GluedBoxesInsideGluedBoxesAreFoundByRaysAtEveryScale) {
  // Two pairs of boxes glued along a wall (soups: edges used by four triangles), the
  // small pair inside the large one: its outside bounds a hole of the large pair's
  // region, joined to it by a ray, and the small pair's volume is counted once. The
  // rays meet boxes in doubles, at any scale (Boost.Geometry's segment test missed
  // boxes of models 1e-20 across); where doubles cannot hold a rounded ray (normals
  // beyond the largest double), every face is tried.
  const std::vector<Box3> boxes{box(0, 0, 0, 4, 4, 4), box(4, 0, 0, 5, 4, 4), box(1, 1, 1, 2, 2, 2),
                                box(2, 1, 1, 3, 2, 2)};
  std::vector<TriangleSoup> soups;
  for (const Box3& b : boxes) soups.push_back(soupOf(b));
  const TriangleSoup unit = joinSoups(soups);
  PreparationReport report;
  const double volume = prepared(unit, &report).volume();
  EXPECT_DOUBLE_EQ(volume, 4 * 4 * 4 + 4 * 4) << "the small pair is enclosed: part of the solid";
  EXPECT_EQ(report.solid.enclosedRegions, 4u);
  for (const double scale : {1e-60, 1e-20, 1e20, 1e60}) {
    SCOPED_TRACE(scale);
    TriangleSoup scaled = unit;
    for (Point3& vertex : scaled.vertices) vertex *= scale;
    EXPECT_NEAR(prepared(scaled).volume() / (scale * scale * scale), volume, 1e-9 * volume);
  }
  TriangleSoup huge = unit;
  for (Point3& vertex : huge.vertices) vertex *= 1e200;  // the diagonal's square overflows, the normals too
  EXPECT_NE(errorOf(huge), "") << "refused as input, not a crash or another exception";
}

}  // namespace freespace
