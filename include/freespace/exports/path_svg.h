#pragma once

#include <ostream>

#include "freespace/space/free_space.h"
#include "freespace/space/max_clearance_path.h"

namespace freespace {

/// A maximum clearance path's answer as SVG, in (x, y) with y up: the environment's
/// footprint seen from above (dark where the robot's heights can touch it, light
/// where it lies above or below them), the robot's outline along the path coloured by
/// its certified clearance there (red at 0 to green at the bound on any path's), the
/// path's line, the start and the goal; with a title (the status and the bounds),
/// axes ticked in the meshes' units, and a legend with the colours' scale.
void writePathSvg(const FreeSpace& space, const Pose2& start, const Pose2& goal, const MaxClearancePath& path,
                  std::ostream& out);

}  // namespace freespace
