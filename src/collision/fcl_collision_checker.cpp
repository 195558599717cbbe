#include "freespace/collision/fcl_collision_checker.h"

#include <fcl/fcl.h>

namespace freespace {

namespace {

using Model = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<Model> buildModel(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& soup) {
  std::vector<fcl::Vector3d> points(vertices.begin(), vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(soup.size());
  for (const TriangleIndices& t : soup) triangles.emplace_back(t[0], t[1], t[2]);
  auto model = std::make_shared<Model>();
  model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
  model->addSubModel(points, triangles);
  model->endModel();
  model->computeLocalAABB();
  return model;
}

fcl::Transform3d transformOf(const Pose2& pose) {
  fcl::Transform3d transform = fcl::Transform3d::Identity();
  transform.translation() = fcl::Vector3d(pose.x, pose.y, 0.0);
  transform.linear() = fcl::AngleAxisd(pose.theta, fcl::Vector3d::UnitZ()).toRotationMatrix();
  return transform;
}

}  // namespace

struct FclCollisionChecker::Impl {
  std::shared_ptr<Model> robot;
  std::shared_ptr<fcl::CollisionObjectd> world;

  /// A fresh robot object per query: FCL objects cache their transformed bounds, so
  /// sharing one between threads is not safe.
  fcl::CollisionObjectd placedRobot(const Pose2& pose) const {
    return fcl::CollisionObjectd(robot, transformOf(pose));
  }
};

FclCollisionChecker::FclCollisionChecker(const Mesh& robot, const Mesh& world)
    : FclCollisionChecker(TriangleSoup{robot.vertices(), robot.triangles()},
                          TriangleSoup{world.vertices(), world.triangles()}) {}

FclCollisionChecker::FclCollisionChecker(const TriangleSoup& robot, const TriangleSoup& world)
    : impl_(std::make_unique<Impl>()) {
  impl_->robot = buildModel(robot.vertices, robot.triangles);
  impl_->world = std::make_shared<fcl::CollisionObjectd>(buildModel(world.vertices, world.triangles));
}

FclCollisionChecker::~FclCollisionChecker() = default;

bool FclCollisionChecker::inCollision(const Pose2& pose) const {
  const fcl::CollisionObjectd robot = impl_->placedRobot(pose);
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(&robot, impl_->world.get(), request, result);
  return result.isCollision();
}

double FclCollisionChecker::distance(const Pose2& pose) const {
  const fcl::CollisionObjectd robot = impl_->placedRobot(pose);
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  fcl::distance(&robot, impl_->world.get(), request, result);
  return std::max(0.0, result.min_distance);
}

}  // namespace freespace
