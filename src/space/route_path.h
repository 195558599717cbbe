#pragma once

#include <optional>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/space/free_space.h"

namespace freespace {

/// A path between two free configurations of one cell along the cell graph's route of
/// nodes (docs/design.md section 7): in each node, turns at fixed (x, y) by steps of
/// half the clearance's allowance, each followed by translations (FaceTriangulation)
/// to the roomiest part of the node's face at the new angle; across each edge of the
/// route, a turn through its critical angle at a point of both faces. None when a step
/// fails (the caller certifies the motions; this only builds them).
std::optional<std::vector<Pose2>> routePath(const FreeSpace& space, const Pose2& from, const Pose2& to,
                                            const Cancellation& cancellation = {});

}  // namespace freespace
