#pragma once

#include <cstdint>
#include <vector>

#include "freespace/geometry/patch_subdivision.h"

namespace freespace {

/// A sub-face of a patch (PatchSubdivision), seen from its positive (free) side.
struct SubFaceId {
  std::uint32_t patch = 0;
  std::uint32_t face = 0;

  friend bool operator==(const SubFaceId& a, const SubFaceId& b) { return a.patch == b.patch && a.face == b.face; }
};

/// The edges of the arrangement two sub-faces are glued across.
enum class GluedEdge { Curve, Spiral, Horizontal };

/// Two sub-faces whose positive sides face the same region of the arrangement,
/// next to each other across an edge (docs/design.md section 6, step 5: walking from a
/// sub-face side across an edge to the angularly next side), as seen in the slice at
/// the angle `at`: a rational angle for curves and spirals, the edge's angle for a
/// horizontal edge (the two sub-faces meet along the edge there).
struct SubFaceGlue {
  SubFaceId first;
  SubFaceId second;
  GluedEdge edge = GluedEdge::Curve;
  AlgebraicAngle at;
};

/// The glues found across one kind of edge, and the sub-faces with a side there
/// that nothing continues: a positive side facing another patch's negative side, or
/// no other patch at all. Such a sub-face does not bound a free cell (its positive
/// side is blocked), and its shell is open (docs/design.md section 6, step 5).
struct SubFaceGluing {
  std::vector<SubFaceGlue> glues;
  std::vector<SubFaceId> unmatched;
};

/// Across every curve of patches f and g: in each slab of f, at its sample angle,
/// the half of f on g's positive side and the half of g on f's positive side bound
/// the one quadrant on both positive sides.
SubFaceGluing glueAcrossCurves(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                               const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra,
                               const Cancellation& cancellation = {});

/// Around every spiral shared as a segment end by several patches: in each slab of
/// each of them, at its sample angle, the segments leaving the spiral's point are
/// ordered by direction, and two consecutive ones whose positive sides both face the
/// sector between them are glued there; a positive side facing a sector alone is
/// unmatched (so is the end of a segment at a spiral no other patch ends at).
SubFaceGluing glueAroundSpirals(const std::vector<PatchGeometry>& patches,
                                const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra,
                                const Cancellation& cancellation = {});

/// Across every horizontal edge: the patches whose lines are one line at an angle
/// theta_h (ranges ending or starting at a root of one EF function, and the two
/// patches of an overlap, which run through it) meet there along pieces of that
/// line. In the cross-section of a piece (offset s across the line against theta)
/// each patch is a ray from the edge, down for the slab ending at theta_h, up for the
/// slab starting there, with slope ds/dtheta; around the edge the rays are ordered
/// by slope, and consecutive rays whose positive sides face the sector between them
/// are glued, as around a spiral. Slopes and pieces are read off the exact slices at
/// rational angles within 2^-64 of theta_h on both sides (closer when needed), where
/// the lines of the patches of a side cross a cross-section in the order of their
/// slopes. The pieces lie between named points of the edge (spirals, crossings of
/// other patches' lines, landing points of curves), which must come out in one order
/// on both sides; points read apart there that are one point at theta_h (a spiral on
/// a crossing line, two crossing lines through one point: exact SF and FFF signs at
/// theta_h) are merged.
///
/// Filtered, each edge is first read at theta_h in double intervals: the slopes are
/// the first derivatives in theta of the lines' offsets there, and the named points
/// the spirals, crossings and equal slopes at theta_h; only an edge where some order
/// is uncertain is read exactly. Exact reads every edge exactly (for tests).
enum class EdgeReading { Filtered, Exact };
SubFaceGluing glueAcrossHorizontalEdges(const std::vector<PatchGeometry>& patches,
                                        const std::vector<PatchCurve>& curves,
                                        const std::vector<PatchOverlap>& overlaps,
                                        const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra,
                                        const Cancellation& cancellation = {},
                                        EdgeReading reading = EdgeReading::Filtered);

/// The slab of `subdivision` whose open angles hold `angle`, if any.
const PatchSlab* slabAt(const PatchSubdivision& subdivision, const AlgebraicAngle& angle, AngleAlgebra& algebra);

}  // namespace freespace
