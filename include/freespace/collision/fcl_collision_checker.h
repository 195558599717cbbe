#pragma once

#include <memory>

#include "freespace/geometry/mesh.h"
#include "freespace/problem/planar_problem.h"

namespace freespace {

/// The baseline that OMPL users run today: FCL (BVHModel<OBBRSS>) collision and
/// distance queries on the same meshes and with the same pose convention as
/// ExactCollisionChecker (robot rotated by theta about its z axis through its
/// origin, then translated by (x, y, 0)). FCL only tests surfaces, so a body
/// strictly inside another counts as free, and its distance is a 3D mesh distance
/// (0 in collision). Thread safe.
class FclCollisionChecker {
 public:
  FclCollisionChecker(const Mesh& robot, const Mesh& world);
  /// On triangles as read from files (OMPL.app's checker takes them as they are:
  /// FCL needs no closed surface).
  FclCollisionChecker(const TriangleSoup& robot, const TriangleSoup& world);
  ~FclCollisionChecker();
  FclCollisionChecker(const FclCollisionChecker&) = delete;
  FclCollisionChecker& operator=(const FclCollisionChecker&) = delete;

  bool inCollision(const Pose2& pose) const;
  /// Minimum 3D distance between the surfaces; 0 when they intersect.
  double distance(const Pose2& pose) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace freespace
