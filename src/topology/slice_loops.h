#pragma once

// The boundary of the free slices over one interval between critical angles, as the
// cell graph's sweep sees it (cell_graph.cpp, face_placement.cpp).

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "freespace/numbers/algebraic_angle.h"

namespace freespace::cellgraph {

/// A free piece of the slices' boundary over an interval: a gap of a slab.
struct Piece {
  std::uint32_t patch;
  std::uint32_t slab;
  std::uint32_t gap;
};

/// The boundary of the free slices over one interval: its pieces, the loops they
/// form, and (once known) the node of each loop's face.
struct IntervalLoops {
  std::uint32_t interval = 0;
  AlgebraicAngle sample = AlgebraicAngle::rational(0, 0.0);
  std::vector<Piece> pieces;
  std::vector<std::uint32_t> loopOf;
  std::uint32_t loopCount = 0;
  /// (patch, slab) for each patch with free pieces here, by patch.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> slabs;
  /// CellGraph::pieceIndex of each piece, increasing.
  std::vector<std::size_t> pieceIndices;

  std::optional<std::uint32_t> slabOf(std::uint32_t patch) const {
    const auto found = std::lower_bound(slabs.begin(), slabs.end(), std::pair(patch, std::uint32_t{0}));
    if (found == slabs.end() || found->first != patch) return std::nullopt;
    return found->second;
  }
  /// The piece with a CellGraph::pieceIndex, if it is one here.
  std::optional<std::uint32_t> pieceAt(std::size_t index) const {
    const auto found = std::lower_bound(pieceIndices.begin(), pieceIndices.end(), index);
    if (found == pieceIndices.end() || *found != index) return std::nullopt;
    return static_cast<std::uint32_t>(found - pieceIndices.begin());
  }
  const Piece& piece(std::size_t id) const { return pieces[id]; }
  std::vector<std::uint32_t> nodeOfLoop;
  std::uint32_t unboundedNode = 0;
};

}  // namespace freespace::cellgraph
