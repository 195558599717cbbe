#include "raised_passage.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>

#include "contact_point.h"
#include "every_core.h"
#include "freespace/numbers/angle_reduction.h"

namespace freespace {

namespace {

using Clock = std::chrono::steady_clock;

/// At most this many parts per motion of the whole passage's length: fine enough
/// that waypoints pushed to a passage's middle keep the motions between them there.
constexpr double kPartsPerPassage = 200;
/// Pushing rounds over all waypoints, and waypoints in all (motions are cut no
/// further), at most.
constexpr int kRounds = 100;
constexpr std::size_t kMostWaypoints = 4000;
/// Only waypoints whose clearance is within this factor of the least are pushed:
/// those with more are not in the way, and pushed toward wider places they would
/// pull the path apart.
constexpr double kNearFloor = 1.1;
/// A motion certified below this share of its ends' clearance is halved, at most
/// kHalvings times.
constexpr double kDip = 0.99;
constexpr int kHalvings = 4;
/// A step is at most this share of the waypoint's clearance: in |dxy| + r |dtheta|
/// (at most sqrt 2 times its length) shorter than the clearance, so the waypoint stays
/// in its cell.
constexpr double kLongestStep = 0.5;

/// A waypoint being pushed: its clearance, and the length of the step it tries next
/// in (x, y, r theta) (it shrinks when a try fails to raise the clearance).
struct PushedWaypoint {
  Pose2 pose;
  Clearance clearance;
  double step = 0;
  /// The certified bound on the motion to the next waypoint, while neither moves.
  std::optional<double> motionBound;
};

double metricLength(const Pose2& from, const Pose2& to, double reach) {
  return std::hypot(to.x - from.x, to.y - from.y) + reach * std::fabs(MotionChecker::shorterTurn(from.theta, to.theta));
}

PushedWaypoint pushedWaypoint(const Pose2& pose, const Clearance& clearance) {
  return {pose, clearance, kLongestStep * clearance.lower, std::nullopt};
}

/// Cuts each motion k into partsOf(k) equal parts, but never into more than
/// kMostWaypoints waypoints in all; whether it cut any. A blocked cut is left out (the
/// motion's check will fail).
template <typename PartsOf>
bool cutMotions(const FreeSpace& space, PartsOf partsOf, std::vector<PushedWaypoint>& waypoints) {
  std::vector<PushedWaypoint> cut{waypoints.front()};
  for (std::size_t k = 0; k + 1 < waypoints.size(); ++k) {
    const Pose2 &from = waypoints[k].pose, &to = waypoints[k + 1].pose;
    const int parts = partsOf(k);
    if (parts > 1) cut.back().motionBound.reset();
    for (int part = 1; part < parts && waypoints.size() + cut.size() < kMostWaypoints; ++part) {
      const Pose2 pose = MotionChecker::interpolate(from, to, static_cast<double>(part) / parts);
      const Clearance clearance = space.clearance(pose, MotionChecker::kClearanceWidth);
      if (clearance.location.free) cut.push_back(pushedWaypoint(pose, clearance));
    }
    cut.push_back(waypoints[k + 1]);
  }
  const bool any = cut.size() > waypoints.size();
  waypoints = std::move(cut);
  return any;
}

/// A move of a waypoint in (x, y, r theta) without its part along the path's
/// direction there (from the previous waypoint to the next): pushed that way, the
/// waypoints would slide along the passage toward wider places instead of to its
/// middle, and the motions between them would grow.
std::array<double, 3> acrossPath(std::array<double, 3> move, const Pose2& previous, const Pose2& next, double reach) {
  const std::array<double, 3> along{next.x - previous.x, next.y - previous.y,
                                    reach * MotionChecker::shorterTurn(previous.theta, next.theta)};
  const double squared = along[0] * along[0] + along[1] * along[1] + along[2] * along[2];
  if (squared == 0) return move;
  const double share = (move[0] * along[0] + move[1] * along[1] + move[2] * along[2]) / squared;
  for (int axis = 0; axis < 3; ++axis) move[axis] -= share * along[axis];
  return move;
}

/// The clearance's gradient at a configuration at angle theta in (x, y, r theta),
/// from its witness: away from the contact in (x, y); in theta, how fast turning moves
/// the robot's point in the contact away from it. None without a contact.
std::optional<std::array<double, 3>> gradient(const FreeSpace& space, const Clearance& clearance, double theta,
                                              double reach) {
  const std::optional<ContactPoint> point = contactPoint(space, clearance, theta, 0);
  if (!point) return std::nullopt;
  const std::array<double, 2>& toContact = clearance.direction;
  // Turning by dtheta moves the point by dtheta (-y, x).
  const double towardContact = toContact[0] * -point->fromAxis[1] + toContact[1] * point->fromAxis[0];
  return std::array<double, 3>{-toContact[0], -toContact[1], -towardContact / reach};
}

double norm(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/// The point of the segment from a to b nearest the origin: the direction that raises
/// both of two distances with these gradients fastest (it is 0 where no direction
/// raises both).
std::array<double, 3> leastOfSegment(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  std::array<double, 3> difference{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double squared = difference[0] * difference[0] + difference[1] * difference[1] + difference[2] * difference[2];
  double share = 0;  // of the way from a to b
  if (squared > 0) {
    share = std::clamp(-(a[0] * difference[0] + a[1] * difference[1] + a[2] * difference[2]) / squared, 0.0, 1.0);
  }
  return {a[0] + share * difference[0], a[1] + share * difference[1], a[2] + share * difference[2]};
}

Pose2 moved(const Pose2& pose, const std::array<double, 3>& direction, double length, double reach) {
  const double scale = length / norm(direction);
  return {pose.x + scale * direction[0], pose.y + scale * direction[1],
          reducedAngle(pose.theta + scale * direction[2] / reach)};
}

/// One push of a waypoint between two others, across the path: up the clearance's
/// gradient; where that meets another contact, up both of theirs (the direction
/// between the two gradients that raises both: the clearance is the least of them);
/// else each coordinate alone (away from the contact in (x, y), turning either way).
/// Whether it moved (never out of `domain`).
bool push(const FreeSpace& space, const Domain& domain, double reach, const Pose2& previous, const Pose2& next,
          PushedWaypoint& waypoint) {
  if (waypoint.step <= 1e-6 * waypoint.clearance.lower) return false;
  const PushedWaypoint from = waypoint;
  Clearance there;
  Pose2 tried;
  const auto raises = [&](const std::array<double, 3>& direction) {
    const std::array<double, 3> across = acrossPath(direction, previous, next, reach);
    if (norm(across) <= 1e-9) return false;
    tried = moved(from.pose, across, from.step, reach);
    if (!domain.holds(tried)) return false;
    // A step of Euclidean length `step` moves |dxy| + reach |dtheta| <= sqrt(2) step:
    // the clearance there is at most that much above the waypoint's (the search's hint).
    there = space.clearance(tried, MotionChecker::kClearanceWidth, from.clearance.upper + 1.5 * from.step);
    return there.location.free && there.lower > from.clearance.lower;
  };
  bool raised = false;
  if (const std::optional<std::array<double, 3>> up = gradient(space, from.clearance, from.pose.theta, reach)) {
    raised = raises(*up);
    if (!raised && there.location.free) {
      const std::optional<std::array<double, 3>> otherUp = gradient(space, there, tried.theta, reach);
      if (otherUp) raised = raises(leastOfSegment(*up, *otherUp));
    }
  }
  const std::array<double, 3> alone[] = {
      {-from.clearance.direction[0], -from.clearance.direction[1], 0}, {0, 0, 1}, {0, 0, -1}};
  for (const std::array<double, 3>& direction : alone) {
    if (!raised) raised = raises(direction);
  }
  if (raised) {
    waypoint.pose = tried;
    waypoint.clearance = there;
  }
  waypoint.step = std::min(raised ? 1.5 * from.step : 0.5 * from.step, kLongestStep * waypoint.clearance.lower);
  return raised;
}

/// Pushes the waypoints near the least clearance among them, round after round, and
/// cuts the motions that grow longer than `spacing`, until none moves; false when
/// `deadline` passes first.
bool relax(const FreeSpace& space, const Domain& domain, double reach, double spacing,
           std::vector<PushedWaypoint>& waypoints, Clock::time_point deadline, const Cancellation& cancellation) {
  const auto partsOf = [&](std::size_t k) {
    return std::max(
        1, static_cast<int>(std::ceil(metricLength(waypoints[k].pose, waypoints[k + 1].pose, reach) / spacing)));
  };
  for (int round = 0; round < kRounds; ++round) {
    bool moved = cutMotions(space, partsOf, waypoints);
    double floor = HUGE_VAL;
    for (const PushedWaypoint& waypoint : waypoints) floor = std::min(floor, waypoint.clearance.lower);
    for (std::size_t k = 1; k + 1 < waypoints.size(); ++k) {
      if (waypoints[k].clearance.lower > kNearFloor * floor) continue;
      cancellation.check();
      if (Clock::now() > deadline) return false;
      if (!push(space, domain, reach, waypoints[k - 1].pose, waypoints[k + 1].pose, waypoints[k])) continue;
      moved = true;
      waypoints[k - 1].motionBound.reset();
      waypoints[k].motionBound.reset();
    }
    if (!moved) break;
  }
  return true;
}

/// The waypoints' motions, each certified with a bound within 1% of its ends' clearance
/// (kept for the motions whose ends have not moved since); none when one is not
/// certified free (or not before `deadline`).
std::optional<Passage> certified(const MotionChecker& checker, std::vector<PushedWaypoint>& waypoints,
                                 Clock::time_point deadline, QueryRate& rate) {
  Passage passage;
  for (const PushedWaypoint& waypoint : waypoints) passage.waypoints.push_back(waypoint.pose);
  // The motions whose ends moved, on every core, until one is not certified free.
  std::vector<std::size_t> unknown;
  for (std::size_t k = 0; k + 1 < waypoints.size(); ++k) {
    if (!waypoints[k].motionBound) unknown.push_back(k);
  }
  std::atomic<bool> allFree{true};
  const auto going = [&] { return allFree && Clock::now() < deadline; };
  onEveryCore(unknown.size(), going, [&](std::size_t at) {
    const std::size_t k = unknown[at];
    const double secondsLeft = std::chrono::duration<double>(deadline - Clock::now()).count();
    const MotionCheck check = rate.check(checker, waypoints[k].pose, waypoints[k + 1].pose, 0.01, secondsLeft);
    if (check.free) {
      waypoints[k].motionBound = check.minClearance;
    } else {
      allFree = false;
    }
  });
  for (std::size_t k = 0; k + 1 < waypoints.size(); ++k) {
    if (!waypoints[k].motionBound) return std::nullopt;
    passage.motionClearance.push_back(*waypoints[k].motionBound);
    passage.lower = std::min(passage.lower, *waypoints[k].motionBound);
  }
  return passage;
}

}  // namespace

std::optional<Passage> raisedPassage(const FreeSpace& space, const MotionChecker& checker, const Passage& passage,
                                     const Domain& domain, Clock::time_point deadline, QueryRate& rate,
                                     const Cancellation& cancellation) {
  const double reach = checker.reach();
  double length = 0;
  for (std::size_t k = 0; k + 1 < passage.waypoints.size(); ++k) {
    length += metricLength(passage.waypoints[k], passage.waypoints[k + 1], reach);
  }
  const double spacing = std::max(passage.lower, length / kPartsPerPassage);
  std::vector<PushedWaypoint> waypoints;
  for (const Pose2& pose : passage.waypoints) {
    const Clearance clearance = space.clearance(pose, MotionChecker::kClearanceWidth);
    if (!clearance.location.free) return std::nullopt;
    waypoints.push_back(pushedWaypoint(pose, clearance));
  }
  // Motions that dip well below their ends' clearance (cutting a bend) are halved
  // and their middles pushed too.
  std::optional<Passage> raised;
  for (int halving = 0; halving <= kHalvings; ++halving) {
    if (!relax(space, domain, reach, spacing, waypoints, deadline, cancellation)) break;
    std::optional<Passage> next = certified(checker, waypoints, deadline, rate);
    if (!next) break;
    if (!raised || next->lower > raised->lower) raised = next;
    const auto partsOf = [&](std::size_t k) {
      const double ends = std::min(waypoints[k].clearance.lower, waypoints[k + 1].clearance.lower);
      return next->motionClearance[k] < kDip * ends ? 2 : 1;
    };
    if (!cutMotions(space, partsOf, waypoints)) break;
  }
  // Its tightest motions' bounds within 0.3% of their ends' clearance.
  if (raised) tightenBounds(space, checker, *raised, 0.003, deadline, rate, cancellation);
  return raised;
}

}  // namespace freespace
