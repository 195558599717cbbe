#pragma once

#include <vector>

#include "freespace/topology/arrangement.h"

namespace freespace {

/// The Euler characteristic of every shell of the arrangement, as a point set (the
/// union of its closed sub-faces), for the topology checks of docs/design.md section 10: a
/// shell bounding a free cell is a closed orientable surface, so its characteristic
/// is even and at most 2.
///
/// Computed by sweeping theta. Let Theta be the angles where any patch's slab begins
/// or ends. The shell S is the disjoint union of its slices at the angles of Theta
/// and of its parts over the open arcs between consecutive angles; each such part is
/// a slice times an open arc (nothing changes inside the arc), and the Euler
/// characteristic with compact supports is additive, with value -1 on an open arc, so
///   chi(S) = sum over theta in Theta of chi(S_theta)
///          - sum over the open arcs of chi(S at a sample inside the arc).
/// Each slice is a graph: the pieces of the patches' segments that the closed
/// sub-faces of S cover there, between the points where curves and segment ends
/// (spirals) cross the segments; chi = points - pieces. A point is named by the
/// curves and spirals through it: at a patch's event, those ranked together along its
/// segment (patchEventSlices) are one point; on a horizontal edge, those at one named
/// point of the edge (its exact reading), where the segments of the patches ending,
/// starting or overlapping there lie on one line and share their pieces.
///
/// Runs the subdivision and the exact reading of the horizontal edges again: meant
/// for checks, not for every build.
std::vector<long> shellEulerCharacteristics(const Arrangement& arrangement, AngleAlgebra& algebra);

}  // namespace freespace
