#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/geometry/patch_geometry.h"

namespace freespace {

/// Why an arc of a curve ends (docs/design.md section 6: a curve's ends are SF points or
/// points on a patch's horizontal boundary); more than one cause only in structural
/// degeneracy. Patch p is 0 for the curve's first patch, 1 for its second.
struct CurveEnd {
  /// endOnOtherLine[p][k]: end k of patch p's segment lies on the other patch's
  /// line. The crossing point reaches p's spiral side there; on the other patch it is
  /// the point where p's end spiral pierces it.
  std::array<std::array<bool, 2>, 2> endOnOtherLine{};
  /// rangeEnd[p]: the angle ends patch p's range; the crossing point reaches p's
  /// horizontal edge.
  std::array<bool, 2> rangeEnd{};

  bool any() const {
    return endOnOtherLine[0][0] || endOnOtherLine[0][1] || endOnOtherLine[1][0] || endOnOtherLine[1][1] ||
           rangeEnd[0] || rangeEnd[1];
  }
};

/// Where two patches meet (docs/design.md section 4, FF): the angles at which their
/// segments cross. At each such angle the crossing is one point moving with theta,
/// the intersection of the two lines (Cramer's rule).
struct PatchCurve {
  std::uint32_t first = 0;
  std::uint32_t second = 0;
  AngleSet angles;
  /// For each arc of `angles`, why it ends at its `from` and at its `to` (nothing
  /// for a full circle).
  std::vector<std::array<CurveEnd, 2>> ends;

  /// The curve's patch that is not `patch` (one of its two).
  std::uint32_t other(std::uint32_t patch) const { return first == patch ? second : first; }
};

/// SF: the line of a patch at a segment end (a spiral) of another patch, as an angle
/// function (docs/design.md section 4). When the spiral's vertex and edge lie in the
/// contact's features, so that the translation cancels, it is an EF function up to a
/// constant factor and carries that EF function's key (docs/design.md section 5:
/// identities from shared input vertices). Otherwise it carries a key of the line's
/// input vertices and the spiral's features, so that the same SF function built for
/// two curves has its roots recognised as one.
std::shared_ptr<const AngleFunction> spiralOnLine(const ContactPoints& line, const SpiralPoints& end,
                                                  const SegmentEnd& endFeatures);

/// The pairs (i < j) of patches whose boxes (patchBoxes) overlap, each once: a
/// superset of the pairs that cross.
std::vector<std::pair<std::uint32_t, std::uint32_t>> candidatePatchPairs(const std::vector<PatchGeometry>& patches);

/// Every curve: the candidate pairs whose crossing angles are not empty. The curve
/// of two patches is the closure of the set of angles in both ranges where their
/// segments cross at a point inside both, i.e. each segment's ends lie strictly on
/// opposite sides of the other's line (four SF functions), with the causes of its
/// arcs' ends; none when the segments share an end (their lines then always meet at
/// it) or their lines coincide. Throws std::logic_error if an arc end has no cause
/// (a bug).
std::vector<PatchCurve> patchCurves(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra,
                                    const Cancellation& cancellation = {});

/// The same from the candidate pairs (candidatePatchPairs), computed once for the
/// curves and the overlaps.
std::vector<PatchCurve> patchCurves(const std::vector<PatchGeometry>& patches,
                                    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& candidates,
                                    AngleAlgebra& algebra, const Cancellation& cancellation = {});

}  // namespace freespace
