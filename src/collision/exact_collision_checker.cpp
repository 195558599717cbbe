#include "freespace/collision/exact_collision_checker.h"

#include <map>
#include <vector>

#include "../geometry/closed_triangle_tests.h"
#include "../geometry/triangle_box_tree.h"
#include "placed_pair.h"

namespace freespace {

namespace {

namespace bgi = boost::geometry::index;
using detail::TreeEntry;
using detail::treeBox;
using detail::TriangleTree;

using detail::kRobotPoint;
using detail::PlacedPair;
using detail::PointId;
using Tests = detail::ClosedTriangleTests<PlacedPair, PointId>;

Tests::Triangle worldTriangle(const Mesh& world, std::uint32_t triangle) {
  const TriangleIndices& t = world.triangles()[triangle];
  return {t[0], t[1], t[2]};
}

Tests::Triangle robotTriangle(const Mesh& robot, std::uint32_t triangle) {
  const TriangleIndices& t = robot.triangles()[triangle];
  return {t[0] | kRobotPoint, t[1] | kRobotPoint, t[2] | kRobotPoint};
}

}  // namespace

struct ExactCollisionChecker::Impl {
  Impl(const Mesh& robotMesh, const Mesh& worldMesh)
      : robot(robotMesh), world(worldMesh), worldTree(detail::triangleTree(world.vertices(), world.triangles())) {
    robotComponentTriangles.resize(robot.componentCount());
    for (std::uint32_t i = 0; i < robot.triangles().size(); ++i) {
      robotComponentTriangles[robot.triangleComponents()[i]].push_back(i);
    }
  }

  bool collides(PlacedPair& pair) {
    Tests tests(pair);
    const bool collision = surfacesIntersect(pair, tests) || robotInsideWorld(pair, tests) || worldInsideRobot(pair, tests);
    evaluated.fetch_add(pair.evaluatedCount(), std::memory_order_relaxed);
    exact.fetch_add(pair.exactCount(), std::memory_order_relaxed);
    return collision;
  }

  bool surfacesIntersect(PlacedPair& pair, Tests& tests) const;
  bool robotInsideWorld(PlacedPair& pair, Tests& tests) const;
  bool worldInsideRobot(PlacedPair& pair, Tests& tests) const;

  Mesh robot;
  Mesh world;
  TriangleTree worldTree;
  std::vector<std::vector<std::uint32_t>> robotComponentTriangles;
  mutable std::atomic<std::uint64_t> evaluated{0};
  mutable std::atomic<std::uint64_t> exact{0};
};

bool ExactCollisionChecker::Impl::surfacesIntersect(PlacedPair& pair, Tests& tests) const {
  std::vector<TreeEntry> candidates;
  for (std::uint32_t i = 0; i < robot.triangles().size(); ++i) {
    candidates.clear();
    worldTree.query(bgi::intersects(treeBox(pair.robotTriangleBounds(i))), std::back_inserter(candidates));
    for (const TreeEntry& candidate : candidates) {
      if (tests.trianglesIntersect(robotTriangle(robot, i), worldTriangle(world, candidate.second))) return true;
    }
  }
  return false;
}

/// With the surfaces disjoint, each robot component is wholly inside or wholly
/// outside each world component: one vertex decides. Winding numbers are counted
/// along a ray in +x (ClosedTriangleTests::rayCrossing).
bool ExactCollisionChecker::Impl::robotInsideWorld(PlacedPair& pair, Tests& tests) const {
  const double rayEnd = world.bounds().max().x();
  std::vector<TreeEntry> candidates;
  for (std::uint32_t vertex : robot.componentRepresentatives()) {
    const PointId q = vertex | kRobotPoint;
    Box3 ray = pair.bounds(q);
    if (ray.min().x() > rayEnd) continue;
    ray.max().x() = rayEnd;
    candidates.clear();
    worldTree.query(bgi::intersects(treeBox(ray)), std::back_inserter(candidates));
    std::map<std::uint32_t, int> windingByComponent;
    bool onSurface = false;
    for (const TreeEntry& candidate : candidates) {
      const int crossing = tests.rayCrossing(q, worldTriangle(world, candidate.second), onSurface);
      windingByComponent[world.triangleComponents()[candidate.second]] += crossing;
    }
    if (onSurface) return true;
    for (const auto& [component, winding] : windingByComponent) {
      if (winding != 0) return true;
    }
  }
  return false;
}

bool ExactCollisionChecker::Impl::worldInsideRobot(PlacedPair& pair, Tests& tests) const {
  const Box3 robotBounds = pair.robotBounds();
  for (std::uint32_t q : world.componentRepresentatives()) {
    if (!robotBounds.contains(world.vertices()[q])) continue;
    for (const std::vector<std::uint32_t>& triangles : robotComponentTriangles) {
      int winding = 0;
      bool onSurface = false;
      for (std::uint32_t triangle : triangles) winding += tests.rayCrossing(q, robotTriangle(robot, triangle), onSurface);
      if (onSurface || winding != 0) return true;
    }
  }
  return false;
}

ExactCollisionChecker::ExactCollisionChecker(const Mesh& robot, const Mesh& world)
    : impl_(std::make_unique<Impl>(robot, world)) {}

ExactCollisionChecker::~ExactCollisionChecker() = default;

bool ExactCollisionChecker::inCollision(const Pose2& pose) const {
  return inCollision(HalfAngle::fromRadians(pose.theta), pose.x, pose.y);
}

bool ExactCollisionChecker::inCollision(const HalfAngle& angle, double x, double y) const {
  RoundingScope rounding;
  PlacedPair pair(impl_->robot, impl_->world, angle, x, y);
  return impl_->collides(pair);
}

bool ExactCollisionChecker::inCollisionAt(const ExactPose& pose) const {
  RoundingScope rounding;
  PlacedPair pair(impl_->robot, impl_->world, pose);
  return impl_->collides(pair);
}

ExactCollisionChecker::PredicateCounts ExactCollisionChecker::predicateCounts() const {
  return {impl_->evaluated.load(), impl_->exact.load()};
}

}  // namespace freespace
