#pragma once

#include <chrono>
#include <optional>

#include "freespace/geometry/cancellation.h"
#include "freespace/space/free_space.h"
#include "passage.h"

namespace freespace {

/// A passage with its least clearance raised (docs/design.md section 7): its motions
/// cut into parts, the inner waypoints near the least clearance pushed across the path
/// up the clearance's gradient (toward the middle of the passage they are in, at its
/// best angle) while that raises their clearance, every move shorter than the
/// waypoint's clearance (so it stays in its cell), then every motion certified with a
/// bound within 1% of its ends' clearance (the tightest within 0.3%). No waypoint is
/// pushed out of `domain` (the motions between waypoints in it stay in it). None when a
/// motion is not certified free, or not before `deadline`.
std::optional<Passage> raisedPassage(const FreeSpace& space, const MotionChecker& checker, const Passage& passage,
                                     const Domain& domain, std::chrono::steady_clock::time_point deadline,
                                     QueryRate& rate, const Cancellation& cancellation = {});

}  // namespace freespace
