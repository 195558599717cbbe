#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "freespace/geometry/patch_curve.h"
#include "freespace/geometry/patch_geometry.h"

namespace freespace {

/// Where three patches meet (docs/design.md section 4, FFF): an angle at which the three
/// patch lines are concurrent at a point inside the three segments. The point is
/// where two curves of one patch cross in that patch's domain. Usually it lies on
/// the third curve, of the other two patches. But two patches of an overlap
/// (PatchOverlap) have no curve: they pass through each other at the angle where
/// their lines coincide, meeting along a horizontal segment, and the vertex is where
/// a third patch crosses them there.
struct PatchVertex {
  /// The three patches, in increasing order.
  std::array<std::uint32_t, 3> patches{};
  AlgebraicAngle angle;
  /// For two coincident patches (an overlap) and one crossing them: the place of the
  /// crossing one in `patches`; otherwise -1.
  int crossing = -1;
};

/// Two patches passing through each other along a horizontal segment, an edge of
/// the arrangement that is not a curve: at an angle inside both ranges their lines
/// coincide and their segments overlap. Structurally, lines coincide at isolated
/// angles in two ways:
///   - two contacts with one facet, of two vertices of the other body, have the same
///     normal n = R a1 + a2 at every angle, and their lines coincide where their
///     constant terms w agree;
///   - two EE contacts sharing one edge, whose other edges leave one vertex, have
///     one line where the shared edge is parallel to the plane of the other two
///     edges (see patchOverlaps).
struct PatchOverlap {
  /// The two patches, in increasing order.
  std::array<std::uint32_t, 2> patches{};
  AlgebraicAngle angle;
  /// reachesEnd[p][k]: the overlap reaches end k of patch p's segment (the other
  /// segment runs up to it, at a shared end, or beyond it).
  std::array<std::array<bool, 2>, 2> reachesEnd{};
};

/// Every overlap: for each pair of patches whose lines coincide at isolated angles,
/// the roots of their coincidence function inside both open ranges where the
/// segments overlap, decided from the signs there of (e - f) . (f1 - f0) for ends e
/// of one segment and f, f0, f1 of the other. The coincidence function is an EF
/// function of input vertices, keyed as one: for contacts of vertices x, y with a
/// facet of normal n, w_a - w_b = (R (x - y)) . n up to sign; for EE contacts sharing
/// an edge of direction v whose other edges run from x to a and a', det(v, u, u')
/// with u = a - x, u' = a' - x (the two lines "x + d on the plane through the shared
/// edge spanned by v and u" are one when v, u, u' are coplanar), which is (R (u x
/// u')) . v for a shared environment edge. Sorted by patches; one pair's overlaps in
/// the order of AngleAlgebra::roots (by chart, then by t).
std::vector<PatchOverlap> patchOverlaps(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra);

/// The same, with the pairs of patches whose boxes meet given (candidatePatchPairs):
/// only those can overlap.
std::vector<PatchOverlap> patchOverlaps(const std::vector<PatchGeometry>& patches,
                                        const std::vector<std::pair<std::uint32_t, std::uint32_t>>& candidates,
                                        AngleAlgebra& algebra, const Cancellation& cancellation = {});

/// The FFF polynomial of three patch lines as an angle function: the determinant
/// det[n_i, w_i] of the lines (threePatchPolynomial), zero where they are concurrent.
std::shared_ptr<const AngleFunction> threePatchFunction(const ContactPoints& a, const ContactPoints& b,
                                                        const ContactPoints& c);

/// Every vertex. For three patches that pairwise have curves: the roots of their
/// FFF polynomial inside the open angle sets of the curves of one patch with the
/// other two (a root at a curve's end is where that curve ends, not a vertex of
/// this kind). Inside a curve's angle set the two segments cross at one point
/// inside both, so at such a root the three crossings are one point inside the three
/// segments. Triples whose FFF determinant has a certain sign in double intervals
/// over the curves' common angles are rejected before any root is isolated. For an
/// overlap of two patches and a third with curves with both: the overlap's
/// angle, when it is inside both curves' open angle sets. Sorted by patches, then by
/// angle.
std::vector<PatchVertex> patchVertices(const std::vector<PatchGeometry>& patches,
                                       const std::vector<PatchCurve>& curves,
                                       const std::vector<PatchOverlap>& overlaps, AngleAlgebra& algebra,
                                       const Cancellation& cancellation = {});

}  // namespace freespace
