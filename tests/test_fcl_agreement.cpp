// The exact collision test and FCL must agree on every bundled scene wherever FCL's
// verdict is clear: FCL reports a collision, or FCL's distance is clearly positive.
// Where FCL's distance is positive and the exact test reports a collision, one body
// must lie inside the other, which an independent ray-parity oracle confirms.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "containment_oracle.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/problem/planar_problem.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

constexpr int kClearVerdictsPerScene = 10000;

std::vector<std::string> bundledProblems() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems")) {
    if (entry.path().extension() == ".cfg") paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

Point3 placed(const Point3& p, const Pose2& pose) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  return {c * p.x() - s * p.y() + pose.x, s * p.x() + c * p.y() + pose.y, p.z()};
}

Point3 unplaced(const Point3& p, const Pose2& pose) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double x = p.x() - pose.x, y = p.y() - pose.y;
  return {c * x + s * y, -s * x + c * y, p.z()};
}

/// One body strictly inside the other, by the independent oracle.
bool containmentByOracle(const Mesh& robot, const Mesh& world, const Pose2& pose) {
  for (std::uint32_t vertex : robot.componentRepresentatives()) {
    if (insideMesh(world, placed(robot.vertices()[vertex], pose))) return true;
  }
  for (std::uint32_t vertex : world.componentRepresentatives()) {
    if (insideMesh(robot, unplaced(world.vertices()[vertex], pose))) return true;
  }
  return false;
}

struct AgreementCounts {
  int fclCollisions = 0;
  int fclClearlyFree = 0;
  int containments = 0;
  int unclear = 0;
  int disagreements = 0;
};

AgreementCounts compareOnRandomPoses(const LoadedProblem& loaded, std::uint64_t seed) {
  const ExactCollisionChecker exact(loaded.robot, loaded.world);
  const FclCollisionChecker fcl(loaded.robot, loaded.world);
  Box3 region = loaded.world.bounds();
  const double margin = loaded.robot.bounds().sizes().head<2>().norm();
  const double clearDistance = 1e-6 * (region.sizes().norm() + margin);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> x(region.min().x() - margin, region.max().x() + margin);
  std::uniform_real_distribution<double> y(region.min().y() - margin, region.max().y() + margin);
  std::uniform_real_distribution<double> theta(-M_PI, M_PI);
  AgreementCounts counts;
  while (counts.fclCollisions + counts.fclClearlyFree < kClearVerdictsPerScene) {
    const Pose2 pose{x(random), y(random), theta(random)};
    const bool exactHit = exact.inCollision(pose);
    if (fcl.inCollision(pose)) {
      ++counts.fclCollisions;
      counts.disagreements += !exactHit;
      continue;
    }
    if (fcl.distance(pose) <= clearDistance) {
      ++counts.unclear;
      continue;
    }
    ++counts.fclClearlyFree;
    if (exactHit) {
      const bool contained = containmentByOracle(loaded.robot, loaded.world, pose);
      counts.containments += contained;
      counts.disagreements += !contained;
    }
  }
  return counts;
}

}  // namespace

TEST(FclAgreement, EveryBundledSceneOnTenThousandClearVerdicts) {
  const std::vector<std::string> problems = bundledProblems();
  ASSERT_GE(problems.size(), 8u);
  for (const std::string& path : problems) {
    const LoadedProblem loaded = loadProblem(path);
    const AgreementCounts counts = compareOnRandomPoses(loaded, 2024);
    std::cout << std::filesystem::path(path).filename().string() << ": " << counts.fclCollisions
              << " FCL collisions, " << counts.fclClearlyFree << " clearly free (" << counts.containments
              << " containments), " << counts.unclear << " near contact skipped, " << counts.disagreements
              << " disagreements\n";
    EXPECT_EQ(counts.disagreements, 0) << path;
    EXPECT_GT(counts.fclCollisions, 0) << path;
    EXPECT_GT(counts.fclClearlyFree, 0) << path;
  }
}

TEST(FclAgreement, ContainmentIsCollisionForExactButNotForFcl) {
  // Independent of scenes: a small box robot inside a large solid block, and the
  // reverse; the oracle confirms the containment, FCL says free, the exact test
  // says collision.
  TriangleSoup big, small;
  for (int i = 0; i < 8; ++i) {
    big.vertices.emplace_back(i & 1 ? 4 : -4, i & 2 ? 4 : -4, i & 4 ? 2 : -1);
    small.vertices.emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.25 : -0.25, i & 4 ? 1 : 0);
  }
  const std::vector<TriangleIndices> faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                              {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  big.triangles = small.triangles = faces;
  const Mesh block = Mesh::fromSoup(big, "block"), box = Mesh::fromSoup(small, "box");
  const Pose2 inside{1.0, -2.0, 0.7};
  for (const auto& [robot, world] : {std::pair<const Mesh*, const Mesh*>{&box, &block}, {&block, &box}}) {
    ASSERT_TRUE(containmentByOracle(*robot, *world, inside));
    EXPECT_FALSE(FclCollisionChecker(*robot, *world).inCollision(inside));
    EXPECT_GT(FclCollisionChecker(*robot, *world).distance(inside), 0.1);
    EXPECT_TRUE(ExactCollisionChecker(*robot, *world).inCollision(inside));
  }
}
