#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "freespace/geometry/patch_segment.h"
#include "freespace/geometry/perturbed_meshes.h"
#include "freespace/input_error.h"
#include "freespace/scenes/scene_generator.h"
#include "test_meshes.h"

using namespace freespace;
using namespace freespace::testing;

TEST(PerturbedMeshes, MovesEveryCoordinateWithinTheSizeReproducibly) {
  const Mesh robot = boxMesh({-1, -1, 0}, {1, 1, 1});
  const Mesh world = boxMesh({0, 0, 0}, {10, 20, 2});  // diagonal sqrt(504)
  const PerturbationSettings settings{true, 99, 1e-8};
  const PerturbedMeshes first = perturbMeshes(robot, world, settings);
  const PerturbedMeshes again = perturbMeshes(robot, world, settings);
  EXPECT_DOUBLE_EQ(first.record.absoluteSize, 1e-8 * std::sqrt(504.0));
  EXPECT_EQ(first.record.seed, 99u);
  ASSERT_EQ(first.world.vertices().size(), world.vertices().size());
  for (std::size_t i = 0; i < world.vertices().size(); ++i) {
    const Point3 offset = first.world.vertices()[i] - world.vertices()[i];
    EXPECT_LE(offset.cwiseAbs().maxCoeff(), first.record.absoluteSize);
    EXPECT_GT(offset.cwiseAbs().minCoeff(), 0.0);  // no coordinate stays put (coplanar faces break up)
    EXPECT_EQ(first.world.vertices()[i], again.world.vertices()[i]);
  }
  EXPECT_EQ(first.robot.triangles(), robot.triangles());
  // Each face moves by at most the perturbation size: the volume by at most area x size.
  EXPECT_NEAR(first.world.volume(), world.volume(), 520 * first.record.absoluteSize);
}

TEST(PerturbedMeshes, SwitchedOffLeavesTheMeshesAlone) {
  const Mesh robot = boxMesh({-1, -1, 0}, {1, 1, 1});
  const Mesh world = boxMesh({0, 0, 0}, {10, 20, 2});
  const PerturbedMeshes same = perturbMeshes(robot, world, {false, 99, 1e-8});
  EXPECT_EQ(same.robot.vertices(), robot.vertices());
  EXPECT_EQ(same.world.vertices(), world.vertices());
  EXPECT_FALSE(same.record.enabled);
  EXPECT_EQ(same.record.absoluteSize, 0.0);
}

// 2,000 vertices at two heights, moved by at most 1e-14 of the scene (about 130
// doubles around each height): offsets must land on the same double, and such
// heights are moved apart.
TEST(PerturbedMeshes, EveryVertexHeightIsDistinctEvenWhenOffsetsCollide) {
  std::vector<TriangleSoup> boxes;
  for (int i = 0; i < 250; ++i) boxes.push_back(boxSoup({2.0 * i, 0, 0.5}, {2.0 * i + 1, 1, 0.75}));
  const Mesh world = Mesh::fromSoup(joinSoups(boxes), "row of boxes");
  const Mesh robot = boxMesh({-1, -1, 0}, {1, 1, 1});
  const PerturbedMeshes perturbed = perturbMeshes(robot, world, {true, 5, 1e-14});
  std::set<double> heights;
  for (const Mesh* mesh : {&perturbed.robot, &perturbed.world}) {
    for (const Point3& vertex : mesh->vertices()) heights.insert(vertex.z());
  }
  EXPECT_EQ(heights.size(), robot.vertices().size() + world.vertices().size());
  EXPECT_NO_THROW(requireDistinctHeights(perturbed.robot, perturbed.world, "row of boxes"));
}

// A square ring 4 wide cut through by a slit `gap` wide: its two sides face each other
// across the slit, so a perturbation much larger than the gap makes them cross.
Mesh slitRing(double gap) {
  const Polygon2 outline{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 2 + gap}, {1, 2 + gap},
                         {1, 3}, {3, 3}, {3, 1}, {1, 1},  {1, 2},       {0, 2}};
  return makeCheckedMesh(extrudePolygon(outline, 0, 1), "slit ring");
}

TEST(PerturbedMeshes, ShrinksWhereFeaturesCloserThanItWouldCross) {
  const Mesh robot = boxMesh({-0.25, -0.25, 0}, {0.25, 0.25, 0.5});
  const Mesh world = slitRing(1e-10);  // 2e-11 of the scene size
  const PerturbedMeshes moved = perturbMeshes(robot, world, {true, 1, 1e-8});
  EXPECT_LT(moved.record.relativeSize, 1e-8 / 8) << "the default size crosses the slit";
  EXPECT_GT(moved.record.relativeSize, 0.0);
  EXPECT_EQ(moved.world.componentCount(), 1u);
  // The record reproduces the run.
  const PerturbedMeshes again = perturbMeshes(robot, world, {true, 1, moved.record.relativeSize});
  EXPECT_EQ(again.world.vertices(), moved.world.vertices());
  EXPECT_EQ(again.record.relativeSize, moved.record.relativeSize);
}

TEST(PerturbedMeshes, FeaturesCloserThanTheSmallestPerturbationAreRefused) {
  const Mesh robot = boxMesh({-0.25, -0.25, 0}, {0.25, 0.25, 0.5});
  const Mesh world = slitRing(std::ldexp(1.0, -50));  // 1.5e-16 of the scene size
  EXPECT_THROW(perturbMeshes(robot, world, {true, 1, 1e-8}), InputError);
}
