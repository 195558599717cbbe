// The generator's imitations of modelling tools' triangle soups (soup_variants.h)
// and the scenes written as soups: facts about each soup checked by independent
// computations on its triangles (signed volumes, edge uses after welding identical
// points, areas of unions of rectangles), the solids the scenes show checked against
// volumes worked out from the boxes, and every soup written and read back in every
// format.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "freespace/input_error.h"
#include "freespace/io/mesh_reader.h"
#include "freespace/io/mesh_writer.h"
#include "freespace/scenes/scene_generator.h"
#include "freespace/scenes/soup_variants.h"
#include "temp_dir.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

using Position = std::array<double, 3>;
using Edge = std::pair<Position, Position>;  // ends in increasing order

Position positionOf(const Point3& p) { return {p.x(), p.y(), p.z()}; }

/// The signed volume the triangles enclose, as a sum of tetrahedra from the origin
/// (exact for the generator's coordinates on a coarse grid).
double signedVolume(const TriangleSoup& soup) {
  double sixTimes = 0;
  for (const TriangleIndices& t : soup.triangles) {
    sixTimes += soup.vertices[t[0]].dot(soup.vertices[t[1]].cross(soup.vertices[t[2]]));
  }
  return sixTimes / 6;
}

double polygonArea(const Polygon2& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return std::abs(twice) / 2;
}

/// How many triangles use each edge once identical points are taken as one (in
/// either direction), and how many use it in each direction.
struct EdgeUses {
  std::map<Edge, int> total;
  std::map<Edge, int> forward;  // from the smaller end to the larger

  explicit EdgeUses(const TriangleSoup& soup) {
    for (const TriangleIndices& t : soup.triangles) {
      for (int k = 0; k < 3; ++k) {
        const Position from = positionOf(soup.vertices[t[k]]);
        const Position to = positionOf(soup.vertices[t[(k + 1) % 3]]);
        const Edge edge = std::minmax(from, to);
        ++total[edge];
        forward[edge] += from < to;
      }
    }
  }

  /// Edge use count -> number of edges used that often.
  std::map<int, int> histogram() const {
    std::map<int, int> counts;
    for (const auto& [edge, uses] : total) ++counts[uses];
    return counts;
  }

  std::vector<Edge> usedOnce() const {
    std::vector<Edge> edges;
    for (const auto& [edge, uses] : total) {
      if (uses == 1) edges.push_back(edge);
    }
    return edges;
  }

  /// Whether every edge is used as often in one direction as in the other: the
  /// triangles form closed surfaces, such as several closed pieces glued together.
  bool balanced() const {
    return std::all_of(total.begin(), total.end(),
                       [&](const auto& entry) { return 2 * forward.at(entry.first) == entry.second; });
  }
};

/// Whether `p` lies on the segment strictly between its ends.
bool insideSegment(const Edge& edge, const Point3& p) {
  const Point3 a(edge.first[0], edge.first[1], edge.first[2]);
  const Point3 b(edge.second[0], edge.second[1], edge.second[2]);
  return (p - a).cross(b - a).norm() == 0 && (p - a).dot(b - a) > 0 && (p - b).dot(a - b) > 0;
}

/// The triangles as corner positions, in order: what a file reader must return.
std::vector<std::array<Position, 3>> trianglePositions(const TriangleSoup& soup) {
  std::vector<std::array<Position, 3>> triangles;
  for (const TriangleIndices& t : soup.triangles) {
    triangles.push_back(
        {positionOf(soup.vertices[t[0]]), positionOf(soup.vertices[t[1]]), positionOf(soup.vertices[t[2]])});
  }
  return triangles;
}

/// The triangles of each piece (connected through shared vertex indices, as the
/// generator writes each piece with vertices of its own).
std::vector<TriangleSoup> piecesOf(const TriangleSoup& soup) {
  std::vector<std::size_t> parent(soup.vertices.size());
  for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = v;
  const auto root = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const TriangleIndices& t : soup.triangles) {
    parent[root(t[1])] = root(t[0]);
    parent[root(t[2])] = root(t[0]);
  }
  std::map<std::size_t, TriangleSoup> pieces;
  for (const TriangleIndices& t : soup.triangles) {
    TriangleSoup& piece = pieces[root(t[0])];
    piece.vertices = soup.vertices;
    piece.triangles.push_back(t);
  }
  std::vector<TriangleSoup> result;
  for (auto& [key, piece] : pieces) result.push_back(std::move(piece));
  return result;
}

Box3 boundsOf(const TriangleSoup& soup) {
  Box3 bounds;
  for (const TriangleIndices& t : soup.triangles) {
    for (std::uint32_t v : t) bounds.extend(soup.vertices[v]);
  }
  return bounds;
}

/// Area of a union of rectangles, by cutting the plane along every rectangle side.
double unionArea(const std::vector<Box2>& rectangles) {
  std::vector<double> xs, ys;
  for (const Box2& r : rectangles) {
    xs.insert(xs.end(), {r.min().x(), r.max().x()});
    ys.insert(ys.end(), {r.min().y(), r.max().y()});
  }
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  double area = 0;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
      const Point2 middle((xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2);
      const bool covered =
          std::any_of(rectangles.begin(), rectangles.end(), [&](const Box2& r) { return r.contains(middle); });
      if (covered) area += (xs[i + 1] - xs[i]) * (ys[j + 1] - ys[j]);
    }
  }
  return area;
}

/// The float spacing at max(|value|, 1): a step of withFloatNoise.
double noiseStep(double value) {
  const float magnitude = std::max(std::abs(static_cast<float>(value)), 1.0f);
  return std::nextafter(magnitude, INFINITY) - magnitude;
}

double onSceneGrid(double value) { return std::round(value / kSceneGrid) * kSceneGrid; }

const TriangleSoup& sceneSoup(const std::string& name, bool robot) {
  static std::map<std::string, Scene> scenes;
  if (!scenes.count(name)) scenes.emplace(name, makeScene(name));
  const Scene& scene = scenes.at(name);
  return robot ? *scene.robotSoup : *scene.worldSoup;
}

const std::vector<std::string> kSoupScenes{"soup_maze", "soup_pieces", "soup_open_sheet", "soup_crack"};

}  // namespace

// ---------------------------------------------------------------------------------
// Variants

TEST(SoupVariants, DoubleSidedFollowsEveryTriangleWithItsReversedCopy) {
  const TriangleSoup box = makeBox(Box3(Point3(0, 0, 0), Point3(2, 1, 0.5)));
  const TriangleSoup doubled = doubleSided(box);
  ASSERT_EQ(doubled.triangles.size(), 2 * box.triangles.size());
  EXPECT_EQ(doubled.vertices, box.vertices);
  for (std::size_t t = 0; t < box.triangles.size(); ++t) {
    const TriangleIndices& original = doubled.triangles[2 * t];
    const TriangleIndices& copy = doubled.triangles[2 * t + 1];
    EXPECT_EQ(original, box.triangles[t]);
    // The copy has the same corners, each followed by the one that preceded it.
    for (int k = 0; k < 3; ++k) {
      const auto at = std::find(copy.begin(), copy.end(), original[k]);
      ASSERT_NE(at, copy.end());
      EXPECT_EQ(copy[(at - copy.begin() + 1) % 3], original[(k + 2) % 3]);
    }
  }
  EXPECT_EQ(signedVolume(box), 1);
  EXPECT_EQ(signedVolume(doubled), 0) << "the two sides cancel";
  EXPECT_EQ(EdgeUses(doubled).histogram(), (std::map<int, int>{{4, 18}})) << "every box edge used twice per side";
}

TEST(SoupVariants, GluedPrismsEncloseTheOutlinesVolumeWithInternalWallsTwice) {
  // A non-convex outline (a U with arms of different lengths) of 8 corners: 6
  // triangles, 5 internal walls.
  const Polygon2 outline{{0, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 0.5}, {1, 0.5}, {1, 2}, {0, 2}};
  const auto corners = static_cast<int>(outline.size());
  const double z0 = 0.25, z1 = 1.5;
  const TriangleSoup prisms = gluedPrisms(outline, z0, z1);
  EXPECT_EQ(static_cast<int>(piecesOf(prisms).size()), corners - 2) << "one closed prism per triangle";
  EXPECT_EQ(static_cast<int>(prisms.triangles.size()), 8 * (corners - 2));
  EXPECT_EQ(signedVolume(prisms), polygonArea(outline) * (z1 - z0));

  const EdgeUses uses(prisms);
  EXPECT_TRUE(uses.balanced()) << "closed pieces glued together";
  std::map<int, int> horizontal;  // uses -> edges on the floor or the top
  for (const auto& [edge, count] : uses.total) {
    if (edge.first[2] == edge.second[2]) ++horizontal[count];
  }
  // The outline's sides once per cap, and each internal wall's bottom and top,
  // used by both prisms it separates.
  EXPECT_EQ(horizontal, (std::map<int, int>{{2, 2 * corners}, {4, 2 * (corners - 3)}}));
  EXPECT_GT(uses.histogram().rbegin()->first, 2) << "the glued walls make edges used 4 times or more";
}

TEST(SoupVariants, TJunctionWallIsClosedWithEdgesUsedOnceAcrossACorner) {
  const Box3 longBox(Point3(0, 0, 0), Point3(4, 0.5, 1));
  const TriangleSoup wall = tJunctionWall(longBox, 1.5, 0.5);
  // The surface of the 4 x 1 x 1 union: closed although its edges do not all match.
  EXPECT_EQ(signedVolume(wall), 4);
  const EdgeUses uses(wall);
  const std::vector<Edge> once = uses.usedOnce();
  // Along the seam y = 0.5 at the floor and the top: the long box's edge and the two
  // short boxes' edges, each used by one triangle.
  EXPECT_EQ(once.size(), 6u);
  int crossed = 0;
  for (const Edge& edge : once) {
    EXPECT_EQ(edge.first[1], 0.5);
    EXPECT_EQ(edge.second[1], 0.5);
    crossed += std::any_of(wall.vertices.begin(), wall.vertices.end(),
                           [&](const Point3& v) { return insideSegment(edge, v); });
  }
  EXPECT_EQ(crossed, 2) << "the long box's edges, at the floor and the top, have the split corner inside";
  EXPECT_THROW(tJunctionWall(longBox, 4, 0.5), std::invalid_argument);
}

TEST(SoupVariants, FloatNoiseMovesEveryCoordinateByAtMostTheStatedSteps) {
  // Coordinates from -100 to 300, with boxes sharing corners in separate vertex slots.
  const TriangleSoup boxes = joinParts({makeBox(Box3(Point3(-100, 0, 0), Point3(300, 0.5, 2))),
                                        makeBox(Box3(Point3(-100, 0.5, 0), Point3(0.25, 1, 2))),
                                        makeBox(Box3(Point3(9.375, 0.5, 0), Point3(10, 1, 0.75)))});
  const unsigned ulps = 3;
  const TriangleSoup noisy = withFloatNoise(boxes, 42, ulps);
  ASSERT_EQ(noisy.vertices.size(), boxes.vertices.size());
  EXPECT_EQ(noisy.triangles, boxes.triangles);
  int moved = 0, zerosMoved = 0;
  for (std::size_t v = 0; v < boxes.vertices.size(); ++v) {
    for (int k = 0; k < 3; ++k) {
      const double before = boxes.vertices[v][k];
      const double after = noisy.vertices[v][k];
      EXPECT_EQ(static_cast<double>(static_cast<float>(after)), after) << "stored as a float";
      const double steps = (after - before) / noiseStep(before);
      EXPECT_EQ(steps, std::round(steps)) << before << " -> " << after;
      EXPECT_LE(std::abs(steps), ulps) << before << " -> " << after;
      moved += after != before;
      zerosMoved += before == 0 && after != 0;
    }
  }
  EXPECT_GT(moved, 36) << "most coordinates move";
  EXPECT_GT(zerosMoved, 0) << "floor heights move too";
  // Copies of a point in separate pieces (the boxes' shared corners) differ.
  std::map<Position, std::set<Position>> copies;
  for (std::size_t v = 0; v < boxes.vertices.size(); ++v) {
    copies[positionOf(boxes.vertices[v])].insert(positionOf(noisy.vertices[v]));
  }
  EXPECT_TRUE(std::any_of(copies.begin(), copies.end(), [](const auto& entry) { return entry.second.size() > 1; }));

  EXPECT_EQ(withFloatNoise(boxes, 42, ulps).vertices, noisy.vertices) << "the same for a seed";
  EXPECT_NE(withFloatNoise(boxes, 43, ulps).vertices, noisy.vertices);
  EXPECT_EQ(withFloatNoise(boxes, 42, 0).vertices, boxes.vertices) << "grid points are floats already";
}

TEST(SoupVariants, OpenBoxesLackTheirFacesAndBuriedWallsTheirEnds) {
  const Box3 box(Point3(0, 0, 0), Point3(4, 0.25, 0.5));
  EXPECT_EQ(openBox(box, {}).triangles.size(), 12u);
  const TriangleSoup lidless = openBox(box, {BoxFace::top});
  EXPECT_EQ(lidless.triangles.size(), 10u);
  for (const TriangleIndices& t : lidless.triangles) {
    EXPECT_FALSE(std::all_of(t.begin(), t.end(), [&](std::uint32_t v) { return lidless.vertices[v].z() == 0.5; }));
  }
  // The rim left by the missing end caps: the four sides of each end square.
  const TriangleSoup buried = wallWithBuriedEnds(box);
  EXPECT_EQ(buried.triangles.size(), 8u);
  const std::vector<Edge> rim = EdgeUses(buried).usedOnce();
  EXPECT_EQ(rim.size(), 8u);
  for (const Edge& edge : rim) {
    EXPECT_EQ(edge.first[0], edge.second[0]);
    EXPECT_TRUE(edge.first[0] == 0 || edge.first[0] == 4) << "at the ends of the wall, which runs along x";
  }
  const Box3 alongY(Point3(0, 0, 0), Point3(0.25, 4, 0.5));
  for (const Edge& edge : EdgeUses(wallWithBuriedEnds(alongY)).usedOnce()) {
    EXPECT_TRUE(edge.first[1] == edge.second[1] && (edge.first[1] == 0 || edge.first[1] == 4));
  }
}

TEST(SoupVariants, TouchingBoxesMeetInAFaceAnEdgeOrAPoint) {
  const Box3 box(Point3(1, 2, 0), Point3(1.5, 2.25, 0.75));
  const std::map<Contact, int> contactDimension{{Contact::face, 2}, {Contact::edge, 1}, {Contact::vertex, 0}};
  const std::map<Contact, int> sharedCorners{{Contact::face, 4}, {Contact::edge, 0}, {Contact::vertex, 1}};
  for (const auto& [contact, dimension] : contactDimension) {
    const TriangleSoup pair = touchingBoxes(box, contact);
    const std::vector<TriangleSoup> pieces = piecesOf(pair);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_EQ(signedVolume(pieces[0]), signedVolume(pieces[1]));
    EXPECT_EQ(signedVolume(pieces[0]), box.volume());
    const Box3 contactBox = boundsOf(pieces[0]).intersection(boundsOf(pieces[1]));
    ASSERT_FALSE(contactBox.isEmpty());
    EXPECT_EQ((contactBox.sizes().array() > 0).count(), dimension);
    std::set<Position> first, second;
    for (const TriangleIndices& t : pieces[0].triangles) {
      for (std::uint32_t v : t) first.insert(positionOf(pair.vertices[v]));
    }
    for (const TriangleIndices& t : pieces[1].triangles) {
      for (std::uint32_t v : t) second.insert(positionOf(pair.vertices[v]));
    }
    std::vector<Position> shared;
    std::set_intersection(first.begin(), first.end(), second.begin(), second.end(), std::back_inserter(shared));
    EXPECT_EQ(static_cast<int>(shared.size()), sharedCorners.at(contact));
  }
}

TEST(SoupVariants, OpenSheetIsAZeroThicknessDoubleSidedQuadBesideAClosedBox) {
  const Box3 box(Point3(0, 0, 0), Point3(0.5, 2, 1));
  const std::vector<TriangleSoup> pieces = piecesOf(openSheetBesideBox(box));
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(signedVolume(pieces[0]), 1);
  const TriangleSoup& sheet = pieces[1];
  EXPECT_EQ(sheet.triangles.size(), 4u);
  EXPECT_EQ(signedVolume(sheet), 0);
  const Box3 bounds = boundsOf(sheet);
  EXPECT_EQ(bounds.sizes(), Point3(0, 2, 1)) << "as long and as high as the box, no thickness";
  EXPECT_EQ(bounds.min().x(), 1) << "one box width east of it";
  const EdgeUses uses(sheet);
  EXPECT_TRUE(uses.balanced()) << "like a closed surface";
  EXPECT_EQ(uses.histogram(), (std::map<int, int>{{2, 4}, {4, 1}})) << "sides once per side, the diagonal twice";
  EXPECT_THROW(Mesh::fromSoup(openSheetBesideBox(box), "sheet"), InputError);
}

TEST(SoupVariants, TornSeamLeavesAGapAlongTwoFacesAtRightAngles) {
  const Box3 box(Point3(-0.25, -8, 0), Point3(0.25, 8, 1));
  const double gap = kSceneGrid;
  const TriangleSoup torn = tornSeamBox(box, gap);
  const std::vector<Edge> rim = EdgeUses(torn).usedOnce();
  ASSERT_FALSE(rim.empty());
  std::set<Position> rimPoints;
  for (const Edge& edge : rim) rimPoints.insert({edge.first, edge.second});
  // The rim: the top face's edge gap short of the seam, the east face's edge gap
  // below it, and the seam's ends.
  std::set<Position> expected;
  for (double y : {-8.0, 8.0}) {
    expected.insert({0.25 - gap, y, 1});
    expected.insert({0.25, y, 1});
    expected.insert({0.25, y, 1 - gap});
  }
  EXPECT_EQ(rimPoints, expected);
  // Not planar: the rim's points span all three dimensions.
  Box3 rimBounds;
  for (const Position& p : rimPoints) rimBounds.extend(Point3(p[0], p[1], p[2]));
  EXPECT_EQ(rimBounds.sizes(), Point3(gap, 16, gap));
  const double width = std::hypot(gap, gap);
  EXPECT_GT(width, 1e-3 * box.sizes().maxCoeff()) << "about 1e-3 of the box's size";
  EXPECT_LT(width, 2e-3 * box.sizes().maxCoeff());
  EXPECT_THROW(Mesh::fromSoup(torn, "torn"), InputError);
  EXPECT_THROW(tornSeamBox(box, 0.5), std::invalid_argument);
}

// ---------------------------------------------------------------------------------
// Scenes written as soups

TEST(ScenesWrittenAsSoups, AreNamedAndCarryTheirSoups) {
  const std::vector<std::string> names = sceneNames();
  for (const std::string& name : kSoupScenes) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    const Scene scene = makeScene(name);
    EXPECT_TRUE(scene.robotSoup.has_value()) << name;
    EXPECT_TRUE(scene.worldSoup.has_value()) << name;
    EXPECT_TRUE(scene.expectSolvable) << name << ": solvable with the solid world";
  }
  for (const std::string name : {"soup_open_sheet", "soup_crack"}) {
    EXPECT_NE(makeScene(name).description.find("must fail"), std::string::npos) << name;
  }
  EXPECT_FALSE(makeScene("maze").robotSoup.has_value()) << "other scenes are written as their meshes";
}

TEST(ScenesWrittenAsSoups, RobotsAreDoubleSidedAndCentredAsWritten) {
  for (const std::string& name : kSoupScenes) {
    const TriangleSoup& robot = sceneSoup(name, true);
    TriangleSoup oneSide{robot.vertices, {}};
    for (std::size_t t = 0; t < robot.triangles.size(); t += 2) oneSide.triangles.push_back(robot.triangles[t]);
    EXPECT_EQ(doubleSided(oneSide).triangles, robot.triangles) << name;
    Point3 sum = Point3::Zero();
    for (const Point3& v : robot.vertices) sum += v;
    EXPECT_EQ(sum.x(), 0) << name;
    EXPECT_EQ(sum.y(), 0) << name;
    EXPECT_DOUBLE_EQ(signedVolume(oneSide), makeScene(name).robot.volume()) << name;
  }
  // The car: 1.5 x 0.75 x 0.375 in four glued prisms.
  EXPECT_EQ(makeScene("soup_maze").robot.volume(), 1.5 * 0.75 * 0.375);
  EXPECT_EQ(piecesOf(sceneSoup("soup_maze", true)).size(), 4u);
}

TEST(ScenesWrittenAsSoups, OmplAppRecentringLeavesTheRobotsInPlace) {
  // OMPL.app's centre is the average of the vertices assimp imports (one per
  // position and normal): the robots are symmetric, so it is 0 too.
  const TempDir dir;
  for (const std::string& name : kSoupScenes) {
    const std::string path = dir.file(name + "_robot.dae");
    writeSoup(sceneSoup(name, true), path);
    const Point3 centre = importMesh(path).vertexAverage;
    EXPECT_EQ(centre.x(), 0) << name;
    EXPECT_EQ(centre.y(), 0) << name;
  }
}

TEST(ScenesWrittenAsSoups, MazeWallsAreDoubleSidedNoisyBoxesAtTwoHeights) {
  const TriangleSoup& world = sceneSoup("soup_maze", false);
  for (std::size_t t = 0; t + 1 < world.triangles.size(); t += 2) {
    const TriangleIndices& a = world.triangles[t];
    ASSERT_EQ(world.triangles[t + 1], (TriangleIndices{a[0], a[2], a[1]}));
  }
  std::map<Position, std::set<Position>> copies;  // grid point -> its noisy copies
  std::set<double> tops;
  for (const Point3& v : world.vertices) {
    const Point3 grid(onSceneGrid(v.x()), onSceneGrid(v.y()), onSceneGrid(v.z()));
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(v[k] - grid[k]), 2 * noiseStep(grid[k]));
    copies[positionOf(grid)].insert(positionOf(v));
    tops.insert(grid.z());
  }
  EXPECT_EQ(tops, (std::set<double>{0, 0.5, 0.75}));
  EXPECT_TRUE(std::any_of(copies.begin(), copies.end(), [](const auto& entry) { return entry.second.size() > 1; }))
      << "copies of a point differ";
  // ... by less than a millionth of the diagonal, a distance a loader can weld.
  const double diagonal = boundsOf(world).sizes().norm();
  for (const auto& [point, noisy] : copies) {
    for (const Position& a : noisy) {
      for (const Position& b : noisy) {
        EXPECT_LT(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]), 1e-6 * diagonal);
      }
    }
  }
  // Box edges are used twice on each side; the T-junction's edges once on each.
  const std::map<int, int> histogram = EdgeUses(world).histogram();
  EXPECT_TRUE(histogram.count(4));
  EXPECT_TRUE(histogram.count(2));
}

TEST(ScenesWrittenAsSoups, TheSolidsHaveTheVolumesOfTheirBoxes) {
  // soup_pieces: every box a component of its own, the two sharing a face as one.
  const double room = 2 * (0.25 * 8.5 * 1) + 2 * (8.25 * 0.25 * 0.75);
  const double cross = 3 * 0.25 * 0.5 + 0.25 * 3 * 0.75;
  const double pairs =
      2 * (0.375 * 0.75 * 0.5) + 2 * (0.375 * 0.375 * 0.5) + 2 * (0.375 * 0.375 * 0.375) + 2 * (0.5 * 0.5 * 0.5);
  const double beam = 2.5 * 0.25 * 0.25;
  const Mesh& pieces = makeScene("soup_pieces").world;
  EXPECT_EQ(pieces.componentCount(), 14u);
  EXPECT_DOUBLE_EQ(pieces.volume(), room + cross + pairs + beam);
  EXPECT_EQ(makeScene("soup_open_sheet").world.volume(), 0.25 * 4 * 0.75) << "the wall alone";
  EXPECT_EQ(makeScene("soup_crack").world.volume(), 0.5 * 16 * 1) << "the whole box";
}

TEST(ScenesWrittenAsSoups, PiecesRoomIsClosedByWallsBuryingTheOpenEnds) {
  // One side of the double-sided soup: the open edges are the rims of the south and
  // north walls' missing end caps, four at each end, all inside the west and east
  // walls (x in [-4.25, -4] and [4, 4.25]), which close the union, and the three
  // edges of the stray triangle under the floor.
  const TriangleSoup& world = sceneSoup("soup_pieces", false);
  TriangleSoup oneSide{world.vertices, {}};
  for (std::size_t t = 0; t < world.triangles.size(); t += 2) oneSide.triangles.push_back(world.triangles[t]);
  const std::vector<Edge> rims = EdgeUses(oneSide).usedOnce();
  EXPECT_EQ(rims.size(), 19u);
  std::size_t underFloor = 0;
  for (const Edge& edge : rims) {
    if (edge.first[2] == -kSceneGrid && edge.second[2] == -kSceneGrid) {
      ++underFloor;
      continue;
    }
    for (const Position& end : {edge.first, edge.second}) {
      EXPECT_TRUE((-4.25 < end[0] && end[0] < -4) || (4 < end[0] && end[0] < 4.25)) << end[0];
    }
  }
  EXPECT_EQ(underFloor, 3u);
}

TEST(ScenesWrittenAsSoups, MazeSolidIsTheUnionOfTheWrittenBoxes) {
  // Each piece written is a box (or part of one) standing on the floor: its
  // footprint and height, from its bounds with the noise rounded away.
  const Scene scene = makeScene("soup_maze");
  std::map<double, std::vector<Box2>> footprints;  // by height
  for (const TriangleSoup& piece : piecesOf(*scene.worldSoup)) {
    const Box3 bounds = boundsOf(piece);
    EXPECT_EQ(onSceneGrid(bounds.min().z()), 0);
    footprints[onSceneGrid(bounds.max().z())].push_back(
        Box2(Point2(onSceneGrid(bounds.min().x()), onSceneGrid(bounds.min().y())),
             Point2(onSceneGrid(bounds.max().x()), onSceneGrid(bounds.max().y()))));
  }
  ASSERT_EQ(footprints.size(), 2u);
  const std::vector<Box2>& high = footprints.at(0.75);
  std::vector<Box2> all = footprints.at(0.5);
  all.insert(all.end(), high.begin(), high.end());
  // The solid's components overlap in two layers: all walls up to the lower
  // height, the high walls from below it up to theirs.
  std::set<std::pair<double, double>> layers;
  for (const Box3& bounds : scene.world.componentBounds()) layers.emplace(bounds.min().z(), bounds.max().z());
  ASSERT_EQ(layers.size(), 2u);
  const auto [lowBottom, lowTop] = *layers.begin();
  const auto [highBottom, highTop] = *layers.rbegin();
  EXPECT_EQ(lowBottom, 0);
  EXPECT_EQ(lowTop, 0.5);
  EXPECT_LT(highBottom, lowTop) << "the layers overlap";
  EXPECT_EQ(highTop, 0.75);
  const double lowLayer = lowTop - lowBottom;
  const double highLayer = highTop - highBottom;
  EXPECT_DOUBLE_EQ(scene.world.volume(), unionArea(all) * lowLayer + unionArea(high) * highLayer);
}

TEST(ScenesWrittenAsSoups, MazeFamilyHasAboutTheAskedNumberOfTriangles) {
  for (const unsigned thousands : {1u, 5u, 20u}) {
    const Scene scene = makeScene("soup_maze_" + std::to_string(thousands));
    EXPECT_EQ(scene.name, "soup_maze_" + std::to_string(thousands));
    const double triangles = static_cast<double>(scene.worldSoup->triangles.size());
    EXPECT_NEAR(triangles, 1000.0 * thousands, 250.0 * thousands) << thousands;
  }
  EXPECT_TRUE(isSceneName("soup_maze_100"));
  EXPECT_FALSE(isSceneName("soup_maze_"));
  EXPECT_THROW(makeScene("soup_maze_x"), std::invalid_argument);
}

// ---------------------------------------------------------------------------------
// Writing soups

namespace {

TriangleSoup roundedToFloats(TriangleSoup soup) {
  for (Point3& v : soup.vertices) v = v.cast<float>().cast<double>();
  return soup;
}

}  // namespace

TEST(MeshWriter, SoupsRoundTripInEveryFormat) {
  const TempDir dir;
  // Coordinates that are not floats: assimp's formats keep them as floats, and so
  // does the OFF reader; VTK keeps doubles.
  TriangleSoup decimals = doubleSided(makeBox(Box3(Point3(0.1, 0.2, 0), Point3(1.3, 0.7, 0.3))));
  decimals.vertices.emplace_back(5, 5, 5);  // unused
  const std::vector<std::pair<std::string, TriangleSoup>> soups{
      {"maze", sceneSoup("soup_maze", false)},     {"car", sceneSoup("soup_maze", true)},
      {"pieces", sceneSoup("soup_pieces", false)}, {"sheet", sceneSoup("soup_open_sheet", false)},
      {"crack", sceneSoup("soup_crack", false)},   {"decimals", decimals}};
  for (const std::string format : {"obj", "stl", "ply", "off", "dae", "vtk"}) {
    for (const auto& [name, soup] : soups) {
      const std::string path = dir.file(name + "." + format);
      writeSoup(soup, path);
      const TriangleSoup expected = format == "vtk" ? soup : roundedToFloats(soup);
      EXPECT_EQ(trianglePositions(readTriangleSoup(path)), trianglePositions(expected)) << path;
    }
  }
}

TEST(MeshWriter, SoupsAreCheckedOnlyForFiniteCoordinatesAndIndices) {
  const TempDir dir;
  TriangleSoup soup = makeBox(Box3(Point3(0, 0, 0), Point3(1, 1, 1)));
  soup.triangles.push_back(soup.triangles.front());  // a duplicate is written as it is
  EXPECT_NO_THROW(writeSoup(soup, dir.file("duplicate.obj")));

  TriangleSoup notFinite = soup;
  notFinite.vertices[3].y() = NAN;
  TriangleSoup outOfRange = soup;
  outOfRange.triangles.back()[2] = 8;
  for (const auto& [soupWithDefect, problem] :
       {std::pair{notFinite, "vertex 3 has a non-finite coordinate"}, {outOfRange, "refers to vertex 8"}}) {
    for (const std::string format : {"obj", "vtk"}) {
      const std::string path = dir.file("bad." + format);
      try {
        writeSoup(soupWithDefect, path);
        FAIL() << "wrote " << path;
      } catch (const InputError& error) {
        EXPECT_EQ(error.file(), path);
        EXPECT_NE(error.problem().find(problem), std::string::npos) << error.what();
      }
      EXPECT_FALSE(std::filesystem::exists(path));
    }
  }
}

TEST(ScenesWrittenAsSoups, WriteSceneWritesTheSoupsInsteadOfTheMeshes) {
  const TempDir dir;
  for (const std::string& name : kSoupScenes) {
    const Scene scene = makeScene(name);
    writeScene(scene, dir.file("scenes"), "dae");
    EXPECT_EQ(trianglePositions(readTriangleSoup(dir.file("scenes/" + name + "_robot.dae"))),
              trianglePositions(*scene.robotSoup))
        << name;
    EXPECT_EQ(trianglePositions(readTriangleSoup(dir.file("scenes/" + name + "_world.dae"))),
              trianglePositions(*scene.worldSoup))
        << name;
  }
}
