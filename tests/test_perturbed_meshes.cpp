#include <gtest/gtest.h>

#include "freespace/geometry/perturbed_meshes.h"
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
