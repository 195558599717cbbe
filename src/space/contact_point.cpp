#include "contact_point.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace freespace {

namespace {

/// Where the placed robot edge robot0-robot1 crosses the environment's edge
/// world0-world1, from `at` (see contactPoint).
std::optional<ContactPoint> crossing(const Point3& robot0, const Point3& robot1, const Point3& world0,
                                     const Point3& world1, const Point3& at, double slack) {
  const Point3 alongRobot = robot1 - robot0, alongWorld = world1 - world0, between = robot0 - world0;
  const double a = alongRobot.squaredNorm(), b = alongRobot.dot(alongWorld), e = alongWorld.squaredNorm();
  const double c = alongRobot.dot(between), f = alongWorld.dot(between);
  const double determinant = a * e - b * b;
  const double sine = std::sqrt(std::max(0.0, determinant / (a * e)));
  if (!(sine > 1e-6)) return std::nullopt;
  const double s = (b * f - c * e) / determinant, t = (a * f - b * c) / determinant;
  if (s < -1e-9 || s > 1 + 1e-9 || t < -1e-9 || t > 1 + 1e-9) return std::nullopt;
  const Point3 onRobot = robot0 + s * alongRobot, onWorld = world0 + t * alongWorld;
  const double gap = (onRobot - onWorld).norm();
  const Point3 fromAxis = onRobot - at;
  return ContactPoint{{fromAxis.x(), fromAxis.y()}, 1e-12 * fromAxis.norm() + 4 * (slack + gap) / sine};
}

}  // namespace

std::optional<ContactPoint> contactPoint(const FreeSpace& space, const Clearance& clearance, double theta,
                                         double slack) {
  if (!clearance.contact) return std::nullopt;
  const PerturbedMeshes& meshes = space.meshes();
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Point3 at(clearance.nearest[0], clearance.nearest[1], 0);
  const auto robotPoint = [&](std::uint32_t vertex) -> Point3 {
    return turn * (meshes.robot.vertices()[vertex] / meshes.scale) + at;
  };
  const auto worldPoint = [&](std::uint32_t vertex) -> Point3 {
    return meshes.world.vertices()[vertex] / meshes.scale;
  };
  const std::array<std::uint32_t, 4>& vertices = clearance.contactVertices;
  switch (clearance.contact->kind) {
    case ContactKind::VertexFacet: {
      const Point3 fromAxis = robotPoint(vertices[0]) - at;
      return ContactPoint{{fromAxis.x(), fromAxis.y()}, 1e-12 * fromAxis.norm()};
    }
    case ContactKind::FacetVertex: {
      const Point3 fromAxis = worldPoint(vertices[0]) - at;
      return ContactPoint{{fromAxis.x(), fromAxis.y()}, 1e-12 * fromAxis.norm() + slack};
    }
    case ContactKind::EdgeEdge:
      break;
  }
  return crossing(robotPoint(vertices[0]), robotPoint(vertices[1]), worldPoint(vertices[2]), worldPoint(vertices[3]),
                  at, slack);
}

}  // namespace freespace
