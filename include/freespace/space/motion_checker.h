#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "freespace/space/free_space.h"

namespace freespace {

/// What a motion check found (MotionChecker::check).
struct MotionCheck {
  /// The whole motion is free, certified.
  bool free = false;
  /// The motion is certified free from its start up to this fraction (1 when free).
  double lastFreeFraction = 0;
  /// A certified lower bound on the clearance along the whole motion (when free).
  double minClearance = 0;
  /// How many clearances were computed.
  std::size_t clearanceQueries = 0;
};

/// Motions as OMPL's SE(2) space interpolates them (x and y linear, theta along the
/// shorter arc), certified free by clearances (docs/design.md section 7): the
/// clearance is 1-Lipschitz in (x, y) and r-Lipschitz in theta (r the robot's
/// largest distance from its vertical axis), so a part of the motion between two
/// free configurations with certified clearances c0 and c1 is free when c0 + c1
/// exceeds its length in the metric |dxy| + r |dtheta|; parts that are not are
/// halved, down to 1e-12 of the motion (a motion that only grazes the obstacle is
/// never certified free).
class MotionChecker {
 public:
  explicit MotionChecker(const FreeSpace& space);

  /// The relative width of the clearances that certify motions and paths: certified
  /// bounds need not be as narrow as FreeSpace::clearance's default, and double
  /// intervals give this without exact arithmetic (about half the time per clearance).
  static constexpr double kClearanceWidth = 1e-9;

  /// The configuration a fraction t of the way from `from` to `to`.
  static Pose2 interpolate(const Pose2& from, const Pose2& to, double t);
  /// Theta's change along the shorter arc, as OMPL's SO(2) space interpolates (half a
  /// turn goes the direct way).
  static double shorterTurn(double from, double to);

  /// Checks the motion; `clearanceSlack` (relative) makes the parts shorter until the
  /// bound on each is within that fraction of its ends' smaller clearance (1: only
  /// certify freedom; 0.02 for a bound on the clearance within 2%). A motion that would
  /// take more than `queryLimit` clearances (one passing within a tiny fraction of its
  /// length of a contact) is not certified free.
  MotionCheck check(const Pose2& from, const Pose2& to, double clearanceSlack = 1,
                    std::size_t queryLimit = SIZE_MAX) const;

  /// Whether the clearance stays at least `level` (> 0) along the whole motion,
  /// certified; false as soon as a configuration on it has less, or when certifying
  /// would take more than `queryLimit` clearances (false is not a proof).
  bool keepsClearance(const Pose2& from, const Pose2& to, double level, std::size_t queryLimit = 256) const;

  /// The least clearance along the whole motion that the Lipschitz bound guarantees
  /// from certified clearances at its ends (from elsewhere than FreeSpace::clearance);
  /// none when that is not positive (the ends alone do not certify the motion free).
  std::optional<double> leastClearanceBetween(const Pose2& from, const Pose2& to, double clearanceFrom,
                                              double clearanceTo) const;

  /// How far the configurations OMPL interpolates between `from` and `to` may lie from
  /// the exact segment between them, in (x, y), and then some: their rounding.
  static double interpolationRounding(const Pose2& from, const Pose2& to);

  /// The robot's largest distance from its vertical axis, rounded up: the clearance's
  /// Lipschitz constant in theta.
  double reach() const { return reach_; }

 private:
  struct Part;
  /// The motion's length in |dxy| + r |dtheta|, with room for its rounding.
  double metricLength(const Pose2& from, const Pose2& to) const;
  /// Halves the motion's parts, the nearest first, until `certain` accepts each
  /// (given the least clearance the Lipschitz bound guarantees on it and its ends'
  /// clearances), a part starts blocked, `hopeless` rejects one, or the parts or
  /// queries run out; fills `result` (free when every part was accepted).
  template <typename Certain, typename Hopeless>
  void certify(const Pose2& from, const Pose2& to, Certain certain, Hopeless hopeless, std::size_t queryLimit,
               MotionCheck& result) const;

  const FreeSpace& space_;
  double reach_;  // the robot's largest distance from its vertical axis, rounded up
};

}  // namespace freespace
