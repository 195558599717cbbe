#pragma once

#include <chrono>
#include <optional>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/space/free_space.h"

namespace freespace {

/// A routed path's waypoints, and for each motion between consecutive ones the lower
/// bound on its clearance already certified while routing (the turns in place), if any.
struct RoutedPath {
  std::vector<Pose2> waypoints;
  std::vector<std::optional<double>> certified;
};

/// A path between two free configurations of one cell along the cell graph's route of
/// nodes (docs/design.md section 7): in each node, turns at fixed (x, y) by steps of
/// half the clearance's allowance, each followed by a translation (FaceTriangulation)
/// to the middle of the node's face's triangle there; across each edge of the route,
/// a turn through its critical angle at a point of both faces (where no such point is
/// found, the route is planned again without that edge). A long route is cut in parts
/// walked at once, one per core. None when a step fails or `deadline` passes (the
/// caller certifies the motions not certified yet).
std::optional<RoutedPath> routePath(const FreeSpace& space, const Pose2& from, const Pose2& to,
                                    std::chrono::steady_clock::time_point deadline,
                                    const Cancellation& cancellation = {});

/// routePath's walk in parts alone: none where routePath walks the route whole (one
/// core, a route shorter than four nodes a part, no junction found, a part's walk
/// failed). While another call has the helper threads (onEveryThread), the parts are
/// walked one after the other.
std::optional<RoutedPath> routePathInParts(const FreeSpace& space, const Pose2& from, const Pose2& to,
                                           std::chrono::steady_clock::time_point deadline,
                                           const Cancellation& cancellation = {});

}  // namespace freespace
