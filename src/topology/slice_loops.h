#pragma once

// The boundary of the free slices over one interval between critical angles, as the
// cell graph's sweep (cell_graph.cpp, face_placement.cpp) and the faces of one slice
// (slice_faces.cpp) see it: its pieces, and how they join into loops.

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include <boost/container/small_vector.hpp>

#include "freespace/topology/cell_graph.h"

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

/// The boundary of the free slices as the sweep goes, kept from interval to interval:
/// which slab of each patch and which pieces are there, each piece's loop (pieces
/// by CellGraph::pieceIndex) and each loop's node.
struct LiveState {
  std::vector<std::int64_t> slabOfPatch;  // -1: none
  std::vector<char> live;
  std::vector<std::uint32_t> loopOf;
  std::vector<std::uint32_t> nodeOfLoop;
  std::uint32_t unboundedNode = 0;
  const std::vector<Piece>* pieceOfIndex = nullptr;

  std::optional<std::uint32_t> slabOf(std::uint32_t patch) const {
    if (slabOfPatch[patch] < 0) return std::nullopt;
    return static_cast<std::uint32_t>(slabOfPatch[patch]);
  }
  std::optional<std::size_t> pieceAt(std::size_t index) const {
    if (!live[index]) return std::nullopt;
    return index;
  }
  const Piece& piece(std::size_t id) const { return (*pieceOfIndex)[id]; }
};

/// Pieces ending at one spiral (a few: as many as the patches that end there).
using SpiralEndPieces = boost::container::small_vector<std::size_t, 8>;

/// The pieces of an IntervalLoops that end at spirals: (spiral, piece), by spiral.
/// Looking a spiral up here is cheaper than trying each patch that ends there.
using SpiralEnds = std::vector<std::pair<std::uint32_t, std::size_t>>;

/// How the free pieces of a slice join into loops (docs/design.md section 7): across
/// a curve, to the free piece of the curve's other patch; at a spiral, to the other
/// piece ending there (the one glued to it around the spiral when more end there).
/// A State (IntervalLoops, LiveState) tells each patch's slab (slabOf), whether a
/// piece by CellGraph::pieceIndex is there (pieceAt) and its pieces by id (piece).
class PieceNeighbours {
 public:
  PieceNeighbours(const Arrangement& arrangement, const CellGraph& numbering);

  /// A piece and its end (0 low, 1 high).
  struct Crossing {
    std::size_t piece;
    int end;
  };

  /// The piece a piece continues into across the curve at its low (0) or high (1)
  /// end: on the curve's other patch, the one side of the curve there that bounds
  /// free space (the other side lies inside this patch's obstacle). None at a spiral.
  template <class State>
  std::optional<std::size_t> curveNeighbour(const State& state, std::size_t id, std::size_t end) const {
    const std::optional<Crossing> crossing = acrossCurve(state, id, end);
    return crossing ? std::optional(crossing->piece) : std::nullopt;
  }

  /// The free pieces of `loops` that end at spirals.
  SpiralEnds spiralEnds(const IntervalLoops& loops) const;

  /// The piece across a piece's low (0) or high (1) end: across a curve, or the one
  /// glued to it around the spiral there; none when that is unclear.
  template <class State>
  std::optional<std::size_t> neighbour(const State& state, std::size_t id, std::size_t end) const {
    const std::optional<Crossing> crossing = across(state, id, end);
    return crossing ? std::optional(crossing->piece) : std::nullopt;
  }

  /// The neighbour across a piece's end (as neighbour()) and the neighbour's end there.
  template <class State>
  std::optional<Crossing> across(const State& state, std::size_t id, std::size_t end) const;
  /// across(), looking the pieces at spirals up in `ends` (spiralEnds(loops)).
  std::optional<Crossing> across(const IntervalLoops& loops, const SpiralEnds& ends, std::size_t id,
                                 std::size_t end) const;

  SubFaceId faceOf(const Piece& piece) const { return {piece.patch, slabOf(piece).faces[piece.gap]}; }
  bool gluedAroundSpiral(const Piece& a, const Piece& b) const;
  const PatchSlab& slabOf(const Piece& piece) const { return arrangement_.subdivisions[piece.patch].slabs[piece.slab]; }

 private:
  /// The number of the spiral at a patch's segment end 0 or 1.
  std::uint32_t spiralOf(std::uint32_t patch, int end) const { return spiralOfEnd_[patch][end]; }
  /// The free pieces that end at a spiral.
  template <class State>
  SpiralEndPieces endPiecesAt(const State& state, std::uint32_t spiral) const;
  /// curveNeighbour, with the neighbour's end on the curve.
  template <class State>
  std::optional<Crossing> acrossCurve(const State& state, std::size_t id, std::size_t end) const;
  /// The piece glued to piece `id` around the spiral at its end, of those ending there.
  template <class State>
  std::optional<Crossing> aroundSpiral(const State& state, std::size_t id, std::uint32_t spiral,
                                       const SpiralEndPieces& ending) const;

  const Arrangement& arrangement_;
  const CellGraph& numbering_;
  std::set<std::pair<std::uint64_t, std::uint64_t>> spiralGlues_;
  std::vector<std::array<std::uint32_t, 2>> spiralOfEnd_;
  std::vector<std::vector<std::pair<std::uint32_t, int>>> patchesAtSpiral_;
};

template <class State>
std::optional<PieceNeighbours::Crossing> PieceNeighbours::acrossCurve(const State& state, std::size_t id,
                                                                      std::size_t end) const {
  const Piece& piece = state.piece(id);
  const PatchSlab& slab = slabOf(piece);
  const std::size_t at = piece.gap + end;
  if (at == 0 || at > slab.curves.size()) return std::nullopt;
  const std::uint32_t curve = slab.curves[at - 1];
  const std::uint32_t other = arrangement_.curves[curve].other(piece.patch);
  const std::optional<std::uint32_t> otherSlab = state.slabOf(other);
  if (!otherSlab) throw std::logic_error("CellGraph: a free piece's curve ends nowhere");
  const auto& curves = arrangement_.subdivisions[other].slabs[*otherSlab].curves;
  const std::size_t crossing = std::find(curves.begin(), curves.end(), curve) - curves.begin();
  // The gap below the curve meets it by its high end, the one above by its low end.
  std::optional<Crossing> next;
  for (const std::size_t gap : {crossing, crossing + 1}) {
    const auto found = state.pieceAt(numbering_.pieceIndex(other, *otherSlab, static_cast<std::uint32_t>(gap)));
    if (!found) continue;
    if (next) throw std::logic_error("CellGraph: both sides of a curve bound free space");
    next = Crossing{*found, gap == crossing ? 1 : 0};
  }
  if (!next) throw std::logic_error("CellGraph: a free piece continues into no free piece across a curve");
  return next;
}

template <class State>
SpiralEndPieces PieceNeighbours::endPiecesAt(const State& state, std::uint32_t spiral) const {
  SpiralEndPieces found;
  for (const auto& [patch, end] : patchesAtSpiral_[spiral]) {
    const std::optional<std::uint32_t> slab = state.slabOf(patch);
    if (!slab) continue;
    const std::size_t gaps = arrangement_.subdivisions[patch].slabs[*slab].faces.size();
    const std::uint32_t gap = end == 0 ? 0 : static_cast<std::uint32_t>(gaps - 1);
    if (const auto piece = state.pieceAt(numbering_.pieceIndex(patch, *slab, gap))) found.push_back(*piece);
  }
  return found;
}

template <class State>
std::optional<PieceNeighbours::Crossing> PieceNeighbours::across(const State& state, std::size_t id,
                                                                 std::size_t end) const {
  if (const std::optional<Crossing> next = acrossCurve(state, id, end)) return next;
  const std::uint32_t spiral = spiralOf(state.piece(id).patch, static_cast<int>(end));
  return aroundSpiral(state, id, spiral, endPiecesAt(state, spiral));
}

template <class State>
std::optional<PieceNeighbours::Crossing> PieceNeighbours::aroundSpiral(const State& state, std::size_t id,
                                                                       std::uint32_t spiral,
                                                                       const SpiralEndPieces& ending) const {
  const Piece& piece = state.piece(id);
  std::optional<std::size_t> found;
  for (std::size_t other : ending) {
    if (other == id) continue;
    if (ending.size() > 2 && !gluedAroundSpiral(piece, state.piece(other))) continue;
    if (found) return std::nullopt;
    found = other;
  }
  if (!found) return std::nullopt;
  // A piece ending at a spiral is its slab's first gap (low end) or last (high end).
  const Piece& other = state.piece(*found);
  return Crossing{*found, other.gap == 0 && spiralOf(other.patch, 0) == spiral ? 0 : 1};
}

}  // namespace freespace::cellgraph
