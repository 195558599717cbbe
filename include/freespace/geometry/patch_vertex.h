#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "freespace/geometry/patch_curve.h"
#include "freespace/geometry/patch_geometry.h"

namespace freespace {

/// Where three patches meet (DESIGN.md section 4, FFF): an angle at which the three
/// patch lines are concurrent at a point inside the three segments. The point is
/// where two curves of one patch cross in that patch's domain, and it lies on the
/// third curve of the three patches.
struct PatchVertex {
  /// The three patches, in increasing order.
  std::array<std::uint32_t, 3> patches{};
  AlgebraicAngle angle;
};

/// The FFF polynomial of three patch lines as an angle function: the determinant
/// det[n_i, w_i] of the lines (threePatchPolynomial), zero where they are concurrent.
std::shared_ptr<const AngleFunction> threePatchFunction(const ContactPoints& a, const ContactPoints& b,
                                                        const ContactPoints& c);

/// Every vertex: for three patches that pairwise have curves, the roots of their FFF
/// polynomial inside the three curves' open angle sets (a root at a curve's end is
/// where that curve ends, not a vertex of this kind). Inside a curve's angle set the
/// two segments cross at one point inside both, so at such a root the three
/// crossings are one point inside the three segments. Triples whose FFF determinant
/// has a certain sign in double intervals over the curves' common angles are
/// rejected before any root is isolated. Sorted by patches, then by angle.
std::vector<PatchVertex> patchVertices(const std::vector<PatchGeometry>& patches,
                                       const std::vector<PatchCurve>& curves, AngleAlgebra& algebra);

}  // namespace freespace
