#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "convex_oracle.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/input_error.h"
#include "test_meshes.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

// Unit cube world; robot: a 0.5 x 0.5 x 1 column centred on its own z axis.
struct CubeScene : ::testing::Test {
  Mesh world = boxMesh({0, 0, 0}, {1, 1, 1});
  Mesh robot = boxMesh({-0.25, -0.25, 0}, {0.25, 0.25, 1});
  ExactCollisionChecker exact{robot, world};
  FclCollisionChecker fcl{robot, world};
};

TEST_F(CubeScene, SeparatedIsFree) {
  EXPECT_FALSE(exact.inCollision({2, 0.5, 0}));
  EXPECT_FALSE(exact.inCollision({-1, -1, 0.7}));
  EXPECT_FALSE(exact.inCollision({0.5, 1.5, M_PI}));
}

TEST_F(CubeScene, OverlapIsCollision) {
  EXPECT_TRUE(exact.inCollision({0.5, 0.5, 0}));
  EXPECT_TRUE(exact.inCollision({1.2, 0.5, 0.3}));
  EXPECT_TRUE(exact.inCollision({0.0, 0.0, -2.0}));
}

TEST_F(CubeScene, TouchingIsCollision) {
  // Face against face: robot's face x = -0.25 at world's x = 1.
  EXPECT_TRUE(exact.inCollision({1.25, 0.5, 0}));
  // Only edges touch: robot corner column on the world's corner column.
  EXPECT_TRUE(exact.inCollision({1.25, 1.25, 0}));
  // Half a turn maps the square onto itself exactly (chart 1, t = 0).
  EXPECT_TRUE(exact.inCollision({1.25, 0.5, M_PI}));
  // The same, just apart (the nearest double above 1.25).
  EXPECT_FALSE(exact.inCollision({std::nextafter(1.25, 2.0), 0.5, 0}));
  EXPECT_FALSE(exact.inCollision({std::nextafter(1.25, 2.0), std::nextafter(1.25, 2.0), 0}));
}

TEST(ExactCollision, BodyInsideBodyIsCollisionThatFclMisses) {
  const Mesh hall = boxMesh({-5, -5, -1}, {5, 5, 2});
  const Mesh small = boxMesh({-0.25, -0.25, 0}, {0.25, 0.25, 1});
  // Robot strictly inside a solid world component.
  {
    const ExactCollisionChecker exact(small, hall);
    const FclCollisionChecker fcl(small, hall);
    EXPECT_TRUE(exact.inCollision({1, 2, 0.4}));
    EXPECT_FALSE(fcl.inCollision({1, 2, 0.4}));
    EXPECT_FALSE(exact.inCollision({7, 2, 0.4}));
  }
  // A world component strictly inside the robot.
  {
    const ExactCollisionChecker exact(hall, small);
    const FclCollisionChecker fcl(hall, small);
    EXPECT_TRUE(exact.inCollision({0.5, -1, 1.0}));
    EXPECT_FALSE(fcl.inCollision({0.5, -1, 1.0}));
    EXPECT_FALSE(exact.inCollision({20, 0, 1.0}));
  }
}

TEST(ExactCollision, NestedComponentsAndHeights) {
  // World: a low wall (z in [0, 0.5]) and a high bar (z in [2, 3]) over the same area.
  const Mesh world = Mesh::fromSoup(joinSoups({boxSoup({0, 0, 0}, {4, 1, 0.5}), boxSoup({0, 0, 2}, {4, 1, 3})}), "w");
  // Robot: a thin plate at z in [1, 1.5] passes between them; a tall one does not.
  const Mesh plate = boxMesh({-1, -1, 1}, {1, 1, 1.5});
  const Mesh tall = boxMesh({-1, -1, 0.25}, {1, 1, 1.5});
  EXPECT_FALSE(ExactCollisionChecker(plate, world).inCollision({2, 0.5, 0.3}));
  EXPECT_TRUE(ExactCollisionChecker(tall, world).inCollision({2, 0.5, 0.3}));
  // Robot with z range touching the wall's top exactly: contact counts.
  const Mesh resting = boxMesh({-1, -1, 0.5}, {1, 1, 1.5});
  EXPECT_TRUE(ExactCollisionChecker(resting, world).inCollision({2, 0.5, 0.3}));
}

/// A whole number uniformly in [low, high), whatever RapidCheck's current size.
int uniform(int low, int high) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(low, high)); }

/// A point on a small integer grid: many coincidences, coplanarities and contacts.
rc::Gen<Point3> gridPoint(int size) {
  const auto coordinate = rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, size));
  return rc::gen::map(rc::gen::tuple(coordinate, coordinate, coordinate),
                      [](const std::tuple<int, int, int>& p) {
                        return Point3(std::get<0>(p), std::get<1>(p), std::get<2>(p));
                      });
}

std::optional<Mesh> randomTetrahedron(int size) {
  const Point3 a = *gridPoint(size), b = *gridPoint(size), c = *gridPoint(size), d = *gridPoint(size);
  try {
    return tetrahedronMesh(a, b, c, d);
  } catch (const InputError&) {
    return std::nullopt;  // flat or repeated points
  }
}

Pose2 randomPose() {
  // Mostly integer translations and exact quarter turns, which put grid bodies in
  // touching contact often; otherwise half-unit translations and arbitrary angles,
  // which exercise the interval path.
  const bool touchingKind = uniform(0, 3) != 0;
  const double scale = touchingKind ? 1.0 : 0.5;
  const double x = uniform(-3, 4) * scale;
  const double y = uniform(-3, 4) * scale;
  const double theta = touchingKind ? uniform(-2, 3) * M_PI / 2 : uniform(-3141592, 3141593) * 1e-6;
  return {x, y, theta};
}

}  // namespace

RC_GTEST_PROP(ExactCollisionOracle, TetrahedraAgreeWithSeparatingAxes, ()) {
  const std::optional<Mesh> robot = randomTetrahedron(4);
  const std::optional<Mesh> world = randomTetrahedron(4);
  RC_PRE(robot.has_value() && world.has_value());
  const Pose2 pose = randomPose();
  const bool expected = convexPolytopesIntersect(exactPlacedRobot(*robot, pose), exactWorld(*world));
  RC_CLASSIFY(expected, "intersecting");
  RC_ASSERT(ExactCollisionChecker(*robot, *world).inCollision(pose) == expected);
}

RC_GTEST_PROP(ExactCollisionOracle, BoxesAgreeWithSeparatingAxes, ()) {
  // Boxes share coplanar faces and collinear edges with each other all the time.
  const auto randomBox = [] {
    const Point3 a = *gridPoint(5), b = *gridPoint(5);
    const Point3 low = a.cwiseMin(b), high = a.cwiseMax(b);
    return (high - low).minCoeff() > 0 ? std::optional<Mesh>(boxMesh(low, high)) : std::nullopt;
  };
  const std::optional<Mesh> robot = randomBox();
  const std::optional<Mesh> world = randomBox();
  RC_PRE(robot.has_value() && world.has_value());
  const Pose2 pose = randomPose();
  const bool expected = convexPolytopesIntersect(exactPlacedRobot(*robot, pose), exactWorld(*world));
  RC_CLASSIFY(expected, "intersecting");
  RC_ASSERT(ExactCollisionChecker(*robot, *world).inCollision(pose) == expected);
}

TEST(ExactCollision, CountsExactFallbacks) {
  const Mesh world = boxMesh({0, 0, 0}, {1, 1, 1});
  const Mesh robot = boxMesh({-0.25, -0.25, 0}, {0.25, 0.25, 1});
  const ExactCollisionChecker exact(robot, world);
  exact.inCollision({1.25, 0.5, 0});  // touching: some signs are exactly zero
  const auto counts = exact.predicateCounts();
  EXPECT_GT(counts.evaluated, 0u);
  EXPECT_LE(counts.exact, counts.evaluated);
}

TEST(ExactCollision, ConcurrentQueriesGiveTheSequentialAnswers) {
  const Mesh world = Mesh::fromSoup(joinSoups({boxSoup({0, 0, 0}, {1, 1, 1}), boxSoup({2, 0, 0}, {3, 1, 1})}), "w");
  const Mesh robot = boxMesh({-0.25, -0.25, 0}, {0.25, 0.25, 1});
  const ExactCollisionChecker checker(robot, world);
  std::vector<Pose2> poses;
  for (int i = 0; i < 400; ++i) poses.push_back({-1 + 0.01 * i, 0.5 + 0.003 * i, 0.05 * i});
  std::vector<char> sequential;
  for (const Pose2& pose : poses) sequential.push_back(checker.inCollision(pose));
  std::vector<char> first(poses.size()), second(poses.size());
  std::thread other([&] {
    for (std::size_t i = 0; i < poses.size(); ++i) second[i] = checker.inCollision(poses[i]);
  });
  for (std::size_t i = poses.size(); i-- > 0;) first[i] = checker.inCollision(poses[i]);
  other.join();
  EXPECT_EQ(first, sequential);
  EXPECT_EQ(second, sequential);
  // Both answers occur along the sweep, so the comparison means something.
  EXPECT_NE(std::count(sequential.begin(), sequential.end(), 1), 0);
  EXPECT_NE(std::count(sequential.begin(), sequential.end(), 0), 0);
}
