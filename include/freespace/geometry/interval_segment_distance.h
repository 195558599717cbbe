#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "freespace/numbers/interval.h"

namespace freespace {

/// A point of the plane in double intervals.
using IntervalPoint = std::array<Interval, 2>;

/// Bounds on the distance from a point to a part of a segment: the exact distance lies
/// in [lower, upper]; nearestLambda is where the part's nearest point lies along it
/// (rounded: the foot of the perpendicular, clamped to the part).
struct SegmentDistanceBounds {
  double lower = 0, upper = HUGE_VAL;
  double nearestLambda = 0;
};

/// Bounds on the distance from `from` to the points e0 + lambda (e1 - e0) with lambda
/// between `low` and `high`, intervals holding the part's ends (inside a
/// RoundingScope). The lower bound comes from the part's widest extent and the line's
/// distance, the upper one from points certainly on the part (a distance evaluated over
/// an end's interval bounds the distance to the end from above).
inline SegmentDistanceBounds segmentDistanceBounds(const IntervalPoint& from, const IntervalPoint& e0,
                                                   const IntervalPoint& e1, const Interval& low = Interval(0),
                                                   const Interval& high = Interval(1)) {
  const auto length = [](const Interval& x, const Interval& y) { return sqrt(x * x + y * y); };
  const Interval wx = e1[0] - e0[0], wy = e1[1] - e0[1], vx = from[0] - e0[0], vy = from[1] - e0[1];
  const auto distanceAt = [&](const Interval& lambda) { return length(vx - lambda * wx, vy - lambda * wy); };
  const Interval toLow = distanceAt(low), toHigh = distanceAt(high);
  const Interval squaredLength = wx * wx + wy * wy;
  SegmentDistanceBounds bounds{0, std::min(toLow.upper(), toHigh.upper()), low.midpoint()};
  if (squaredLength.lower() > 0) {
    const Interval foot = (vx * wx + vy * wy) / squaredLength;
    const Interval cross = vx * wy - vy * wx;
    const Interval toLine = sqrt(cross * cross / squaredLength);
    if (foot.upper() < low.lower()) {
      bounds.lower = toLow.lower();
    } else if (foot.lower() > high.upper()) {
      bounds.lower = toHigh.lower();
    } else {
      bounds.lower = toLine.lower();
    }
    if (foot.lower() >= low.upper() && foot.upper() <= high.lower())
      bounds.upper = std::min(bounds.upper, toLine.upper());
    bounds.nearestLambda = std::clamp(foot.midpoint(), low.midpoint(), std::max(low.midpoint(), high.midpoint()));
  } else {
    // A segment shrunk to (nearly) a point: every point of it is that near its end.
    bounds.lower = std::min(toLow.lower(), toHigh.lower()) - sqrt(squaredLength).upper();
  }
  bounds.lower = std::max(bounds.lower, 0.0);
  return bounds;
}

}  // namespace freespace
