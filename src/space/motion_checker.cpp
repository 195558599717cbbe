#include "freespace/space/motion_checker.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace freespace {

namespace {

/// The smallest fraction of a motion a part is halved down to.
constexpr double kShortestPart = 1e-12;

/// The least clearance the Lipschitz bound guarantees on a part of metric length
/// `length` between clearances c0 and c1: the lowest point of the upper envelope of
/// the two cones c0 - s and c1 - (length - s).
double leastClearanceOn(double c0, double c1, double length) {
  if (std::fabs(c0 - c1) >= length) return std::min(c0, c1);
  return (c0 + c1 - length) / 2;
}

}  // namespace

MotionChecker::MotionChecker(const FreeSpace& space)
    // In the input's units, rounded up far beyond the rounding of the hypotenuse.
    : space_(space), reach_(space.meshes().robot.horizontalReach() / space.meshes().scale * (1 + 1e-12)) {}

double MotionChecker::shorterTurn(double from, double to) {
  double turn = to - from;
  if (std::fabs(turn) > M_PI) turn = std::remainder(turn, 2 * M_PI);
  return turn;
}

Pose2 MotionChecker::interpolate(const Pose2& from, const Pose2& to, double t) {
  return {from.x + t * (to.x - from.x), from.y + t * (to.y - from.y),
          from.theta + t * shorterTurn(from.theta, to.theta)};
}

double MotionChecker::interpolationRounding(const Pose2& from, const Pose2& to) {
  return 1e-12 * (1 + std::max({std::fabs(from.x), std::fabs(from.y), std::fabs(to.x), std::fabs(to.y)}));
}

double MotionChecker::metricLength(const Pose2& from, const Pose2& to) const {
  return std::hypot(to.x - from.x, to.y - from.y) * (1 + 1e-12) +
         reach_ * std::fabs(shorterTurn(from.theta, to.theta)) + interpolationRounding(from, to);
}

std::optional<double> MotionChecker::leastClearanceBetween(const Pose2& from, const Pose2& to, double clearanceFrom,
                                                           double clearanceTo) const {
  const double least = leastClearanceOn(clearanceFrom, clearanceTo, metricLength(from, to));
  if (!(least > 0)) return std::nullopt;
  return least;
}

/// A part of the motion between fractions `from` and `to`, with the clearances there
/// (certified lower bounds; 0 or less where the configuration is not free).
struct MotionChecker::Part {
  double from, to;
  double clearanceFrom, clearanceTo;
};

template <typename Certain, typename Hopeless>
void MotionChecker::certify(const Pose2& from, const Pose2& to, Certain certain, Hopeless hopeless,
                            std::size_t queryLimit, MotionCheck& result) const {
  const auto clearanceAt = [&](double t, double expected = HUGE_VAL) {
    ++result.clearanceQueries;
    const Clearance clearance = space_.clearance(interpolate(from, to, t), kClearanceWidth, expected);
    return clearance.location.free ? clearance.lower : 0.0;
  };
  const double length = metricLength(from, to);
  result.minClearance = HUGE_VAL;
  // Parts from the start on, the nearest first, so that the certified prefix grows.
  std::vector<Part> parts{{0, 1, clearanceAt(0), clearanceAt(1)}};
  while (!parts.empty()) {
    const Part part = parts.back();
    if (part.clearanceFrom <= 0 || hopeless(part.clearanceFrom) || hopeless(part.clearanceTo)) break;
    const double least = leastClearanceOn(part.clearanceFrom, part.clearanceTo, (part.to - part.from) * length);
    if (certain(least, part.clearanceFrom, part.clearanceTo)) {
      parts.pop_back();
      result.lastFreeFraction = part.to;
      result.minClearance = std::min(result.minClearance, least);
      continue;
    }
    if (part.to - part.from < kShortestPart || result.clearanceQueries >= queryLimit) break;
    parts.pop_back();
    // The middle's clearance is at most an end's plus the way from it (Lipschitz).
    const double middle = 0.5 * (part.from + part.to);
    const double clearanceMiddle =
        clearanceAt(middle, std::min(part.clearanceFrom, part.clearanceTo) + (middle - part.from) * length);
    parts.push_back({middle, part.to, clearanceMiddle, part.clearanceTo});
    parts.push_back({part.from, middle, part.clearanceFrom, clearanceMiddle});
  }
  result.free = parts.empty() && result.lastFreeFraction == 1;
  if (!result.free) result.minClearance = 0;
}

MotionCheck MotionChecker::check(const Pose2& from, const Pose2& to, double clearanceSlack,
                                 std::size_t queryLimit) const {
  MotionCheck result;
  // (Without a slack, an unbounded clearance, where nothing can be touched, needs no comparison.)
  const auto certain = [&](double least, double clearanceFrom, double clearanceTo) {
    return least > 0 && (clearanceSlack >= 1 || least >= (1 - clearanceSlack) * std::min(clearanceFrom, clearanceTo));
  };
  certify(
      from, to, certain, [](double) { return false; }, queryLimit, result);
  return result;
}

bool MotionChecker::keepsClearance(const Pose2& from, const Pose2& to, double level, std::size_t queryLimit) const {
  MotionCheck result;
  const auto certain = [&](double least, double, double) { return least >= level; };
  const auto hopeless = [&](double clearance) { return clearance < level; };
  certify(from, to, certain, hopeless, queryLimit, result);
  return result.free;
}

}  // namespace freespace
