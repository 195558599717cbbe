#pragma once

#include <cstdint>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/geometry/patch_curve.h"
#include "freespace/geometry/patch_geometry.h"
#include "freespace/geometry/patch_vertex.h"

namespace freespace {

/// A slab of a patch's domain (docs/design.md section 6, step 5): the open angles between
/// two consecutive events of the patch, where the same curves cross the patch's
/// segment in the same order. The domain of a patch is (theta, lambda), lambda in
/// [0, 1] running along the segment from its end 0 to its end 1.
struct PatchSlab {
  AlgebraicAngle from;
  AlgebraicAngle to;
  /// A rational angle strictly inside. A whole circle from an event back to it has
  /// `from` equal to `to`; a whole circle without events has all three equal.
  AlgebraicAngle sample;
  /// The curves that cross the segment in the slab, by increasing lambda.
  std::vector<std::uint32_t> curves;
  /// The sub-face of each gap between curves: faces[i] lies below curves[i] (and
  /// above curves[i - 1]); curves.size() + 1 entries.
  std::vector<std::uint32_t> faces;
};

/// A patch split by its curves into sub-faces, numbered 0 .. faceCount - 1, as a
/// list of slabs (trapezoids glued across the events between slabs). Slabs follow
/// each arc of the patch's range counterclockwise, arc after arc.
struct PatchSubdivision {
  std::vector<PatchSlab> slabs;
  std::uint32_t faceCount = 0;
};

/// The order along `patch`'s segment of its crossings with the lines of `first` and
/// `second` at a rational angle where both cross the segment: Positive when
/// `first`'s crossing is nearer end 0.
Sign crossingOrder(const PatchGeometry& patch, const PatchGeometry& first, const PatchGeometry& second,
                   const AlgebraicAngle& rationalAngle, AngleAlgebra& algebra);

/// The side of `other`'s line that end k of `patch`'s segment lies on, at a rational
/// angle (the sign of the SF value there).
Sign sideOfEnd(const PatchGeometry& patch, int k, const PatchGeometry& other, const AlgebraicAngle& rationalAngle,
               AngleAlgebra& algebra);

/// The subdivision of every patch. The events of a patch are the ends of its range's
/// arcs, the ends of its curves' arcs, its vertices and its overlaps. Between two
/// events the crossing order of the curves is constant (it changes only at
/// vertices), so each gap between consecutive curves is a trapezoid. Across the
/// events at one angle, a trapezoid continues in the next slab's trapezoids whose
/// sides at that angle share an open piece of the segment with its own: the curves'
/// crossings there are ranked exactly along the segment, several curves meeting in
/// one point (a vertex, curves continuing across a spiral or a horizontal edge) and
/// several points at one angle. An overlap is a horizontal cut: the trapezoids along
/// it are not continued. Throws std::logic_error when the events contradict the
/// slab orders (a missing event: a bug).
std::vector<PatchSubdivision> patchSubdivisions(const std::vector<PatchGeometry>& patches,
                                                const std::vector<PatchCurve>& curves,
                                                const std::vector<PatchVertex>& vertices,
                                                const std::vector<PatchOverlap>& overlaps, AngleAlgebra& algebra,
                                                const Cancellation& cancellation = {});

/// The segment of a patch at one of its events inside its range where its slabs
/// join at points (not at an overlap's cut, nor at its range's ends: those lie on
/// horizontal edges): the ranks along the segment there, as patchSubdivisions finds
/// them (0 for end 0 and the curves reaching it, 1, 2, ... for the distinct interior
/// points, `endRank` for end 1 and the curves reaching it), of the curves of the slab
/// before the event and of the slab after it (indices into the subdivision's slabs).
struct PatchEventSlice {
  AlgebraicAngle angle;
  std::size_t before = 0;
  std::size_t after = 0;
  std::vector<int> ranksBefore;  // one per curve of slab `before`, in its order
  std::vector<int> ranksAfter;
  int endRank = 0;
};

/// The slices at the events of every patch (for checks of the arrangement's
/// topology): the subdivision is run again, and its slabs are those of
/// patchSubdivisions.
std::vector<std::vector<PatchEventSlice>> patchEventSlices(const std::vector<PatchGeometry>& patches,
                                                           const std::vector<PatchCurve>& curves,
                                                           const std::vector<PatchVertex>& vertices,
                                                           const std::vector<PatchOverlap>& overlaps,
                                                           AngleAlgebra& algebra);

}  // namespace freespace
