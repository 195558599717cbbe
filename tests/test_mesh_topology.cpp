// MeshTopology: edges with their triangles, exact convexity and pointedness, on meshes
// whose answers are known by construction (boxes, tetrahedra, prisms, pyramids, touching
// components) and on random boxes and tetrahedra.

#include "freespace/geometry/mesh_topology.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "freespace/scenes/scene_generator.h"
#include "test_meshes.h"

namespace freespace {
namespace {

using testing::boxMesh;
using testing::boxSoup;
using testing::joinSoups;
using testing::tetrahedronMesh;

MeshTopology topologyOf(const Mesh& mesh) {
  PredicateStatistics statistics;
  return MeshTopology(mesh, statistics);
}

std::uint32_t vertexAt(const Mesh& mesh, const Point3& position) {
  const auto found = std::find(mesh.vertices().begin(), mesh.vertices().end(), position);
  EXPECT_NE(found, mesh.vertices().end()) << "no vertex at " << position.transpose();
  return static_cast<std::uint32_t>(found - mesh.vertices().begin());
}

const MeshEdge& edgeBetween(const MeshTopology& topology, const Mesh& mesh, const Point3& a, const Point3& b) {
  const std::uint32_t from = vertexAt(mesh, a), to = vertexAt(mesh, b);
  for (const std::uint32_t e : topology.vertexEdges(from)) {
    if (topology.otherEnd(e, from) == to) return topology.edges()[e];
  }
  ADD_FAILURE() << "no edge from " << a.transpose() << " to " << b.transpose();
  return topology.edges().front();
}

int convexEdgeCount(const MeshTopology& topology) {
  return static_cast<int>(std::count_if(topology.edges().begin(), topology.edges().end(),
                                        [](const MeshEdge& edge) { return edge.convex; }));
}

std::vector<Point3> pointedVertices(const Mesh& mesh, const MeshTopology& topology) {
  std::vector<Point3> pointed;
  for (std::uint32_t v = 0; v < mesh.vertices().size(); ++v) {
    if (topology.isPointed(v)) pointed.push_back(mesh.vertices()[v]);
  }
  return pointed;
}

bool runs(const TriangleIndices& triangle, std::uint32_t from, std::uint32_t to) {
  for (int side = 0; side < 3; ++side) {
    if (triangle[side] == from && triangle[(side + 1) % 3] == to) return true;
  }
  return false;
}

/// Every triangle side is one side of exactly one edge, `left` runs from -> to and
/// `right` to -> from, and each edge is listed at both its ends.
void expectConsistentAdjacency(const Mesh& mesh, const MeshTopology& topology) {
  EXPECT_EQ(topology.edges().size() * 2, mesh.triangles().size() * 3);
  std::set<std::pair<std::uint32_t, std::uint32_t>> ends;
  for (std::uint32_t e = 0; e < topology.edges().size(); ++e) {
    const MeshEdge& edge = topology.edges()[e];
    EXPECT_LT(edge.from, edge.to);
    EXPECT_TRUE(ends.insert({edge.from, edge.to}).second) << "edge listed twice";
    EXPECT_TRUE(runs(mesh.triangles()[edge.left], edge.from, edge.to));
    EXPECT_TRUE(runs(mesh.triangles()[edge.right], edge.to, edge.from));
    for (const std::uint32_t end : {edge.from, edge.to}) {
      const std::vector<std::uint32_t>& incident = topology.vertexEdges(end);
      EXPECT_EQ(std::count(incident.begin(), incident.end(), e), 1);
    }
    EXPECT_EQ(topology.otherEnd(e, edge.from), edge.to);
    EXPECT_EQ(topology.otherEnd(e, edge.to), edge.from);
  }
}

/// How a box face is cut into triangles: along either diagonal, or into four around a
/// point inside it.
struct FaceSplit {
  enum Kind { FirstDiagonal, SecondDiagonal, Fan } kind = FirstDiagonal;
  Point3 fanCentre = Point3::Zero();
};

/// A box whose faces (in the order -z, +z, -y, +y, -x, +x) are split as `splits` say.
TriangleSoup splitBoxSoup(const Point3& low, const Point3& high, const std::vector<FaceSplit>& splits) {
  // The faces' corners, counter-clockwise seen from outside.
  static const std::uint32_t kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  TriangleSoup soup = boxSoup(low, high);
  soup.triangles.clear();
  for (int f = 0; f < 6; ++f) {
    const std::uint32_t* q = kFaces[f];
    switch (splits[f].kind) {
      case FaceSplit::FirstDiagonal:
        soup.triangles.insert(soup.triangles.end(), {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}});
        break;
      case FaceSplit::SecondDiagonal:
        soup.triangles.insert(soup.triangles.end(), {{q[0], q[1], q[3]}, {q[1], q[2], q[3]}});
        break;
      case FaceSplit::Fan: {
        const auto centre = static_cast<std::uint32_t>(soup.vertices.size());
        soup.vertices.push_back(splits[f].fanCentre);
        for (int i = 0; i < 4; ++i) soup.triangles.push_back({q[i], q[(i + 1) % 4], centre});
        break;
      }
    }
  }
  return soup;
}

/// The unit box with its top face split into four triangles around (0.5, 0.5, 1 + lift).
Mesh boxWithTopCentre(double lift) {
  std::vector<FaceSplit> splits(6);
  splits[1] = {FaceSplit::Fan, Point3(0.5, 0.5, 1 + lift)};
  return Mesh::fromSoup(splitBoxSoup(Point3(0, 0, 0), Point3(1, 1, 1), splits), "box with top centre");
}

TriangleSoup tetrahedronSoup(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return TriangleSoup{{a, b, c, d}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
}

/// Integer points around the origin in counter-clockwise order, one per direction.
Polygon2 starAroundOrigin(std::vector<Point2> points) {
  const auto lowerHalf = [](const Point2& p) { return p.y() < 0 || (p.y() == 0 && p.x() < 0); };
  const auto cross = [](const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); };
  const auto before = [&](const Point2& a, const Point2& b) {
    return lowerHalf(a) != lowerHalf(b) ? lowerHalf(b) : cross(a, b) > 0;
  };
  std::sort(points.begin(), points.end(), before);
  const auto sameDirection = [&](const Point2& a, const Point2& b) { return !before(a, b) && !before(b, a); };
  points.erase(std::unique(points.begin(), points.end(), sameDirection), points.end());
  return points;
}

const Polygon2 kLOutline{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
const Point2 kLInnerCorner{1, 1};

}  // namespace

TEST(MeshTopology, CubeHasTwelveConvexEdgesAndSixFlatDiagonals) {
  const Mesh cube = boxMesh(Point3(0, 0, 0), Point3(1, 1, 1));
  const MeshTopology topology = topologyOf(cube);
  expectConsistentAdjacency(cube, topology);
  ASSERT_EQ(topology.edges().size(), 18u);
  for (const MeshEdge& edge : topology.edges()) {
    const Point3 direction = cube.vertices()[edge.to] - cube.vertices()[edge.from];
    const bool boxEdge = (direction.array() != 0).count() == 1;
    EXPECT_EQ(edge.convex, boxEdge) << "edge " << edge.from << "-" << edge.to;
  }
  EXPECT_EQ(convexEdgeCount(topology), 12);
  EXPECT_EQ(pointedVertices(cube, topology).size(), 8u);
}

TEST(MeshTopology, TetrahedronIsConvexAndPointedEverywhere) {
  const Mesh tetrahedron = tetrahedronMesh(Point3(0, 0, 0), Point3(3, 0, 0), Point3(0, 2, 0), Point3(1, 1, 5));
  const MeshTopology topology = topologyOf(tetrahedron);
  expectConsistentAdjacency(tetrahedron, topology);
  EXPECT_EQ(topology.edges().size(), 6u);
  EXPECT_EQ(convexEdgeCount(topology), 6);
  EXPECT_EQ(pointedVertices(tetrahedron, topology).size(), 4u);
}

TEST(MeshTopology, CentreOfAFlatFaceIsNotPointedAndItsEdgesAreFlat) {
  const Mesh box = boxWithTopCentre(0);
  const MeshTopology topology = topologyOf(box);
  expectConsistentAdjacency(box, topology);
  EXPECT_EQ(topology.edges().size(), 21u);
  const std::uint32_t centre = vertexAt(box, Point3(0.5, 0.5, 1));
  ASSERT_EQ(topology.vertexEdges(centre).size(), 4u);
  for (const std::uint32_t e : topology.vertexEdges(centre)) EXPECT_FALSE(topology.edges()[e].convex);
  EXPECT_FALSE(topology.isPointed(centre));
  EXPECT_EQ(convexEdgeCount(topology), 12);
  EXPECT_EQ(pointedVertices(box, topology).size(), 8u) << "the corners";
}

TEST(MeshTopology, TopCentreRaisedByATinyAmountIsPointedLoweredIsNot) {
  const double lift = std::ldexp(1.0, -40);
  const Mesh raised = boxWithTopCentre(lift);
  const MeshTopology raisedTopology = topologyOf(raised);
  const std::uint32_t raisedCentre = vertexAt(raised, Point3(0.5, 0.5, 1 + lift));
  EXPECT_TRUE(raisedTopology.isPointed(raisedCentre));
  for (const std::uint32_t e : raisedTopology.vertexEdges(raisedCentre)) EXPECT_TRUE(raisedTopology.edges()[e].convex);

  // A dent: every neighbour lies above the centre, so the edge directions span a
  // pointed cone, but the solid is the other side of it.
  const Mesh dented = boxWithTopCentre(-lift);
  const MeshTopology dentedTopology = topologyOf(dented);
  const std::uint32_t dentedCentre = vertexAt(dented, Point3(0.5, 0.5, 1 - lift));
  EXPECT_FALSE(dentedTopology.isPointed(dentedCentre));
  for (const std::uint32_t e : dentedTopology.vertexEdges(dentedCentre)) EXPECT_FALSE(dentedTopology.edges()[e].convex);
  EXPECT_EQ(pointedVertices(dented, dentedTopology).size(), 8u);
}

TEST(MeshTopology, LShapedPrismHasOneReflexEdgeAtTheInnerCorner) {
  const Mesh prism = makeCheckedMesh(extrudePolygon(kLOutline, 0, 1), "L prism");
  const MeshTopology topology = topologyOf(prism);
  expectConsistentAdjacency(prism, topology);
  const auto cornerIndex = [](const Point3& p) {
    return std::find(kLOutline.begin(), kLOutline.end(), Point2(p.x(), p.y())) - kLOutline.begin();
  };
  const auto n = static_cast<long>(kLOutline.size());
  for (const MeshEdge& edge : topology.edges()) {
    const Point3& a = prism.vertices()[edge.from];
    const Point3& b = prism.vertices()[edge.to];
    const long step = (cornerIndex(b) - cornerIndex(a) + n) % n;
    const bool vertical = step == 0;
    const bool outlineSide = a.z() == b.z() && (step == 1 || step == n - 1);
    const bool innerCornerEdge = vertical && Point2(a.x(), a.y()) == kLInnerCorner;
    EXPECT_EQ(edge.convex, (vertical || outlineSide) && !innerCornerEdge)
        << a.transpose() << " - " << b.transpose();
  }
  EXPECT_FALSE(edgeBetween(topology, prism, Point3(1, 1, 0), Point3(1, 1, 1)).convex);
  for (const Point3& p : prism.vertices()) {
    const bool innerCorner = Point2(p.x(), p.y()) == kLInnerCorner;
    EXPECT_EQ(topology.isPointed(vertexAt(prism, p)), !innerCorner) << p.transpose();
  }
}

TEST(MeshTopology, ApexOfAPyramidOverAnLIsPointedThoughOneOfItsEdgesIsReflex) {
  TriangleSoup pyramid;
  for (const Point2& corner : kLOutline) pyramid.vertices.emplace_back(corner.x(), corner.y(), 0);
  const Point3 apex(0.5, 0.5, 1);
  pyramid.vertices.push_back(apex);
  // Base: a fan from corner 0 (it sees the whole L), facing down; sides facing out.
  for (std::uint32_t i = 1; i + 1 < kLOutline.size(); ++i) pyramid.triangles.push_back({0, i + 1, i});
  for (std::uint32_t i = 0; i < kLOutline.size(); ++i) {
    pyramid.triangles.push_back({i, static_cast<std::uint32_t>((i + 1) % kLOutline.size()), 6});
  }
  const Mesh mesh = makeCheckedMesh(pyramid, "L pyramid");
  const MeshTopology topology = topologyOf(mesh);
  expectConsistentAdjacency(mesh, topology);
  const Point3 innerCorner(kLInnerCorner.x(), kLInnerCorner.y(), 0);
  EXPECT_FALSE(edgeBetween(topology, mesh, apex, innerCorner).convex);
  EXPECT_EQ(convexEdgeCount(topology), 11) << "6 base sides, 5 of the 6 apex edges";
  EXPECT_TRUE(topology.isPointed(vertexAt(mesh, apex)));
  EXPECT_FALSE(topology.isPointed(vertexAt(mesh, innerCorner)));
  EXPECT_EQ(pointedVertices(mesh, topology).size(), 6u);
}

TEST(MeshTopology, VertexInTheMiddleOfAStraightEdgeRunIsAWedgeNotPointed) {
  // A 2 x 2 square prism with an extra corner at (1, 0): the top and bottom front edges
  // run straight through it, and the front wall is split there.
  const Mesh prism = makeCheckedMesh(extrudePolygon({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, 0, 1), "wedge");
  const MeshTopology topology = topologyOf(prism);
  expectConsistentAdjacency(prism, topology);
  for (const double z : {0.0, 1.0}) {
    EXPECT_FALSE(topology.isPointed(vertexAt(prism, Point3(1, 0, z))));
    EXPECT_TRUE(edgeBetween(topology, prism, Point3(0, 0, z), Point3(1, 0, z)).convex);
    EXPECT_TRUE(edgeBetween(topology, prism, Point3(1, 0, z), Point3(2, 0, z)).convex);
  }
  EXPECT_FALSE(edgeBetween(topology, prism, Point3(1, 0, 0), Point3(1, 0, 1)).convex) << "inside the front wall";
  EXPECT_EQ(pointedVertices(prism, topology).size(), 8u);
  EXPECT_EQ(convexEdgeCount(topology), 14) << "the 12 box edges, two of them in two pieces";
}

TEST(MeshTopology, ComponentsKeepSeparateAdjacency) {
  const Mesh mesh = Mesh::fromSoup(
      joinSoups({boxSoup(Point3(0, 0, 0), Point3(1, 1, 1)), boxSoup(Point3(3, 0, 0), Point3(4, 2, 1))}), "two boxes");
  ASSERT_EQ(mesh.componentCount(), 2u);
  const MeshTopology topology = topologyOf(mesh);
  expectConsistentAdjacency(mesh, topology);
  EXPECT_EQ(topology.edges().size(), 36u);
  EXPECT_EQ(convexEdgeCount(topology), 24);
  const std::vector<std::uint32_t>& component = mesh.triangleComponents();
  for (std::uint32_t e = 0; e < topology.edges().size(); ++e) {
    const MeshEdge& edge = topology.edges()[e];
    EXPECT_EQ(component[edge.left], component[edge.right]);
    const bool firstBox = mesh.vertices()[edge.from].x() < 2;
    EXPECT_EQ(mesh.vertices()[edge.to].x() < 2, firstBox);
    EXPECT_EQ(component[edge.left], firstBox ? component.front() : component.back());
  }
  EXPECT_EQ(pointedVertices(mesh, topology).size(), 16u);
}

TEST(MeshTopology, TetrahedraTouchingAtAVertexArePointedThereOnlyOnOneSide) {
  const Point3 v(0, 0, 0);
  const TriangleSoup below = tetrahedronSoup(v, Point3(1, 0, -1), Point3(0, 1, -1), Point3(1, 1, -1));
  const TriangleSoup besideBelow = tetrahedronSoup(v, Point3(-1, 0, -1), Point3(0, -1, -2), Point3(-1, -1, -1));
  // No ray of `above` is opposite to one of `below`, yet no plane has all of them on one side.
  const TriangleSoup above = tetrahedronSoup(v, Point3(-1, 0, 2), Point3(0, -1, 2), Point3(-1, -1, 1));

  const Mesh sameSide = Mesh::fromSoup(joinSoups({below, besideBelow}), "same side");
  const MeshTopology sameSideTopology = topologyOf(sameSide);
  expectConsistentAdjacency(sameSide, sameSideTopology);
  ASSERT_EQ(sameSideTopology.vertexEdges(vertexAt(sameSide, v)).size(), 6u) << "two fans at one vertex";
  EXPECT_TRUE(sameSideTopology.isPointed(vertexAt(sameSide, v)));

  const Mesh opposite = Mesh::fromSoup(joinSoups({below, above}), "opposite sides");
  const MeshTopology oppositeTopology = topologyOf(opposite);
  EXPECT_FALSE(oppositeTopology.isPointed(vertexAt(opposite, v))) << "each fan is pointed, their union is not";
  EXPECT_EQ(pointedVertices(opposite, oppositeTopology).size(), 6u);
  EXPECT_EQ(convexEdgeCount(oppositeTopology), 12);
}

TEST(MeshTopology, CountsOrientationPredicates) {
  PredicateStatistics statistics;
  const MeshTopology topology(boxMesh(Point3(0, 0, 0), Point3(1, 1, 1)), statistics);
  const PredicateStatistics::KindCounts& counts = statistics.counts(PredicateKind::Orientation);
  EXPECT_GT(counts.total(), topology.edges().size()) << "one per edge, more for the vertex cones";
  EXPECT_GE(counts.identities, 6u) << "the flat diagonals are exact zeros";
  for (const PredicateKind other : {PredicateKind::EdgeFacet, PredicateKind::Other}) {
    EXPECT_EQ(statistics.counts(other).total(), 0u);
  }
}

RC_GTEST_PROP(MeshTopology, RandomTetrahedraAreConvexAndPointedEverywhere, ()) {
  const auto gridPoint = [] {
    return Point3(*rc::gen::inRange(-4, 5), *rc::gen::inRange(-4, 5), *rc::gen::inRange(-4, 5));
  };
  const Point3 a = gridPoint(), b = gridPoint(), c = gridPoint(), d = gridPoint();
  RC_PRE((b - a).cross(c - a).dot(d - a) != 0.0);  // small integers: exact
  const Mesh tetrahedron = tetrahedronMesh(a, b, c, d);
  const MeshTopology topology = topologyOf(tetrahedron);
  RC_ASSERT(topology.edges().size() == 6u);
  RC_ASSERT(convexEdgeCount(topology) == 6);
  RC_ASSERT(pointedVertices(tetrahedron, topology).size() == 4u);
}

RC_GTEST_PROP(MeshTopology, RandomlySplitBoxesHaveTwelveConvexEdgesAndEightPointedCorners, ()) {
  const Point3 low(*rc::gen::inRange(-5, 5), *rc::gen::inRange(-5, 5), *rc::gen::inRange(-5, 5));
  const Point3 size(*rc::gen::inRange(1, 6), *rc::gen::inRange(1, 6), *rc::gen::inRange(1, 6));
  const Point3 high = low + size;
  std::vector<FaceSplit> splits(6);
  for (int f = 0; f < 6; ++f) {
    splits[f].kind = static_cast<FaceSplit::Kind>(*rc::gen::inRange(0, 3));
    // A fan centre strictly inside the face, at eighths of the box.
    const int normalAxis = 2 - f / 2;
    for (int axis = 0; axis < 3; ++axis) {
      splits[f].fanCentre[axis] = axis == normalAxis ? (f % 2 == 0 ? low : high)[axis]
                                                     : low[axis] + size[axis] * *rc::gen::inRange(1, 8) / 8.0;
    }
  }
  const Mesh box = Mesh::fromSoup(splitBoxSoup(low, high, splits), "split box");
  const MeshTopology topology = topologyOf(box);
  const auto isCorner = [&](const Point3& p) {
    return ((p.array() == low.array()) || (p.array() == high.array())).all();
  };
  for (const MeshEdge& edge : topology.edges()) {
    const Point3& a = box.vertices()[edge.from];
    const Point3& b = box.vertices()[edge.to];
    const bool boxEdge = isCorner(a) && isCorner(b) && ((b - a).array() != 0).count() == 1;
    RC_ASSERT(edge.convex == boxEdge);
  }
  RC_ASSERT(convexEdgeCount(topology) == 12);
  for (const Point3& p : pointedVertices(box, topology)) RC_ASSERT(isCorner(p));
  RC_ASSERT(pointedVertices(box, topology).size() == 8u);
}

RC_GTEST_PROP(MeshTopology, PyramidsOverStarPolygonsArePointedAtTheApexAndAtConvexCorners, ()) {
  // A pyramid over a polygon that is star-shaped around the origin, its base split into
  // a fan around the origin and its apex anywhere above the base plane. Both the apex
  // edge to a corner and the corner itself are convex (pointed) exactly when the
  // polygon turns left there; the apex is always pointed, the base centre never. One
  // point on each half axis keeps the origin strictly inside, every turn around it
  // below pi.
  std::vector<Point2> points{{*rc::gen::inRange(1, 7), 0},
                             {0, *rc::gen::inRange(1, 7)},
                             {-*rc::gen::inRange(1, 7), 0},
                             {0, -*rc::gen::inRange(1, 7)}};
  const int extraPoints = *rc::gen::inRange(0, 10);
  while (static_cast<int>(points.size()) < 4 + extraPoints) {
    const Point2 p(*rc::gen::inRange(-6, 7), *rc::gen::inRange(-6, 7));
    if (p != Point2(0, 0)) points.push_back(p);
  }
  const Polygon2 polygon = starAroundOrigin(points);
  const std::size_t m = polygon.size();
  const auto turn = [&](std::size_t i) {
    const Point2 &a = polygon[(i + m - 1) % m], &b = polygon[i], &c = polygon[(i + 1) % m];
    return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  };

  TriangleSoup soup;
  for (const Point2& p : polygon) soup.vertices.emplace_back(p.x(), p.y(), 0);
  const Point3 apex(*rc::gen::inRange(-6, 7), *rc::gen::inRange(-6, 7), *rc::gen::inRange(1, 6));
  const auto apexIndex = static_cast<std::uint32_t>(m), centreIndex = apexIndex + 1;
  soup.vertices.push_back(apex);
  soup.vertices.emplace_back(0, 0, 0);
  for (std::uint32_t i = 0; i < m; ++i) {
    const auto next = static_cast<std::uint32_t>((i + 1) % m);
    soup.triangles.push_back({i, next, apexIndex});
    soup.triangles.push_back({centreIndex, next, i});
  }
  const Mesh pyramid = makeCheckedMesh(soup, "star pyramid");
  const MeshTopology topology = topologyOf(pyramid);

  RC_ASSERT(topology.isPointed(vertexAt(pyramid, apex)));
  RC_ASSERT(!topology.isPointed(vertexAt(pyramid, Point3(0, 0, 0))));
  int convexCorners = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const Point3 corner(polygon[i].x(), polygon[i].y(), 0);
    const bool convex = turn(i) > 0;
    convexCorners += convex ? 1 : 0;
    RC_ASSERT(topology.isPointed(vertexAt(pyramid, corner)) == convex);
    RC_ASSERT(edgeBetween(topology, pyramid, apex, corner).convex == convex);
  }
  RC_ASSERT(convexEdgeCount(topology) == static_cast<int>(m) + convexCorners);  // base sides, apex edges
}

}  // namespace freespace
