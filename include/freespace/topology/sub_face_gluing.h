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
enum class GluedEdge { Curve, Spiral };

/// Two sub-faces whose positive sides face the same region of the arrangement,
/// next to each other across an edge (DESIGN.md section 6, step 5: walking from a
/// sub-face side across an edge to the angularly next side), as seen in the slice at
/// a rational angle `at`.
struct SubFaceGlue {
  SubFaceId first;
  SubFaceId second;
  GluedEdge edge = GluedEdge::Curve;
  AlgebraicAngle at;
};

/// Across every curve of patches f and g: in each slab of f, at its sample angle,
/// the half of f on g's positive side and the half of g on f's positive side bound
/// the one quadrant on both positive sides.
std::vector<SubFaceGlue> glueAcrossCurves(const std::vector<PatchGeometry>& patches,
                                          const std::vector<PatchCurve>& curves,
                                          const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra);

/// Around every spiral shared as a segment end by several patches: in each slab of
/// each of them, at its sample angle, the segments leaving the spiral's point are
/// ordered by direction, and two consecutive ones whose positive sides both face the
/// sector between them are glued there.
std::vector<SubFaceGlue> glueAroundSpirals(const std::vector<PatchGeometry>& patches,
                                           const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra);

/// The slab of `subdivision` whose open angles hold `angle`, if any.
const PatchSlab* slabAt(const PatchSubdivision& subdivision, const AlgebraicAngle& angle, AngleAlgebra& algebra);

}  // namespace freespace
