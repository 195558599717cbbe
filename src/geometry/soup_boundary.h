#pragma once

// The boundary of a soup's solid as closed components (soup_complex.h).

#include <cstdint>
#include <utility>
#include <vector>

#include "soup_complex.h"

namespace freespace::detail {

/// A face of the complex between the solid and the outside; `flip` turns it to face
/// the outside.
struct BoundaryFace {
  std::uint32_t face;
  bool flip;
};

/// Two boundary faces that meet across a wedge of solid at their shared edge (lower
/// and higher vertex).
struct BoundaryPairing {
  std::uint32_t first;
  std::uint32_t second;
  std::pair<std::uint32_t, std::uint32_t> edge;
};

/// Adds the boundary faces to solid.boundary as closed edge-manifold components
/// (faces joined by pairings), each with vertices of its own rounded to doubles. Where
/// one component touches itself along an edge (more than two of its faces there), the
/// edge's vertices get a copy per fan of faces around them, and every copy but the
/// first moves by `separation` towards its fan's neighbours, into its own wedge of
/// solid: the pieces then no longer touch (counted in solid.separatedEdges).
void assembleBoundary(const SoupComplex& complex, const std::vector<BoundaryFace>& faces,
                      const std::vector<BoundaryPairing>& pairings, double separation, EnclosedSolid& solid);

}  // namespace freespace::detail
