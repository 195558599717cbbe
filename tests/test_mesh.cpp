// Mesh::fromSoup: welding, every validation rule with its message (a surface that
// meets itself among them), components, orientation repair and translation, on soups
// built in code.

#include "freespace/geometry/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "freespace/input_error.h"
#include "geometry/surface_self_intersection.h"

namespace freespace {
namespace {

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

// Box corners in the order of cube.obj; triangles counter-clockwise seen from outside.
const std::vector<TriangleIndices> kBoxTriangles = {
    {0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
    {2, 3, 7}, {2, 7, 6}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};

TriangleSoup boxSoup(const Point3& low = Point3(0, 0, 0), const Point3& high = Point3(1, 1, 1)) {
  TriangleSoup soup;
  for (int corner = 0; corner < 8; ++corner) {
    const bool x = corner == 1 || corner == 2 || corner == 5 || corner == 6;
    const bool y = corner == 2 || corner == 3 || corner == 6 || corner == 7;
    const bool z = corner >= 4;
    soup.vertices.emplace_back(x ? high.x() : low.x(), y ? high.y() : low.y(),
                               z ? high.z() : low.z());
  }
  soup.triangles = kBoxTriangles;
  return soup;
}

// Appends `other` to `soup` (its indices shifted).
void append(TriangleSoup& soup, const TriangleSoup& other) {
  const auto shift = static_cast<std::uint32_t>(soup.vertices.size());
  soup.vertices.insert(soup.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (TriangleIndices triangle : other.triangles) {
    for (std::uint32_t& index : triangle) index += shift;
    soup.triangles.push_back(triangle);
  }
}

void reverseTriangles(TriangleSoup& soup) {
  for (TriangleIndices& triangle : soup.triangles) std::swap(triangle[1], triangle[2]);
}

// The problem fromSoup reports, or "" when the soup is accepted.
std::string problemOf(const TriangleSoup& soup) {
  try {
    Mesh::fromSoup(soup, "soup");
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "soup");
    EXPECT_EQ(std::string(error.what()), "soup: " + error.problem());
    return error.problem();
  }
  return "";
}

TEST(Mesh, UnitCubeHasEightVerticesTwelveTrianglesAndVolumeOne) {
  std::vector<std::string> warnings;
  const Mesh mesh = Mesh::fromSoup(boxSoup(), "cube", &warnings);
  EXPECT_EQ(mesh.vertices().size(), 8u);
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_EQ(mesh.componentCount(), 1u);
  EXPECT_EQ(mesh.volume(), 1.0);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(mesh.bounds().min(), Point3(0, 0, 0));
  EXPECT_EQ(mesh.bounds().max(), Point3(1, 1, 1));
  EXPECT_EQ(mesh.triangleComponents(), std::vector<std::uint32_t>(12, 0));
  ASSERT_EQ(mesh.componentRepresentatives().size(), 1u);
  EXPECT_LT(mesh.componentRepresentatives()[0], 8u);
}

TEST(Mesh, KeepsTheNumberingOfDistinctUsedVertices) {
  const TriangleSoup soup = boxSoup();
  const Mesh mesh = Mesh::fromSoup(soup, "cube");
  EXPECT_EQ(mesh.vertices(), soup.vertices);
  EXPECT_EQ(mesh.triangles(), soup.triangles);
}

TEST(Mesh, WeldsIdenticalVerticesAndDropsUnusedOnesInFirstAppearanceOrder) {
  // Every triangle gets its own three vertices, after an unused one.
  const TriangleSoup box = boxSoup();
  TriangleSoup soup;
  soup.vertices.emplace_back(9, 9, 9);
  for (const TriangleIndices& triangle : box.triangles) {
    const auto first = static_cast<std::uint32_t>(soup.vertices.size());
    for (std::uint32_t index : triangle) soup.vertices.push_back(box.vertices[index]);
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  const Mesh mesh = Mesh::fromSoup(soup, "soup");
  EXPECT_EQ(mesh.vertices().size(), 8u);
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_EQ(mesh.volume(), 1.0);
  // The first triangle {0, 3, 2} of the box comes first: its corners are vertices 0, 1, 2.
  EXPECT_EQ(mesh.vertices()[0], box.vertices[0]);
  EXPECT_EQ(mesh.vertices()[1], box.vertices[3]);
  EXPECT_EQ(mesh.vertices()[2], box.vertices[2]);
  EXPECT_EQ(mesh.triangles()[0], (TriangleIndices{0, 1, 2}));
  for (std::size_t t = 0; t < 12; ++t) {
    for (int corner = 0; corner < 3; ++corner) {
      EXPECT_EQ(mesh.vertices()[mesh.triangles()[t][corner]], box.vertices[box.triangles[t][corner]]);
    }
  }
}

TEST(Mesh, NegativeZeroIsTheSameCoordinateAsZero) {
  TriangleSoup soup = boxSoup();
  soup.vertices.emplace_back(-0.0, -0.0, -0.0);
  soup.triangles[0][0] = 8;  // a copy of vertex 0
  const Mesh mesh = Mesh::fromSoup(soup, "soup");
  EXPECT_EQ(mesh.vertices().size(), 8u);
  EXPECT_EQ(mesh.volume(), 1.0);
}

TEST(Mesh, RejectsNonFiniteCoordinatesNamingTheSoupVertex) {
  TriangleSoup soup = boxSoup();
  soup.vertices[5].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(problemOf(soup), "vertex 5 has a non-finite coordinate (nan)");
  soup.vertices[5].y() = -std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(problemOf(soup), "vertex 5 has a non-finite coordinate (nan)");
  soup.vertices[5].y() = 0;
  soup.vertices[6].z() = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(problemOf(soup), "vertex 6 has a non-finite coordinate (-inf)");
}

TEST(Mesh, RejectsASoupWithoutTriangles) {
  TriangleSoup soup = boxSoup();
  soup.triangles.clear();
  EXPECT_EQ(problemOf(soup), "contains no triangles");
  EXPECT_EQ(problemOf(TriangleSoup()), "contains no triangles");
}

TEST(Mesh, RejectsIndicesOutOfRange) {
  TriangleSoup soup = boxSoup();
  soup.triangles[3][1] = 12;
  EXPECT_EQ(problemOf(soup), "triangle 3 refers to vertex 12, but there are only 8 vertices");
}

TEST(Mesh, RejectsATriangleWhoseVerticesWeldTogether) {
  TriangleSoup soup = boxSoup();
  soup.vertices.push_back(soup.vertices[3]);
  soup.triangles[0] = {0, 3, 8};
  EXPECT_EQ(problemOf(soup),
            "triangle 0 (vertices 0, 3, 3) has zero area; vertex 0 is at (0, 0, 0), "
            "vertex 3 at (0, 1, 0)");
}

// A surface with the triangle (0, 1, 2) and all other triangles fine.
TriangleSoup surfaceWithTriangle(const Point3& a, const Point3& b, const Point3& c) {
  TriangleSoup soup;
  soup.vertices = {a, b, c, Point3(1, 0, 0), Point3(0, 1, 0)};
  soup.triangles = {{0, 2, 1}, {2, 0, 3}, {1, 2, 3}, {0, 1, 4}, {3, 0, 4}, {1, 3, 4}};
  return soup;
}

TEST(Mesh, RejectsExactlyCollinearTriangles) {
  // 0.2 and 0.4 are exactly twice 0.1 and 0.2 as doubles, 0.6 twice 0.3.
  const TriangleSoup soup =
      surfaceWithTriangle(Point3(0, 0, 0), Point3(0.2, 0.4, 0.6), Point3(0.1, 0.2, 0.3));
  EXPECT_TRUE(contains(problemOf(soup), "triangle 0 (vertices 0, 2, 1) has zero area; "
                                         "vertex 0 is at (0, 0, 0), vertex 2 at (0.1, 0.2, 0.3)"));
}

TEST(Mesh, AcceptsASliverThatDoublesWouldCallCollinear) {
  // (0.3, 0.3, 0.3) x (0.9, 0.9, 0.9 + ulp) is exactly zero in doubles, but not in
  // exact arithmetic: the triangle has a tiny positive area.
  const Point3 far(0.9, 0.9, std::nextafter(0.9, 1.0));
  const Point3 middle(0.3, 0.3, 0.3);
  ASSERT_EQ(middle.cross(far), Point3::Zero());
  std::vector<std::string> warnings;
  const Mesh mesh = Mesh::fromSoup(surfaceWithTriangle(Point3::Zero(), far, middle), "sliver",
                                   &warnings);
  EXPECT_EQ(mesh.triangles().size(), 6u);
  EXPECT_EQ(mesh.vertices().size(), 5u);
  // The sliver hardly changes the tetrahedron (0, far, (1,0,0), (0,1,0)): 0.9 / 6.
  EXPECT_NEAR(mesh.volume(), 0.15, 1e-12);
}

TEST(Mesh, RejectsDuplicateTriangles) {
  TriangleSoup soup = boxSoup();
  soup.triangles.push_back({2, 0, 3});  // triangle 0, {0, 3, 2}, rotated
  EXPECT_TRUE(contains(problemOf(soup), "triangles 0 and 12 use the same three vertices (0, 3, 2); "
                                         "vertex 0 is at (0, 0, 0)"));
}

TEST(Mesh, NamesDoubleSidedTrianglesAsSuch) {
  TriangleSoup soup = boxSoup();
  TriangleSoup backFaces = boxSoup();
  reverseTriangles(backFaces);
  append(soup, backFaces);
  EXPECT_TRUE(contains(problemOf(soup), "triangles 0 and 12 use the same three vertices (0, 3, 2) "
                                         "in opposite orientations"));
}

TEST(Mesh, RejectsAnEdgeSharedByThreeTriangles) {
  TriangleSoup soup = boxSoup();
  soup.vertices.emplace_back(0.5, -1, -1);
  soup.triangles.push_back({0, 1, 8});  // a fin on the edge (0, 1)
  EXPECT_EQ(problemOf(soup),
            "edge (0, 1) is shared by 3 triangles; vertex 0 is at (0, 0, 0), vertex 1 at (1, 0, 0)");
}

TEST(Mesh, RejectsAnOpenSurface) {
  TriangleSoup soup = boxSoup();
  soup.triangles.erase(soup.triangles.begin() + 2, soup.triangles.begin() + 4);  // the top
  EXPECT_EQ(problemOf(soup),
            "edge (4, 5) borders only one triangle: the surface is not closed; "
            "vertex 4 is at (0, 0, 1), vertex 5 at (1, 0, 1)");
}

TEST(Mesh, RejectsInconsistentOrientation) {
  TriangleSoup soup = boxSoup();
  std::swap(soup.triangles[2][1], soup.triangles[2][2]);
  std::swap(soup.triangles[3][1], soup.triangles[3][2]);  // the top, both triangles
  EXPECT_TRUE(contains(problemOf(soup),
                       "triangles 2 and 5 have inconsistent orientation across edge (4, 5)"));
}

TEST(Mesh, FlipsAnInsideOutComponentWithAWarning) {
  TriangleSoup soup = boxSoup();
  reverseTriangles(soup);
  std::vector<std::string> warnings;
  const Mesh mesh = Mesh::fromSoup(soup, "inside_out.obj", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "inside_out.obj: component 0 was inside-out and has been flipped");
  EXPECT_EQ(mesh.volume(), 1.0);
  EXPECT_EQ(mesh.triangles(), kBoxTriangles);
}

TEST(Mesh, RejectsAComponentThatEnclosesNoVolume) {
  TriangleSoup soup = boxSoup(Point3(5, 5, 5), Point3(6, 6, 6));
  // A closed, oriented tetrahedron surface on four coplanar points (plane y = z).
  TriangleSoup flat;
  flat.vertices = {Point3(0, 0, 0), Point3(1, 1, 1), Point3(1, 0, 0), Point3(2, 1, 1)};
  flat.triangles = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  append(soup, flat);
  EXPECT_EQ(problemOf(soup), "component 1 encloses no volume");
}

TEST(Mesh, RejectsAComponentWhoseSurfaceCrossesItself) {
  // A box with its top corner (2, 2, 1) pushed down through its bottom: closed and
  // consistently oriented, but the triangles at that corner cross the bottom.
  TriangleSoup soup = boxSoup(Point3(5, 5, 5), Point3(6, 6, 6));
  TriangleSoup folded = boxSoup(Point3(0, 0, 0), Point3(2, 2, 1));
  folded.vertices[6] = Point3(1.3, 1.1, -0.6);
  append(soup, folded);
  EXPECT_TRUE(contains(problemOf(soup), "component 1 intersects itself: triangles 12 (vertices 8, 11, 10) and"));
  EXPECT_EQ(problemOf(folded).rfind("component 0 intersects itself", 0), 0u) << problemOf(folded);
}

TEST(Mesh, RejectsAComponentWhoseSurfaceTouchesItself) {
  // The top corner moved onto the bottom face, inside the bottom triangle (0, 2, 1),
  // which the top triangle (4, 5, 6) then touches at that corner.
  TriangleSoup touching = boxSoup(Point3(0, 0, 0), Point3(2, 2, 1));
  touching.vertices[6] = Point3(1.5, 0.5, 0);
  EXPECT_EQ(problemOf(touching).rfind("component 0 intersects itself: triangles 1 (vertices 0, 2, 1) and 2 (vertices 4, 5, 6)", 0), 0u)
      << problemOf(touching);
}

// The pairs of triangles of one component that firstSelfIntersection reports, by the
// features they share: (0, 1, 2) in the plane z = 0 against a second triangle.
std::optional<std::pair<std::uint32_t, std::uint32_t>> pairMeeting(const std::vector<Point3>& others,
                                                                  const TriangleIndices& second) {
  std::vector<Point3> vertices = {Point3(0, 0, 0), Point3(4, 0, 0), Point3(0, 4, 0)};
  vertices.insert(vertices.end(), others.begin(), others.end());
  return detail::firstSelfIntersection(vertices, {{0, 1, 2}, second}, {0, 0});
}

TEST(SurfaceSelfIntersection, TrianglesSharingAVertexMeetOnlyWhenAnotherPointIsInBoth) {
  // Through the first triangle's plane inside it, and above it only.
  EXPECT_TRUE(pairMeeting({Point3(1, 1, -1), Point3(1, 2, 1)}, {0, 3, 4}));
  EXPECT_FALSE(pairMeeting({Point3(1, 1, 1), Point3(1, 2, 1)}, {0, 3, 4}));
  // In the plane: overlapping the first, and outside it beyond the shared vertex.
  EXPECT_TRUE(pairMeeting({Point3(1, 1, 0), Point3(2, 1, 0)}, {0, 3, 4}));
  EXPECT_FALSE(pairMeeting({Point3(-1, -1, 0), Point3(-2, -1, 0)}, {0, 3, 4}));
  // Along the first's edge from the shared vertex: a common segment.
  EXPECT_TRUE(pairMeeting({Point3(2, 0, 0), Point3(2, -1, 1)}, {0, 3, 4}));
}

TEST(SurfaceSelfIntersection, TrianglesSharingNoVertexMeetWhenTheyCrossOrTouch) {
  EXPECT_TRUE(pairMeeting({Point3(1, 1, -1), Point3(1, 1, 1), Point3(2, 1, 1)}, {3, 4, 5}));   // crossing
  EXPECT_FALSE(pairMeeting({Point3(1, 1, 1), Point3(1, 2, 1), Point3(2, 1, 1)}, {3, 4, 5}));   // above
  // In the plane: overlapping, one corner on the first's edge, and apart across it.
  EXPECT_TRUE(pairMeeting({Point3(1, 1, 0), Point3(5, 1, 0), Point3(1, 5, 0)}, {3, 4, 5}));
  EXPECT_TRUE(pairMeeting({Point3(2, 2, 0), Point3(5, 2, 0), Point3(2, 5, 0)}, {3, 4, 5}));
  EXPECT_FALSE(pairMeeting({Point3(2.5, 2, 0), Point3(5, 2, 0), Point3(2.5, 5, 0)}, {3, 4, 5}));
  EXPECT_FALSE(pairMeeting({Point3(-1, -1, 0), Point3(-2, -1, 0), Point3(-1, -2, 0)}, {3, 4, 5}));
}

TEST(SurfaceSelfIntersection, TrianglesSharingAnEdgeMeetOnlyWhenFoldedFlat) {
  EXPECT_TRUE(pairMeeting({Point3(1, 1, 0)}, {1, 0, 3}));     // in the plane, on the first's side
  EXPECT_FALSE(pairMeeting({Point3(1, -1, 0)}, {1, 0, 3}));   // in the plane, across the edge
  EXPECT_FALSE(pairMeeting({Point3(1, 1, 1e-300)}, {1, 0, 3}));  // a hair above the plane
}

TEST(SurfaceSelfIntersection, TrianglesOfDifferentComponentsMayMeet) {
  const std::vector<Point3> vertices = {Point3(0, 0, 0), Point3(4, 0, 0), Point3(0, 4, 0),
                                        Point3(1, 1, -1), Point3(1, 2, 1), Point3(2, 1, 1)};
  EXPECT_TRUE(detail::firstSelfIntersection(vertices, {{0, 1, 2}, {3, 4, 5}}, {0, 0}));
  EXPECT_FALSE(detail::firstSelfIntersection(vertices, {{0, 1, 2}, {3, 4, 5}}, {0, 1}));
}

TEST(Mesh, AcceptsComponentsThatOverlapEachOther) {
  TriangleSoup soup = boxSoup(Point3(0, 0, 0), Point3(2, 2, 2));
  append(soup, boxSoup(Point3(1, 1, 1), Point3(3, 3, 3)));
  EXPECT_EQ(problemOf(soup), "");
}

TEST(Mesh, SeparatesComponentsInOrderOfTheirFirstTriangle) {
  TriangleSoup soup = boxSoup(Point3(3, 0, 0), Point3(5, 1, 1));
  TriangleSoup inner = boxSoup(Point3(0, 0, 0), Point3(1, 1, 1));
  reverseTriangles(inner);
  append(soup, inner);
  std::swap(soup.triangles[1], soup.triangles[20]);  // interleave the components

  std::vector<std::string> warnings;
  const Mesh mesh = Mesh::fromSoup(soup, "two", &warnings);
  ASSERT_EQ(mesh.componentCount(), 2u);
  EXPECT_EQ(mesh.volume(), 3.0);
  EXPECT_EQ(warnings, std::vector<std::string>{"two: component 1 was inside-out and has been flipped"});
  const std::vector<std::uint32_t>& component = mesh.triangleComponents();
  ASSERT_EQ(component.size(), 24u);
  EXPECT_EQ(component[0], 0u);
  EXPECT_EQ(component[1], 1u);
  EXPECT_EQ(component[20], 0u);
  EXPECT_EQ(std::count(component.begin(), component.end(), 0u), 12);
  EXPECT_EQ(mesh.componentBounds()[0].min(), Point3(3, 0, 0));
  EXPECT_EQ(mesh.componentBounds()[0].max(), Point3(5, 1, 1));
  EXPECT_EQ(mesh.componentBounds()[1].min(), Point3(0, 0, 0));
  EXPECT_EQ(mesh.componentBounds()[1].max(), Point3(1, 1, 1));
  EXPECT_EQ(mesh.bounds().min(), Point3(0, 0, 0));
  EXPECT_EQ(mesh.bounds().max(), Point3(5, 1, 1));
  for (std::size_t c = 0; c < 2; ++c) {
    const Point3& representative = mesh.vertices()[mesh.componentRepresentatives()[c]];
    EXPECT_TRUE(mesh.componentBounds()[c].contains(representative));
  }
  // Only the inner component was flipped: its first triangle is now outward.
  for (std::size_t t = 12; t < 24; ++t) {
    const TriangleIndices& triangle = mesh.triangles()[t];
    const Point3 normal = (mesh.vertices()[triangle[1]] - mesh.vertices()[triangle[0]])
                              .cross(mesh.vertices()[triangle[2]] - mesh.vertices()[triangle[0]]);
    const Point3 outward = mesh.vertices()[triangle[0]] - Point3(0.5, 0.5, 0.5);
    if (component[t] == 1) {
      EXPECT_GT(normal.dot(outward), 0) << "triangle " << t;
    }
  }
}

TEST(Mesh, TwoCubesSharingOnlyAVertexAreTwoComponents) {
  TriangleSoup soup = boxSoup();
  append(soup, boxSoup(Point3(1, 1, 1), Point3(2, 2, 2)));
  const Mesh mesh = Mesh::fromSoup(soup, "pinched");
  EXPECT_EQ(mesh.vertices().size(), 15u);
  EXPECT_EQ(mesh.componentCount(), 2u);
  EXPECT_EQ(mesh.volume(), 2.0);
}

TEST(Mesh, MeasuresTheVolumeOfAGeneralTetrahedron) {
  TriangleSoup soup;
  soup.vertices = {Point3(1, 1, 1), Point3(4, 1, 1), Point3(1, 3, 1), Point3(1, 1, 7)};
  soup.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  const Mesh mesh = Mesh::fromSoup(soup, "tetrahedron");
  EXPECT_DOUBLE_EQ(mesh.volume(), 3.0 * 2.0 * 6.0 / 6.0);
}

TEST(Mesh, TranslatesAndChecksAgain) {
  const Mesh cube = Mesh::fromSoup(boxSoup(), "cube");
  const Mesh moved = cube.translated(Point3(0.5, -2, 3), "moved");
  EXPECT_EQ(moved.bounds().min(), Point3(0.5, -2, 3));
  EXPECT_EQ(moved.bounds().max(), Point3(1.5, -1, 4));
  EXPECT_EQ(moved.volume(), 1.0);
  EXPECT_EQ(moved.triangles(), cube.triangles());
}

TEST(Mesh, TranslationThatMergesVerticesIsAnError) {
  const Mesh tiny = Mesh::fromSoup(boxSoup(Point3::Zero(), Point3(1e-10, 1e-10, 1e-10)), "tiny");
  try {
    tiny.translated(Point3(1e10, 0, 0), "far");
    FAIL() << "rounding merges the cube's vertices";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "far");
    EXPECT_TRUE(contains(error.problem(), "has zero area"));
  }
}

TEST(Mesh, IsDeterministic) {
  TriangleSoup soup = boxSoup();
  append(soup, boxSoup(Point3(2, 0, 0), Point3(3, 1, 1)));
  const Mesh first = Mesh::fromSoup(soup, "a");
  const Mesh second = Mesh::fromSoup(soup, "a");
  EXPECT_EQ(first.vertices(), second.vertices());
  EXPECT_EQ(first.triangles(), second.triangles());
  EXPECT_EQ(first.triangleComponents(), second.triangleComponents());
  EXPECT_EQ(first.componentRepresentatives(), second.componentRepresentatives());
}

// Any box with integer corners, its triangles shuffled, each with its own copies of
// its corners in a rotated order, and possibly inside-out: welding gives back the 8
// corners and the exact volume, and only an inside-out box is flipped.
RC_GTEST_PROP(MeshProperty, WeldsAndOrientsShuffledBoxSoups, ()) {
  const auto coordinate = rc::gen::inRange(-1000, 1000);
  const auto extent = rc::gen::inRange(1, 100);
  const Point3 low(*coordinate, *coordinate, *coordinate);
  const Point3 high = low + Point3(*extent, *extent, *extent);
  const bool insideOut = *rc::gen::arbitrary<bool>();
  const TriangleSoup box = boxSoup(low, high);

  std::vector<TriangleIndices> triangles = box.triangles;
  if (insideOut) {
    for (TriangleIndices& triangle : triangles) std::swap(triangle[1], triangle[2]);
  }
  const std::vector<int> keys = *rc::gen::container<std::vector<int>>(12, rc::gen::arbitrary<int>());
  std::vector<std::size_t> order(12);
  for (std::size_t t = 0; t < 12; ++t) order[t] = t;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  TriangleSoup soup;
  for (std::size_t t : order) {
    const int rotation = *rc::gen::inRange(0, 3);
    const auto first = static_cast<std::uint32_t>(soup.vertices.size());
    for (int corner = 0; corner < 3; ++corner) {
      soup.vertices.push_back(box.vertices[triangles[t][(corner + rotation) % 3]]);
    }
    soup.triangles.push_back({first, first + 1, first + 2});
  }

  std::vector<std::string> warnings;
  const Mesh mesh = Mesh::fromSoup(soup, "box", &warnings);
  RC_ASSERT(mesh.vertices().size() == 8u);
  RC_ASSERT(mesh.triangles().size() == 12u);
  RC_ASSERT(mesh.componentCount() == 1u);
  RC_ASSERT(mesh.volume() == (high - low).prod());
  RC_ASSERT(mesh.bounds().min() == low);
  RC_ASSERT(mesh.bounds().max() == high);
  RC_ASSERT(warnings.size() == (insideOut ? 1u : 0u));
}

}  // namespace
}  // namespace freespace
