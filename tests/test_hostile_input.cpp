// Hostile input to the construction gives a clear error or a correct answer (checked
// against the exact collision test): overlapping environment solids, tiny and huge
// coordinates, a robot above the environment, heights that coincide without
// perturbation, a surface that comes within a hair of itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "freespace/input_error.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/free_space.h"
#include "locate_oracle.h"
#include "test_meshes.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

const Mesh kRobot = tetrahedronMesh({0, 0, 0.1}, {0.6, 0, 0.2}, {0, 0.5, 0.3}, {0.1, 0.1, 0.8});

}  // namespace

TEST(HostileInput, OverlappingEnvironmentSolidsAreTheirUnion) {
  const Mesh world = Mesh::fromSoup(joinSoups({boxSoup({0, 0, 0}, {2, 1, 1}), boxSoup({1, 0.5, 0.05}, {3, 2, 0.9})}),
                                    "overlapping boxes");
  const FreeSpace space(kRobot, world);
  const LocateCheck check = locateAgainstCollision(space, 400, 5);
  EXPECT_EQ(check.disagreements, 0);
  EXPECT_GT(check.free, 0);
}

// Scenes far from unit size are scaled by a power of two before the construction
// (docs/design.md section 5): tiny ones (whose products of coordinates would
// underflow, every filter failing, and at 2^-126 a division by an interval holding
// zero) and huge ones give the bundled keyhole's cells, and locate agrees with the
// exact test.
TEST(HostileInput, TinyAndHugeCoordinatesGiveTheSameCells) {
  const LoadedProblem keyhole = loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole.cfg");
  const std::size_t cells = FreeSpace(keyhole.robot, keyhole.world).cellCount();
  const Pose2 start = keyhole.problem.start, goal = keyhole.problem.goal;
  for (const double factor : {0x1p-126, 1e-30, 1e-3, 1e9, 0x1p100}) {
    const FreeSpace space(scaled(keyhole.robot, factor), scaled(keyhole.world, factor));
    EXPECT_EQ(space.cellCount(), cells) << factor;
    const Location from = space.locate({start.x * factor, start.y * factor, start.theta});
    const Location to = space.locate({goal.x * factor, goal.y * factor, goal.theta});
    EXPECT_TRUE(from.free && to.free && from.cell == to.cell) << factor;
    EXPECT_FALSE(space.locate({0, 0, 0}).free) << factor;
    EXPECT_EQ(locateAgainstCollision(space, 300, 5).disagreements, 0) << factor;
  }
}

TEST(HostileInput, ARobotAboveTheEnvironmentIsFreeEverywhere) {
  const Mesh world = boxMesh({0, 0, 0}, {2, 2, 1});
  const Mesh above = scaled(kRobot, 1.0);
  TriangleSoup lifted{{}, above.triangles()};
  for (const Point3& p : above.vertices()) lifted.vertices.push_back(p + Point3(0, 0, 5));
  const FreeSpace space(Mesh::fromSoup(lifted, "lifted robot"), world);
  EXPECT_EQ(space.cellCount(), 1u);
  const LocateCheck check = locateAgainstCollision(space, 200, 5);
  EXPECT_EQ(check.disagreements, 0);
  EXPECT_EQ(check.free, 200);
}

TEST(HostileInput, CoincidentHeightsWithoutPerturbationAreAnErrorNamingTheInput) {
  FreeSpaceOptions options;
  options.perturbation.enabled = false;
  options.sourceName = "flat.cfg";
  try {
    const FreeSpace space(boxMesh({0, 0, 0}, {1, 1, 1}), boxMesh({2, 0, 0}, {3, 1, 1}), options);
    FAIL() << "built a free space from coincident heights";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "flat.cfg");
    EXPECT_NE(error.problem().find("same height"), std::string::npos) << error.what();
  }
}

// A box whose top corner is pulled down to `height` above its bottom face: valid
// input, but the perturbation (about 1e-8 of the scene) may push it through.
Mesh pinchedBox(double height) {
  TriangleSoup soup = boxSoup({0, 0, 0}, {2, 2, 1});
  const auto corner = std::find(soup.vertices.begin(), soup.vertices.end(), Point3(2, 2, 1));
  *corner = Point3(1.5, 0.5, height);
  return Mesh::fromSoup(soup, "pinched box");
}

TEST(HostileInput, ASurfaceAHairFromItselfIsBuiltWithASmallerPerturbation) {
  const Mesh world = pinchedBox(1e-12);
  int reduced = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    FreeSpaceOptions options;
    options.perturbation.seed = seed;
    const FreeSpace space(kRobot, world, options);
    if (space.meshes().record.relativeSize < options.perturbation.relativeSize) ++reduced;
    EXPECT_EQ(locateAgainstCollision(space, 300, seed).disagreements, 0) << seed;
  }
  EXPECT_GT(reduced, 0) << "the corner ends below the bottom for some seeds at the default size";
}

TEST(HostileInput, ASurfaceCloserToItselfThanAnyPerturbationIsRefusedOrCorrect) {
  const Mesh world = pinchedBox(1e-16);
  int refused = 0, built = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    FreeSpaceOptions options;
    options.perturbation.seed = seed;
    try {
      const FreeSpace space(kRobot, world, options);
      ++built;
      EXPECT_EQ(locateAgainstCollision(space, 300, seed).disagreements, 0) << seed;
    } catch (const InputError& error) {
      ++refused;
      EXPECT_EQ(error.file(), "perturbed environment");
      EXPECT_NE(error.problem().find("intersects itself"), std::string::npos) << error.problem();
    }
  }
  // Both outcomes occur among these seeds (the corner ends above or below the bottom).
  EXPECT_GT(refused, 0);
  EXPECT_GT(built, 0);
}
