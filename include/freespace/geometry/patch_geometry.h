#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "freespace/geometry/patch.h"
#include "freespace/geometry/patch_segment.h"

namespace freespace {

/// A patch with its segment and, by value, the input points of its line and of its
/// two end spirals: everything the later stages evaluate, independent of the meshes.
struct PatchGeometry {
  Patch patch;
  PatchSegment segment;
  ContactPoints line;
  std::array<SpiralPoints, 2> ends;
};

std::vector<PatchGeometry> patchGeometries(const std::vector<Patch>& patches, const Mesh& robot,
                                           const MeshTopology& robotTopology, const Mesh& world,
                                           const MeshTopology& worldTopology, PredicateStatistics& statistics,
                                           const Cancellation& cancellation = {});

/// An axis-aligned box in (x, y, theta), theta in radians in [-pi, pi].
struct PatchBox {
  double low[3];
  double high[3];
};

/// Boxes that contain the patch's segment at every angle of its range (one per arc,
/// two for an arc through theta = pi; each arc taken from the outer ends of its
/// angles' enclosures), computed in doubles and padded so that they contain the
/// exact segments with a wide margin over rounding. With `maxWidth`, each arc is cut
/// into equal pieces at most that many radians wide, one box each: tighter boxes.
std::vector<PatchBox> patchBoxes(const PatchGeometry& patch, double maxWidth = HUGE_VAL);

}  // namespace freespace
