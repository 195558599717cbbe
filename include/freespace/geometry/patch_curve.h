#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "freespace/geometry/patch_geometry.h"

namespace freespace {

/// Where two patches meet (DESIGN.md section 4, FF): the angles at which their
/// segments cross. At each such angle the crossing is one point moving with theta,
/// the intersection of the two lines (Cramer's rule); the curve's ends are SF angles
/// (an end of one segment on the other) or ends of the patches' ranges.
struct PatchCurve {
  std::uint32_t first = 0;
  std::uint32_t second = 0;
  AngleSet angles;
};

/// The closure of the set of angles in both ranges where the two segments cross at
/// a point inside both: each segment's ends lie strictly on opposite sides of the
/// other's line (four SF functions). Empty when the segments share an end (their
/// lines then always meet at it) or their lines coincide.
AngleSet crossingAngles(const PatchGeometry& a, const PatchGeometry& b, AngleAlgebra& algebra);

/// The pairs (i < j) of patches whose boxes (patchBoxes) overlap, each once: a
/// superset of the pairs that cross.
std::vector<std::pair<std::uint32_t, std::uint32_t>> candidatePatchPairs(const std::vector<PatchGeometry>& patches);

/// Every curve: the candidate pairs whose crossing angles are not empty.
std::vector<PatchCurve> patchCurves(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra);

}  // namespace freespace
