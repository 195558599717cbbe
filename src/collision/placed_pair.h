#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "freespace/geometry/determinants.h"
#include "freespace/geometry/mesh.h"
#include "freespace/numbers/half_angle.h"
#include "freespace/numbers/interval.h"
#include "freespace/numbers/rational.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/problem/planar_problem.h"

namespace freespace::detail {

/// Point names shared by the two bodies: world vertex i is i, robot vertex i is
/// i | kRobotPoint.
using PointId = std::uint32_t;
constexpr PointId kRobotPoint = 1u << 31;

/// The robot placed at one configuration next to the world: the points of both
/// bodies, with exact predicates on them. Placed robot vertices are rational (the
/// rotation is rational in the half-angle tangent); they are kept as double
/// intervals and converted to exact rationals only when an interval sign is not
/// certain. Construct and use only inside a RoundingScope.
class PlacedPair {
 public:
  /// The robot turned by the rational angle and moved by (x, y), exactly.
  PlacedPair(const Mesh& robot, const Mesh& world, const HalfAngle& angle, double x, double y);
  /// The robot placed exactly as `pose` says (cosine and sine on the unit circle).
  PlacedPair(const Mesh& robot, const Mesh& world, const ExactPose& pose);

  Sign orient3d(PointId a, PointId b, PointId c, PointId d) {
    return decide([&](auto point) { return orient3dDeterminant(point(a), point(b), point(c), point(d)); });
  }
  Sign orient2d(PointId a, PointId b, PointId c, int droppedAxis) {
    return decide([&](auto point) { return orient2dDeterminant(point(a), point(b), point(c), droppedAxis); });
  }
  Sign between(PointId a, PointId b, PointId c, int droppedAxis) {
    return decide(
        [&](auto point) { return projectedBetweenDeterminant(point(a), point(b), point(c), droppedAxis); });
  }
  Sign compare(PointId a, PointId b, int axis) {
    return decide([&](auto point) { return point(a)[axis] - point(b)[axis]; });
  }

  /// Bounds of a placed point (exact for world points).
  Box3 bounds(PointId id) const;
  /// Bounds of the placed robot triangle.
  Box3 robotTriangleBounds(std::uint32_t triangle) const;
  Box3 robotBounds() const { return robotBounds_; }

  std::uint64_t evaluatedCount() const { return evaluated_; }
  std::uint64_t exactCount() const { return exact_; }

 private:
  /// Sign of a determinant written once over point coordinates: double intervals
  /// first, GMP rationals when the interval contains zero but is not zero.
  template <class Determinant>
  Sign decide(Determinant&& determinant) {
    ++evaluated_;
    const Interval estimate = determinant([this](PointId id) { return approximate(id); });
    if (const std::optional<Sign> sign = certainSign(estimate)) return *sign;
    ++exact_;
    return exactSign(determinant([this](PointId id) -> const Vec3T<Rational>& { return exact(id); }));
  }

  Vec3T<Interval> approximate(PointId id) const;
  const Vec3T<Rational>& exact(PointId id);

  const Mesh& robot_;
  const Mesh& world_;
  void place(const Interval& cosine, const Interval& sine, const Interval& x, const Interval& y);

  HalfAngle angle_;
  double x_ = 0, y_ = 0;
  std::vector<Vec3T<Interval>> placedRobot_;
  Box3 robotBounds_;
  std::optional<ExactPose> exactPose_;  // given, or made from the angle once needed
  std::vector<std::optional<Vec3T<Rational>>> exactRobot_;
  std::vector<std::optional<Vec3T<Rational>>> exactWorld_;
  std::uint64_t evaluated_ = 0;
  std::uint64_t exact_ = 0;
};

}  // namespace freespace::detail
