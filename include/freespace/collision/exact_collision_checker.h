#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

#include "freespace/geometry/mesh.h"
#include "freespace/numbers/half_angle.h"
#include "freespace/numbers/rational.h"
#include "freespace/problem/planar_problem.h"

namespace freespace {

/// A configuration given exactly: the rotation by a rational point (cosine, sine)
/// of the unit circle, then the translation by (x, y).
struct ExactPose {
  Rational cosine, sine, x, y;
};

/// Decides exactly whether robot A placed at (x, y, theta) and environment B
/// intersect. Closed bodies: touching counts as intersecting, and so does a
/// component of one body lying strictly inside a component of the other (which
/// surface-only tests such as FCL's miss).
///
/// Exactness: theta becomes a rational tangent half-angle (HalfAngle::fromRadians),
/// so every placed robot vertex is a rational point. Every decision is the sign of
/// an orientation determinant; it is evaluated with double intervals and, when the
/// interval straddles zero, again with GMP rationals. A bounding-volume hierarchy
/// (Boost.Geometry R-tree) over B's triangles limits the pairs tested.
///
/// Thread safe: queries are const and use no shared scratch memory.
class ExactCollisionChecker {
 public:
  ExactCollisionChecker(const Mesh& robot, const Mesh& world);
  ~ExactCollisionChecker();
  ExactCollisionChecker(const ExactCollisionChecker&) = delete;
  ExactCollisionChecker& operator=(const ExactCollisionChecker&) = delete;

  bool inCollision(const Pose2& pose) const;
  /// The same at the rational angle `angle` (the robot turned exactly by it).
  bool inCollision(const HalfAngle& angle, double x, double y) const;
  bool inCollisionAt(const ExactPose& pose) const;

  /// How many predicate signs needed the exact fallback, and how many were
  /// evaluated in all, since construction (for benchmarks and tests).
  struct PredicateCounts {
    std::uint64_t evaluated = 0;
    std::uint64_t exact = 0;
  };
  PredicateCounts predicateCounts() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace freespace
