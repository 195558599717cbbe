// Shells against the exact collision test. From a random free configuration (exact
// collision test on the perturbed meshes), the ray toward -x at its angle stays in
// free space until it meets the boundary of the configuration's free cell, so the
// first sub-face it meets must be met from its positive side and belong to a closed
// shell (every side of it glued). A missing or wrong glue leaves such a shell open.
// The shells of free cells are probed on both sides of every sub-face (free side
// inward), every curve, spiral and horizontal edge of them is used by exactly two
// sides, and their Euler characteristics are those of closed orientable surfaces.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "bundled_scene.h"
#include "test_meshes.h"
#include "topology/horizontal_edge.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/free_space.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/topology/shell_classification.h"
#include "freespace/topology/shell_euler_characteristic.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

struct ShellCheck {
  int free = 0;
  int escaped = 0;        // rays from free configurations that meet nothing
  int hits = 0;           // ... that meet a sub-face
  int fromNegative = 0;   // ... from its negative side (wrong)
  int openShells = 0;     // ... of an open shell (wrong)
  int degenerate = 0;
  std::size_t shells = 0, closedShells = 0;
  std::array<int, 3> glues{}, probedGlues{}, wrongGlues{};  // by GluedEdge
};

/// Whether the positive side of a sub-face is free, by the exact collision test at a
/// probe (if it can be probed); each sub-face probed once.
class FreeSides {
 public:
  FreeSides(const Arrangement& arrangement, const SliceRays& rays, const ExactCollisionChecker& collision,
            AngleAlgebra& algebra)
      : arrangement_(arrangement), rays_(rays), collision_(collision), algebra_(algebra) {}

  std::optional<bool> of(SubFaceId face) {
    const auto [found, inserted] = known_.try_emplace({face.patch, face.face});
    if (inserted) {
      const std::optional<SubFaceProbe> probe = probeSubFace(arrangement_, rays_, face);
      if (probe) found->second = !collision_.inCollisionAt(probe->pose);
    }
    return found->second;
  }

 private:
  const Arrangement& arrangement_;
  const SliceRays& rays_;
  const ExactCollisionChecker& collision_;
  AngleAlgebra& algebra_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::optional<bool>> known_;
};

/// Glued sub-faces face one region: both free or both blocked.
void checkGlues(const Arrangement& arrangement, const SliceRays& rays, const ExactCollisionChecker& collision,
                AngleAlgebra& algebra, ShellCheck& check) {
  FreeSides freeSide(arrangement, rays, collision, algebra);
  for (const SubFaceGluing* gluing :
       {&arrangement.acrossCurves, &arrangement.aroundSpirals, &arrangement.acrossHorizontalEdges}) {
    for (const SubFaceGlue& glue : gluing->glues) {
      const auto kind = static_cast<std::size_t>(glue.edge);
      check.glues[kind]++;
      const std::optional<bool> a = freeSide.of(glue.first), b = freeSide.of(glue.second);
      if (!a || !b) continue;
      check.probedGlues[kind]++;
      check.wrongGlues[kind] += *a != *b;
    }
  }
}

ShellCheck checkShells(BundledScene& scene, int samples, unsigned seed) {
  const Arrangement arrangement = buildArrangement(scene.geometries, scene.algebra);
  const SliceRays rays(arrangement, scene.algebra);
  const ExactCollisionChecker collision(scene.meshes.robot, scene.meshes.world);
  ShellCheck check;
  check.shells = arrangement.shells.count();
  for (std::uint32_t shell = 0; shell < arrangement.shells.count(); ++shell) {
    check.closedShells += arrangement.shells.closed(shell);
  }
  checkGlues(arrangement, rays, collision, scene.algebra, check);
  const Box3 world = scene.meshes.world.bounds();
  const double reach = scene.meshes.robot.bounds().sizes().head<2>().norm();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(world.min().x() - reach, world.max().x() + reach);
  std::uniform_real_distribution<double> y(world.min().y() - reach, world.max().y() + reach);
  std::uniform_real_distribution<double> theta(-M_PI, M_PI);
  for (int i = 0; i < samples; ++i) {
    const Pose2 pose{x(random), y(random), theta(random)};
    if (collision.inCollision(pose)) continue;
    check.free++;
    const RayHit hit = rays.cast(AlgebraicAngle::rational(HalfAngle::fromRadians(pose.theta)),
                                 {Rational(pose.x), Rational(pose.y)}, -1);
    switch (hit.kind) {
      case RayHit::Kind::Nothing: check.escaped++; break;
      case RayHit::Kind::SubFace:
        check.hits++;
        check.fromNegative += !hit.fromPositiveSide;
        check.openShells += !arrangement.shells.closed(arrangement.shells.shellOf(hit.face));
        break;
      default: check.degenerate++;
    }
  }
  return check;
}

class BundledSceneShells : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledSceneShells, RaysFromFreeConfigurationsMeetClosedShellsFromTheirFreeSide) {
  BundledScene scene(GetParam());
  const ShellCheck check = checkShells(scene, 400, 7);
  std::cout << GetParam() << ": " << check.shells << " shells, " << check.closedShells << " closed; " << check.free
            << " free configurations: " << check.hits << " rays meet a sub-face (" << check.fromNegative
            << " from its negative side, " << check.openShells << " of an open shell), " << check.escaped
            << " meet nothing, " << check.degenerate << " degenerate\n";
  for (int kind = 0; kind < 3; ++kind) {
    std::cout << "  glues of kind " << kind << ": " << check.glues[kind] << ", probed " << check.probedGlues[kind]
              << ", joining a free and a blocked side " << check.wrongGlues[kind] << "\n";
    EXPECT_EQ(check.wrongGlues[kind], 0);
  }
  EXPECT_GT(check.hits, 0);
  EXPECT_EQ(check.fromNegative, 0);
  EXPECT_EQ(check.openShells, 0);
  EXPECT_EQ(check.degenerate, 0);
}

/// Every sub-face of a shell bounding a free cell, probed on both sides by the exact
/// collision test: free on its positive side, blocked on its negative side (the
/// shell is oriented with the free side inward); and the shell is closed.
TEST_P(BundledSceneShells, ShellsOfFreeCellsAreClosedWithTheFreeSideInward) {
  const LoadedProblem loaded = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/" + GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  const Arrangement& arrangement = space.arrangement();
  const SliceRays rays(arrangement, space.algebra());
  const ExactCollisionChecker collision(space.meshes().robot, space.meshes().world);
  int faces = 0, probed = 0, freeBelow = 0, blockedAbove = 0, open = 0;
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    for (std::uint32_t index = 0; index < arrangement.subdivisions[patch].faceCount; ++index) {
      const SubFaceId face{patch, index};
      if (!space.cellOfSubFace(face)) continue;
      ++faces;
      open += !arrangement.shells.closed(arrangement.shells.shellOf(face));
      const auto above = probeSubFace(arrangement, rays, face, ProbeSide::Positive);
      const auto below = probeSubFace(arrangement, rays, face, ProbeSide::Negative);
      if (!above || !below) continue;
      ++probed;
      blockedAbove += collision.inCollisionAt(above->pose);
      freeBelow += !collision.inCollisionAt(below->pose);
    }
  }
  std::cout << GetParam() << ": " << faces << " sub-faces bound free cells, " << probed << " probed on both sides\n";
  EXPECT_GT(probed, faces / 2);
  EXPECT_EQ(open, 0);
  EXPECT_EQ(blockedAbove, 0);
  EXPECT_EQ(freeBelow, 0);
}

/// The sub-face sides that meet along one edge of the arrangement at one angle:
/// every shell bounding a free cell must hold none or exactly two of them (each edge
/// of such a shell is used by exactly two of its sub-face sides: a closed surface
/// without pinches).
class EdgeUse {
 public:
  explicit EdgeUse(const FreeSpace& space) : space_(space) {}

  void side(SubFaceId face) {
    if (space_.cellOfSubFace(face)) shells_[space_.arrangement().shells.shellOf(face)]++;
  }

  /// Ends one edge: counts it, and counts it wrong if a shell held other than two.
  void finish(int& edges, int& wrong) {
    if (shells_.empty()) return;
    ++edges;
    wrong += std::any_of(shells_.begin(), shells_.end(), [](const auto& entry) { return entry.second != 2; });
    shells_.clear();
  }

 private:
  const FreeSpace& space_;
  std::map<std::uint32_t, int> shells_;
};

/// At every slab sample of every patch: the four sides along each of its curves (the
/// sub-faces below and above the crossing on the patch and on the curve's other
/// patch), and the sides of every patch ending at each of its segment's spirals; and
/// the rays over every piece of every horizontal edge (read exactly).
TEST_P(BundledSceneShells, EveryEdgeOfAFreeCellsShellIsUsedByTwoSides) {
  const LoadedProblem loaded = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/" + GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  const Arrangement& arrangement = space.arrangement();
  AngleAlgebra& algebra = space.algebra();
  std::map<std::tuple<bool, std::uint32_t, std::uint32_t, std::uint32_t>, std::vector<std::pair<std::uint32_t, int>>>
      bySpiral;
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    for (int k = 0; k < 2; ++k) {
      const SegmentEnd& end = arrangement.patches[patch].segment.ends[k];
      bySpiral[{end.robotVertex, end.vertex, end.edge[0], end.edge[1]}].push_back({patch, k});
    }
  }
  EdgeUse use(space);
  int curveEdges = 0, spiralEdges = 0, wrongCurves = 0, wrongSpirals = 0;
  for (std::uint32_t f = 0; f < arrangement.patches.size(); ++f) {
    for (const PatchSlab& slab : arrangement.subdivisions[f].slabs) {
      for (std::size_t i = 0; i < slab.curves.size(); ++i) {
        const std::uint32_t g = arrangement.curves[slab.curves[i]].other(f);
        const PatchSlab* across = slabAt(arrangement.subdivisions[g], slab.sample, algebra);
        ASSERT_NE(across, nullptr);
        const std::size_t j = static_cast<std::size_t>(
            std::find(across->curves.begin(), across->curves.end(), slab.curves[i]) - across->curves.begin());
        ASSERT_LT(j, across->curves.size());
        for (const SubFaceId face : {SubFaceId{f, slab.faces[i]}, SubFaceId{f, slab.faces[i + 1]},
                                     SubFaceId{g, across->faces[j]}, SubFaceId{g, across->faces[j + 1]}}) {
          use.side(face);
        }
        use.finish(curveEdges, wrongCurves);
      }
      for (const SegmentEnd& end : arrangement.patches[f].segment.ends) {
        for (const auto& [patch, k] : bySpiral.at({end.robotVertex, end.vertex, end.edge[0], end.edge[1]})) {
          if (!algebra.contains(arrangement.patches[patch].patch.range, slab.sample)) continue;
          // No slab there: the sample is an event of that patch.
          const PatchSlab* at = slabAt(arrangement.subdivisions[patch], slab.sample, algebra);
          if (at) use.side({patch, k == 0 ? at->faces.front() : at->faces.back()});
        }
        use.finish(spiralEdges, wrongSpirals);
      }
    }
  }
  int horizontalEdges = 0, wrongHorizontal = 0;
  for (const gluing::EdgeSlice& edge : gluing::horizontalEdgeSlices(
           arrangement.patches, arrangement.curves, arrangement.overlaps, arrangement.subdivisions, algebra)) {
    for (const std::vector<gluing::EdgeRay>& piece : edge.reading.pieces) {
      for (const gluing::EdgeRay& ray : piece) use.side(ray.face);
      use.finish(horizontalEdges, wrongHorizontal);
    }
  }
  std::cout << GetParam() << ": " << curveEdges << " curve edges, " << spiralEdges << " spiral edges and "
            << horizontalEdges << " pieces of horizontal edges of free cells' shells looked at\n";
  EXPECT_GT(curveEdges + spiralEdges, 0);
  EXPECT_EQ(wrongHorizontal, 0);
  EXPECT_EQ(wrongCurves, 0);
  EXPECT_EQ(wrongSpirals, 0);
}

/// The shells bounding each free cell.
std::map<std::uint32_t, std::set<std::uint32_t>> shellsOfCells(const FreeSpace& space) {
  std::map<std::uint32_t, std::set<std::uint32_t>> shells;
  for (std::uint32_t shell = 0; shell < space.shellCount(); ++shell) {
    if (const auto cell = space.cellOfShell(shell)) shells[*cell].insert(shell);
  }
  return shells;
}

/// Every shell bounding a free cell is a closed orientable surface: an even Euler
/// characteristic, at most 2 (a sphere; 0 for a torus, a cell that wraps around theta).
TEST_P(BundledSceneShells, ShellsOfFreeCellsHaveEvenEulerCharacteristicsAtMostTwo) {
  const LoadedProblem loaded = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/" + GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  const std::vector<long> chi = shellEulerCharacteristics(space.arrangement(), space.algebra());
  ASSERT_EQ(chi.size(), space.arrangement().shells.count());
  std::set<std::uint32_t> freeShells;
  for (const auto& [cell, shells] : shellsOfCells(space)) freeShells.insert(shells.begin(), shells.end());
  std::map<long, int> byCharacteristic;
  for (std::uint32_t shell : freeShells) byCharacteristic[chi[shell]]++;
  std::cout << GetParam() << ": " << freeShells.size() << " shells of free cells by Euler characteristic:";
  for (const auto& [value, count] : byCharacteristic) std::cout << " " << value << " x" << count;
  std::cout << "\n";
  EXPECT_FALSE(freeShells.empty());
  for (std::uint32_t shell : freeShells) {
    EXPECT_EQ(chi[shell] % 2, 0) << "shell " << shell;
    EXPECT_LE(chi[shell], 2) << "shell " << shell;
  }
}

/// A bar in a room too narrow to turn it across: two cells inside (the bar along the
/// room one way or the other, turning less than a quarter turn), each a ball bounded
/// by a sphere (2); outside the walls the unbounded cell, whose boundary is a torus
/// (0: the obstacle's outline times the circle of angles).
TEST(ShellEulerCharacteristic, ABarThatCannotTurnInARoomMakesTwoBallsInsideAndATorusOutside) {
  const Mesh robot = boxMesh({-2, -0.25, 0}, {2, 0.25, 1});
  const Mesh world = Mesh::fromSoup(joinSoups({boxSoup({-2.75, -2, 0}, {-2.25, 2, 2}), boxSoup({2.25, -2, 0}, {2.75, 2, 2}),
                                               boxSoup({-2.2, -2, 0}, {2.2, -1.5, 2}), boxSoup({-2.2, 1.5, 0}, {2.2, 2, 2})}),
                                    "room");
  const FreeSpace space(robot, world);
  const Location along = space.locate({0, 0, 0}), reversed = space.locate({0, 0, M_PI}),
                 outside = space.locate({10, 0, 0.3});
  ASSERT_TRUE(along.free && reversed.free && outside.free);
  ASSERT_NE(along.cell, reversed.cell);
  ASSERT_EQ(space.cellCount(), 3u);
  const std::vector<long> chi = shellEulerCharacteristics(space.arrangement(), space.algebra());
  std::map<std::uint32_t, std::vector<long>> chiOfCell;
  for (const auto& [cell, shells] : shellsOfCells(space)) {
    for (std::uint32_t shell : shells) chiOfCell[cell].push_back(chi[shell]);
  }
  EXPECT_EQ(chiOfCell[along.cell], std::vector<long>{2});
  EXPECT_EQ(chiOfCell[reversed.cell], std::vector<long>{2});
  EXPECT_EQ(chiOfCell[outside.cell], std::vector<long>{0});
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledSceneShells,
                         ::testing::Values("cage.cfg", "keyhole.cfg", "keyhole_narrow.cfg", "turn_around.cfg", "table.cfg",
                                           "table_tall.cfg", "overhang.cfg", "room_door.cfg", "room_door_dae.cfg",
                                           "random_polyhedra.cfg", "tetra_floorplan.cfg", "maze.cfg"));

}  // namespace
