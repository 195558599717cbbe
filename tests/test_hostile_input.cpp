// Hostile input to the construction gives a clear error or a correct answer (checked
// against the exact collision test): overlapping environment solids, huge
// coordinates, a robot above the environment, heights that coincide without
// perturbation, a surface that comes within a hair of itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "freespace/input_error.h"
#include "freespace/space/free_space.h"
#include "locate_oracle.h"
#include "test_meshes.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

Mesh scaled(const Mesh& mesh, double factor) {
  TriangleSoup soup{{}, mesh.triangles()};
  for (const Point3& p : mesh.vertices()) soup.vertices.push_back(p * factor);
  return Mesh::fromSoup(soup, "scaled");
}

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

TEST(HostileInput, HugeCoordinatesGiveTheSameCells) {
  // A yard closed by four overlapping walls: the robot inside cannot leave.
  const Mesh world = Mesh::fromSoup(joinSoups({boxSoup({0, 0, 0}, {1, 4, 1}), boxSoup({3, 0, 0}, {4, 4, 1}),
                                               boxSoup({0.5, -0.1, 0}, {3.5, 1, 0.95}),
                                               boxSoup({0.5, 3, 0}, {3.5, 4.1, 0.95})}),
                                    "walled yard");
  const FreeSpace small(kRobot, world);
  const FreeSpace huge(scaled(kRobot, 1e9), scaled(world, 1e9));
  EXPECT_EQ(small.cellCount(), 2u);
  EXPECT_EQ(huge.cellCount(), 2u);
  const Location inside = huge.locate({1.8e9, 1.8e9, 0.3}), outside = huge.locate({8e9, 8e9, 0.3});
  ASSERT_TRUE(inside.free && outside.free);
  EXPECT_NE(inside.cell, outside.cell);
  EXPECT_EQ(locateAgainstCollision(small, 200, 5).disagreements, 0);
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
