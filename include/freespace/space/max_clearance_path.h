#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/space/free_space.h"

namespace freespace {

struct MaxClearancePathOptions {
  /// The path's certified bottleneck must reach this fraction of the certified upper
  /// bound on every path's (docs/design.md section 7).
  double clearanceRatio = 0.98;
  /// Paths stay inside x in [low[0], high[0]], y in [low[1], high[1]] (OMPL's state
  /// space bounds); none: inside the bounded cell's box, or around the environment
  /// with room for the robot in the unbounded cell.
  std::optional<std::array<double, 2>> volumeLow, volumeHigh;
  /// Stop refining after this long, or this many boxes, with the bounds reached then
  /// (`converged` false).
  double secondsLimit = 60;
  std::size_t boxLimit = 3'000'000;
  /// Names the start and the goal in errors ("--start", "maze.cfg: start").
  std::string startName = "start", goalName = "goal";
  Cancellation cancellation;
};

/// Certified bounds on a bottleneck: the least clearance along a path.
struct BottleneckBounds {
  double lower = 0, upper = 0;
};

enum class PathStatus {
  /// A path, with its certified bounds.
  solved,
  /// No path: the start and the goal lie in different free cells (startCell and
  /// goalCell are the proof), or no path of their cell stays inside the volume.
  infeasible,
  /// Stopped by the time or box limit before a path was certified.
  unfinished,
};

/// A maximum clearance path query's answer.
struct MaxClearancePath {
  PathStatus status = PathStatus::unfinished;
  /// Why there is no path, in words (infeasible).
  std::string proof;
  std::uint32_t startCell = 0, goalCell = 0;
  /// The path: OMPL's SE(2) motions between consecutive waypoints, each certified
  /// free, with a certified lower bound on the clearance along each.
  std::vector<Pose2> waypoints;
  std::vector<double> motionClearance;
  /// The certified clearances of the start and the goal (lower bounds).
  double startClearance = 0, goalClearance = 0;
  /// Between the first and the last motions (which leave the start and reach the
  /// goal straight away from their nearest contacts, while that raises the
  /// clearance): `lower` is this path's bottleneck there, `upper` bounds every
  /// path's between the same two configurations.
  BottleneckBounds passage;
  /// Along the whole path: `upper` bounds the bottleneck of every path from the
  /// start to the goal.
  BottleneckBounds whole;
  /// passage.lower >= clearanceRatio * passage.upper.
  bool converged = false;
  /// Length in (x, y) and total turn (radians) along the path.
  double length = 0, turn = 0;
  /// Seconds to the first certified path and to the bounds' end.
  double secondsToFirstPath = 0, seconds = 0;
  std::size_t boxes = 0, refinements = 0;
};

/// The maximum clearance path between two configurations of the free space
/// (docs/design.md section 7): no path when their free cells differ; otherwise boxes
/// of configurations with certified clearance bounds are halved along the widest
/// chains until a chain's lower bounds reach clearanceRatio of the widest chain's
/// upper bounds, and the path through that chain is shortened by motions that keep
/// its clearance. A start or goal that is blocked, not finite or outside the volume is
/// an InputError naming it. Throws Cancelled when asked to stop.
MaxClearancePath maxClearancePath(const FreeSpace& space, const Pose2& start, const Pose2& goal,
                                  const MaxClearancePathOptions& options = {});

}  // namespace freespace
