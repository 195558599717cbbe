#include "raised_passage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "freespace/numbers/angle_reduction.h"

namespace freespace {

namespace {

using Clock = std::chrono::steady_clock;

/// At most this many parts per motion of the whole passage's length: fine enough
/// that waypoints pushed to a passage's middle keep the motions between them there.
constexpr double kPartsPerPassage = 200;
/// Pushing rounds over all waypoints, at most.
constexpr int kRounds = 40;
constexpr std::size_t kMostWaypoints = 4000;
/// Only waypoints whose clearance is within this factor of the least are pushed:
/// those with more are not in the way, and pushed toward wider places they would
/// pull the path apart.
constexpr double kNearFloor = 1.1;
/// A motion certified below this share of its ends' clearance is halved, at most
/// kHalvings times.
constexpr double kDip = 0.99;
constexpr int kHalvings = 4;

/// A waypoint being pushed: its clearance, and the step it tries next in (x, y) and
/// in theta (both shrink when a try fails to raise the clearance).
struct PushedWaypoint {
  Pose2 pose;
  Clearance clearance;
  double step = 0, turnStep = 0;
  /// The certified bound on the motion to the next waypoint, while neither moves.
  std::optional<double> motionBound;
};

double metricLength(const Pose2& from, const Pose2& to, double reach) {
  return std::hypot(to.x - from.x, to.y - from.y) + reach * std::fabs(MotionChecker::shorterTurn(from.theta, to.theta));
}

PushedWaypoint pushedWaypoint(const Pose2& pose, const Clearance& clearance, double reach) {
  return {pose, clearance, 0.5 * clearance.lower, 0.5 * clearance.lower / reach, std::nullopt};
}

/// Cuts each motion k into partsOf(k) equal parts, but never into more than
/// kMostWaypoints waypoints in all; whether it cut any. A blocked cut is left out (the
/// motion's check will fail).
template <typename PartsOf>
bool cutMotions(const FreeSpace& space, double reach, PartsOf partsOf, std::vector<PushedWaypoint>& waypoints) {
  std::vector<PushedWaypoint> cut{waypoints.front()};
  for (std::size_t k = 0; k + 1 < waypoints.size(); ++k) {
    const Pose2 &from = waypoints[k].pose, &to = waypoints[k + 1].pose;
    const int parts = partsOf(k);
    if (parts > 1) cut.back().motionBound.reset();
    for (int part = 1; part < parts && waypoints.size() + cut.size() < kMostWaypoints; ++part) {
      const Pose2 pose = MotionChecker::interpolate(from, to, static_cast<double>(part) / parts);
      const Clearance clearance = space.clearance(pose, MotionChecker::kClearanceWidth);
      if (clearance.location.free) cut.push_back(pushedWaypoint(pose, clearance, reach));
    }
    cut.push_back(waypoints[k + 1]);
  }
  const bool any = cut.size() > waypoints.size();
  waypoints = std::move(cut);
  return any;
}

/// Replaces the waypoint by `candidate` when that is free with more clearance. A
/// candidate less than the clearance away (in |dxy| + r |dtheta|) is joined to it by
/// a free motion: the waypoint stays in its cell.
bool tryMove(const FreeSpace& space, PushedWaypoint& waypoint, const Pose2& candidate) {
  const Clearance clearance = space.clearance(candidate, MotionChecker::kClearanceWidth);
  if (!clearance.location.free || clearance.lower <= waypoint.clearance.lower) return false;
  waypoint.pose = candidate;
  waypoint.clearance = clearance;
  return true;
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

Pose2 moved(const Pose2& pose, const std::array<double, 3>& move, double reach) {
  return {pose.x + move[0], pose.y + move[1], reducedAngle(pose.theta + move[2] / reach)};
}

/// One push of a waypoint between two others: away from its nearest contact, then
/// turned either way (each across the path); whether it moved.
bool push(const FreeSpace& space, double reach, const Pose2& previous, const Pose2& next, PushedWaypoint& waypoint) {
  bool raised = false;
  const std::array<double, 2> toContact = waypoint.clearance.direction;
  if (waypoint.step > 1e-6 * waypoint.clearance.lower && (toContact[0] != 0 || toContact[1] != 0)) {
    const std::array<double, 3> away =
        acrossPath({-waypoint.step * toContact[0], -waypoint.step * toContact[1], 0}, previous, next, reach);
    const bool pushed = tryMove(space, waypoint, moved(waypoint.pose, away, reach));
    waypoint.step = std::min(pushed ? 1.5 * waypoint.step : 0.5 * waypoint.step, 0.5 * waypoint.clearance.lower);
    raised |= pushed;
  }
  if (waypoint.turnStep * reach > 1e-6 * waypoint.clearance.lower) {
    const std::array<double, 3> turn = acrossPath({0, 0, reach * waypoint.turnStep}, previous, next, reach);
    const Pose2 pose = waypoint.pose;
    const bool turned = tryMove(space, waypoint, moved(pose, turn, reach)) ||
                        tryMove(space, waypoint, moved(pose, {-turn[0], -turn[1], -turn[2]}, reach));
    waypoint.turnStep =
        std::min(turned ? 1.5 * waypoint.turnStep : 0.5 * waypoint.turnStep, 0.5 * waypoint.clearance.lower / reach);
    raised |= turned;
  }
  return raised;
}

/// Pushes the waypoints near the least clearance among them, round after round, and
/// cuts the motions that grow longer than `spacing`, until none moves; false when
/// `deadline` passes first.
bool relax(const FreeSpace& space, double reach, double spacing, std::vector<PushedWaypoint>& waypoints,
           Clock::time_point deadline, const Cancellation& cancellation) {
  const auto partsOf = [&](std::size_t k) {
    return std::max(
        1, static_cast<int>(std::ceil(metricLength(waypoints[k].pose, waypoints[k + 1].pose, reach) / spacing)));
  };
  for (int round = 0; round < kRounds; ++round) {
    bool moved = cutMotions(space, reach, partsOf, waypoints);
    double floor = HUGE_VAL;
    for (const PushedWaypoint& waypoint : waypoints) floor = std::min(floor, waypoint.clearance.lower);
    for (std::size_t k = 1; k + 1 < waypoints.size(); ++k) {
      if (waypoints[k].clearance.lower > kNearFloor * floor) continue;
      cancellation.check();
      if (Clock::now() > deadline) return false;
      if (!push(space, reach, waypoints[k - 1].pose, waypoints[k + 1].pose, waypoints[k])) continue;
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
  for (std::size_t k = 0; k + 1 < waypoints.size(); ++k) {
    if (!waypoints[k].motionBound) {
      const double secondsLeft = std::chrono::duration<double>(deadline - Clock::now()).count();
      if (secondsLeft <= 0) return std::nullopt;
      const MotionCheck check = rate.check(checker, waypoints[k].pose, waypoints[k + 1].pose, 0.01, secondsLeft);
      if (!check.free) return std::nullopt;
      waypoints[k].motionBound = check.minClearance;
    }
    passage.motionClearance.push_back(*waypoints[k].motionBound);
    passage.lower = std::min(passage.lower, *waypoints[k].motionBound);
  }
  return passage;
}

}  // namespace

std::optional<Passage> raisedPassage(const FreeSpace& space, const MotionChecker& checker, const Passage& passage,
                                     Clock::time_point deadline, QueryRate& rate, const Cancellation& cancellation) {
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
    waypoints.push_back(pushedWaypoint(pose, clearance, reach));
  }
  // Motions that dip well below their ends' clearance (cutting a bend) are halved
  // and their middles pushed too.
  std::optional<Passage> raised;
  for (int halving = 0; halving <= kHalvings; ++halving) {
    if (!relax(space, reach, spacing, waypoints, deadline, cancellation)) break;
    std::optional<Passage> next = certified(checker, waypoints, deadline, rate);
    if (!next) break;
    if (!raised || next->lower > raised->lower) raised = next;
    const auto partsOf = [&](std::size_t k) {
      const double ends = std::min(waypoints[k].clearance.lower, waypoints[k + 1].clearance.lower);
      return next->motionClearance[k] < kDip * ends ? 2 : 1;
    };
    if (!cutMotions(space, reach, partsOf, waypoints)) break;
  }
  return raised;
}

}  // namespace freespace
