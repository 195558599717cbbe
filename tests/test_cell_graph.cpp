// The free cell graph (docs/design.md section 7) on the bundled scenes: its nodes
// and edges against the free cells, the exact locate and the clearance.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <tuple>

#include "bundled_problem.h"
#include "freespace/numbers/angle_reduction.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/scenes/scene_generator.h"
#include "freespace/space/free_space.h"
#include "freespace/topology/slice_faces.h"
#include "geometry/disjoint_sets.h"
#include "random_configurations.h"
#include "temp_dir.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

class BundledCellGraph : public ::testing::TestWithParam<std::string> {
 protected:
  static LoadedProblem problem() { return loadBundledProblem(GetParam()); }
};

/// Components of the graph: the nodes of one cell form one component, and no edge
/// joins two cells.
TEST_P(BundledCellGraph, ComponentsAreTheCells) {
  const LoadedProblem loaded = problem();
  const FreeSpace space(loaded.robot, loaded.world);
  const auto start = std::chrono::steady_clock::now();
  const CellGraph& graph = space.cellGraph();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << GetParam() << ": " << graph.criticalAngles().size() << " critical angles, " << graph.nodes().size()
            << " nodes, " << graph.edges().size() << " edges, " << seconds << " s\n";
  detail::DisjointSets components(graph.nodes().size());
  for (const CellGraphEdge& edge : graph.edges()) {
    EXPECT_EQ(graph.nodes()[edge.from].cell, graph.nodes()[edge.to].cell);
    components.unite(edge.from, edge.to);
  }
  std::vector<std::optional<std::uint32_t>> componentOfCell(space.cellCount());
  for (std::uint32_t node = 0; node < graph.nodes().size(); ++node) {
    auto& component = componentOfCell[graph.nodes()[node].cell];
    if (!component) component = components.find(node);
    EXPECT_EQ(*component, components.find(node)) << "node " << node << " of cell " << graph.nodes()[node].cell;
  }
  for (std::size_t cell = 0; cell < componentOfCell.size(); ++cell) EXPECT_TRUE(componentOfCell[cell]) << cell;
}

/// The start's and the goal's nodes are joined by a route of edges exactly when the
/// problem was designed solvable; consecutive nodes of the route share an edge.
TEST_P(BundledCellGraph, StartAndGoalNodesAreJoinedExactlyWhenSolvable) {
  const LoadedProblem loaded = problem();
  const FreeSpace space(loaded.robot, loaded.world);
  const CellGraph& graph = space.cellGraph();
  const std::optional<std::uint32_t> start = space.nodeOf(loaded.problem.start),
                                     goal = space.nodeOf(loaded.problem.goal);
  ASSERT_TRUE(start && goal);
  const std::optional<std::vector<std::uint32_t>> route = graph.route(*start, *goal);
  EXPECT_EQ(route.has_value(), makeScene(GetParam()).expectSolvable);
  if (!route) return;
  EXPECT_EQ(route->front(), *start);
  EXPECT_EQ(route->back(), *goal);
  for (std::size_t i = 0; i + 1 < route->size(); ++i) {
    const auto joins = [&](const CellGraphEdge& edge) {
      return (edge.from == (*route)[i] && edge.to == (*route)[i + 1]) ||
             (edge.to == (*route)[i] && edge.from == (*route)[i + 1]);
    };
    EXPECT_TRUE(std::any_of(graph.edges().begin(), graph.edges().end(), joins)) << i;
  }
}

/// Edges join the last interval of one node to the first of the next, at the
/// critical angle between them.
TEST_P(BundledCellGraph, EdgesJoinNeighbouringIntervals) {
  const LoadedProblem loaded = problem();
  const FreeSpace space(loaded.robot, loaded.world);
  const CellGraph& graph = space.cellGraph();
  const std::size_t intervals = graph.intervalCount();
  for (const CellGraphEdge& edge : graph.edges()) {
    const CellGraphNode& from = graph.nodes()[edge.from];
    const CellGraphNode& to = graph.nodes()[edge.to];
    EXPECT_EQ((from.lastInterval + 1) % intervals, to.firstInterval);
    EXPECT_EQ(edge.angle, to.firstInterval);
  }
  for (const CellGraphNode& node : graph.nodes()) EXPECT_LE(node.firstInterval, node.lastInterval);
}

/// Whether each node's edges (CellGraph::edgesAt) are the edges naming it, in order.
void expectEdgesIndexedByNode(const CellGraph& graph) {
  for (std::uint32_t node = 0; node < graph.nodes().size(); ++node) {
    std::vector<std::uint32_t> naming;
    for (std::uint32_t edge = 0; edge < graph.edges().size(); ++edge) {
      if (graph.edges()[edge].from == node || graph.edges()[edge].to == node) naming.push_back(edge);
    }
    const CellGraph::EdgeIndices indexed = graph.edgesAt(node);
    EXPECT_EQ(std::vector<std::uint32_t>(indexed.begin(), indexed.end()), naming) << "node " << node;
  }
}

TEST_P(BundledCellGraph, EachNodesEdgesAreIndexed) {
  const LoadedProblem loaded = problem();
  const FreeSpace space(loaded.robot, loaded.world);
  expectEdgesIndexedByNode(space.cellGraph());
}

/// Every node's point lies in its face: free in the node's cell by the exact
/// collision test and locate, and nodeOf gives the node back.
TEST_P(BundledCellGraph, NodePointsLieInTheirFaces) {
  const LoadedProblem loaded = problem();
  const FreeSpace space(loaded.robot, loaded.world);
  const CellGraph& graph = space.cellGraph();
  const double scale = space.meshes().scale;
  for (std::uint32_t index = 0; index < graph.nodes().size(); ++index) {
    const CellGraphNode& node = graph.nodes()[index];
    const Pose2 pose{node.point[0] / scale, node.point[1] / scale, node.sample.radians()};
    const Location location = space.locate(pose);
    ASSERT_TRUE(location.free) << "node " << index;
    EXPECT_EQ(location.cell, node.cell) << "node " << index;
    EXPECT_EQ(space.nodeOf(pose), index);
    if (std::isfinite(node.box[0])) {
      EXPECT_LE(node.box[0], node.point[0]);
      EXPECT_LE(node.point[0], node.box[2]);
      EXPECT_LE(node.box[1], node.point[1]);
      EXPECT_LE(node.point[1], node.box[3]);
    }
  }
}

/// Random configurations: a node exactly for the free ones, of their cell, over an
/// interval holding their angle; and a configuration moved by less than its
/// clearance at the same angle (inside a disc of free configurations) stays in
/// the same node.
TEST_P(BundledCellGraph, ConfigurationsFindTheirNodes) {
  const LoadedProblem loaded = problem();
  const FreeSpace space(loaded.robot, loaded.world);
  const CellGraph& graph = space.cellGraph();
  RandomConfigurations random(space, 2026);
  std::mt19937 turn(7);
  int free = 0, moved = 0;
  for (int sample = 0; sample < 1000; ++sample) {
    const Pose2 pose = random.next();
    const Location location = space.locate(pose);
    const std::optional<std::uint32_t> node = space.nodeOf(pose);
    ASSERT_EQ(node.has_value(), location.free);
    if (!node) continue;
    ++free;
    EXPECT_EQ(graph.nodes()[*node].cell, location.cell);
    const std::uint32_t interval =
        graph.intervalOf(AlgebraicAngle::rational(HalfAngle::fromRadians(pose.theta)), space.algebra());
    EXPECT_LE(graph.nodes()[*node].firstInterval, interval);
    EXPECT_GE(graph.nodes()[*node].lastInterval, interval);
    const Clearance clearance = space.clearance(pose);
    if (!std::isfinite(clearance.lower) || clearance.lower <= 0) continue;
    const double direction = std::uniform_real_distribution<double>(-M_PI, M_PI)(turn);
    const double distance = 0.9 * clearance.lower;
    const Pose2 near{pose.x + distance * std::cos(direction), pose.y + distance * std::sin(direction), pose.theta};
    EXPECT_EQ(space.nodeOf(near), node);
    ++moved;
  }
  std::cout << GetParam() << ": " << free << " free of 1000, " << moved << " moved within their clearance\n";
  EXPECT_GT(free, 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledCellGraph,
                         ::testing::Values("keyhole", "keyhole_narrow", "keyhole_wide", "keyhole_tight", "flip_window",
                                           "cage", "maze", "overhang", "table", "table_tall", "turn_around",
                                           "room_door", "random_polyhedra", "tetra_floorplan"));

/// Whether an even-odd count of the loops' edges crossing the ray toward +x from a
/// point puts it inside the face (and how near an edge it lies).
struct Containment {
  bool inside = false;
  double nearestEdge = HUGE_VAL;
};

double signedArea(const SliceLoop& loop) {
  double twice = 0;
  for (std::size_t i = 0; i < loop.corners.size(); ++i) {
    const auto& a = loop.corners[i];
    const auto& b = loop.corners[(i + 1) % loop.corners.size()];
    twice += a[0] * b[1] - a[1] * b[0];
  }
  return twice / 2;
}

Containment containment(const SliceFace& face, const std::array<double, 2>& p) {
  Containment result;
  int crossings = 0;
  for (const SliceLoop& loop : face.loops) {
    for (std::size_t i = 0; i < loop.corners.size(); ++i) {
      const auto& a = loop.corners[i];
      const auto& b = loop.corners[(i + 1) % loop.corners.size()];
      const double dx = b[0] - a[0], dy = b[1] - a[1], length2 = dx * dx + dy * dy;
      const double t = length2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2, 0.0, 1.0) : 0;
      result.nearestEdge = std::min(result.nearestEdge, std::hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]));
      if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * dx) ++crossings;
    }
  }
  result.inside = (crossings % 2 == 1) != face.unbounded;
  return result;
}

/// The faces of slices at random angles, as polygons, against the exact locate: a
/// free configuration lies in exactly one face, that of its node; a blocked one in
/// none (points within 1e-9 of an edge are left out: the corners are rounded).
TEST_P(BundledCellGraph, SliceFacesHoldTheirConfigurations) {
  const LoadedProblem loaded = problem();
  const FreeSpace space(loaded.robot, loaded.world);
  const CellGraph& graph = space.cellGraph();
  const double scale = space.meshes().scale;
  RandomConfigurations random(space, 99);
  const SliceFaces sliceFaces(
      space.arrangement(), graph, [&](SubFaceId face) { return space.cellOfSubFace(face); }, space.algebra());
  int checked = 0;
  for (int slice = 0; slice < 6; ++slice) {
    const double theta = random.next().theta;
    const AlgebraicAngle angle = AlgebraicAngle::rational(HalfAngle::fromRadians(theta));
    std::vector<SliceFace> faces;
    try {
      faces = sliceFaces.at(angle, space.algebra());
    } catch (const std::invalid_argument&) {
      continue;  // a critical angle
    }
    // One face per node: walked with the free side on the right, a face's outer loop
    // turns clockwise and its holes counterclockwise; an unbounded face has none.
    for (const SliceFace& face : faces) {
      std::size_t clockwise = 0;
      for (const SliceLoop& loop : face.loops) clockwise += signedArea(loop) < 0;
      EXPECT_EQ(clockwise, face.unbounded ? 0u : 1u) << "node " << face.node << " at theta " << theta;
    }
    for (int sample = 0; sample < 300; ++sample) {
      Pose2 pose = random.next();
      pose.theta = theta;
      const std::array<double, 2> point{pose.x * scale, pose.y * scale};
      std::vector<std::uint32_t> holding;
      bool nearEdge = false;
      for (const SliceFace& face : faces) {
        const Containment in = containment(face, point);
        nearEdge = nearEdge || in.nearestEdge < 1e-9 * (1 + std::abs(point[0]) + std::abs(point[1]));
        if (in.inside) holding.push_back(face.node);
      }
      if (nearEdge) continue;
      const std::optional<std::uint32_t> node = space.nodeOf(pose);
      if (node) {
        EXPECT_EQ(holding, std::vector<std::uint32_t>{*node}) << pose.x << " " << pose.y << " " << pose.theta;
      } else {
        EXPECT_TRUE(holding.empty()) << pose.x << " " << pose.y << " " << pose.theta;
      }
      ++checked;
    }
  }
  std::cout << GetParam() << ": " << checked << " configurations checked against the slices' faces\n";
  EXPECT_GT(checked, 500);
}

/// One node's face from its own pieces (SliceFaces::faceOf) against the whole slice's
/// (SliceFaces::at): the same loops, corner for corner, for every node at random
/// angles; none for nodes whose run misses the angle.
/// How many nodes' faces SliceFaces::faceOf makes at an angle, each checked against
/// the whole slice's face of that node (none for a critical angle).
int compareNodeFacesAt(const FreeSpace& space, const SliceFaces& sliceFaces, const AlgebraicAngle& angle) {
  std::vector<SliceFace> faces;
  try {
    faces = sliceFaces.at(angle, space.algebra());
  } catch (const std::invalid_argument&) {
    return 0;  // a critical angle
  }
  std::map<std::uint32_t, const SliceFace*> byNode;
  for (const SliceFace& face : faces) byNode[face.node] = &face;
  int compared = 0;
  for (std::uint32_t node = 0; node < space.cellGraph().nodes().size(); ++node) {
    const std::optional<SliceFace> alone = sliceFaces.faceOf(node, angle, space.algebra());
    const auto whole = byNode.find(node);
    EXPECT_EQ(alone.has_value(), whole != byNode.end()) << "node " << node;
    if (!alone || whole == byNode.end()) continue;
    EXPECT_EQ(alone->cell, whole->second->cell);
    EXPECT_EQ(alone->unbounded, whole->second->unbounded);
    EXPECT_EQ(alone->loops.size(), whole->second->loops.size()) << "node " << node;
    for (std::size_t k = 0; k < std::min(alone->loops.size(), whole->second->loops.size()); ++k) {
      EXPECT_EQ(alone->loops[k].corners, whole->second->loops[k].corners) << "node " << node << " loop " << k;
    }
    ++compared;
  }
  return compared;
}

TEST_P(BundledCellGraph, OneNodesFaceIsTheWholeSlicesFaceOfIt) {
  const LoadedProblem loaded = problem();
  const FreeSpace space(loaded.robot, loaded.world);
  const CellGraph& graph = space.cellGraph();
  RandomConfigurations random(space, 7);
  const SliceFaces sliceFaces(
      space.arrangement(), graph, [&](SubFaceId face) { return space.cellOfSubFace(face); }, space.algebra());
  int compared = 0;
  for (int slice = 0; slice < 12; ++slice) {
    compared +=
        compareNodeFacesAt(space, sliceFaces, AlgebraicAngle::rational(HalfAngle::fromRadians(random.next().theta)));
  }
  EXPECT_GT(compared, 10);
  // At the first and the last interval of every node's run (where its pieces' tabled
  // intervals start and end, across theta = pi when they wrap around).
  int atEnds = 0;
  for (const CellGraphNode& node : graph.nodes()) {
    atEnds += compareNodeFacesAt(space, sliceFaces, node.sample);
    const auto [low, width] = graph.arc(node.lastInterval, node.lastInterval);
    atEnds += compareNodeFacesAt(space, sliceFaces,
                                 AlgebraicAngle::rational(HalfAngle::fromRadians(reducedAngle(low + width / 2))));
  }
  EXPECT_GE(atEnds, static_cast<int>(graph.nodes().size()));
}

/// A saved free space holds its graph: read back, it has the same nodes and edges,
/// and configurations find the same nodes.
TEST(CellGraphFile, TheGraphIsSavedAndReadBack) {
  const LoadedProblem loaded = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole.cfg");
  const FreeSpace built(loaded.robot, loaded.world);
  TempDir dir;
  built.save(dir.file("keyhole.fspace"));
  const std::unique_ptr<FreeSpace> read = FreeSpace::load(dir.file("keyhole.fspace"));
  const CellGraph& before = built.cellGraph();
  const CellGraph& after = read->cellGraph();
  ASSERT_EQ(after.criticalAngles().size(), before.criticalAngles().size());
  for (std::size_t i = 0; i < before.criticalAngles().size(); ++i) {
    EXPECT_EQ(built.algebra().compare(before.criticalAngles()[i], after.criticalAngles()[i]), 0);
  }
  ASSERT_EQ(after.nodes().size(), before.nodes().size());
  for (std::size_t i = 0; i < before.nodes().size(); ++i) {
    const CellGraphNode &a = before.nodes()[i], &b = after.nodes()[i];
    EXPECT_EQ(std::tie(a.cell, a.firstInterval, a.lastInterval, a.point, a.box),
              std::tie(b.cell, b.firstInterval, b.lastInterval, b.point, b.box));
  }
  ASSERT_EQ(after.edges().size(), before.edges().size());
  for (std::size_t i = 0; i < before.edges().size(); ++i) {
    const CellGraphEdge &a = before.edges()[i], &b = after.edges()[i];
    EXPECT_EQ(std::tie(a.from, a.to, a.angle), std::tie(b.from, b.to, b.angle));
  }
  expectEdgesIndexedByNode(after);
  RandomConfigurations random(built, 11);
  int different = 0;
  for (int sample = 0; sample < 500; ++sample) {
    const Pose2 pose = random.next();
    different += built.nodeOf(pose) != read->nodeOf(pose);
  }
  EXPECT_EQ(different, 0);
}

}  // namespace
