#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "freespace/topology/cell_graph.h"

namespace freespace {

/// A boundary loop of a face of a slice: its corners in order (each segment from one
/// corner to the next is a piece of a patch's segment), in the construction's
/// coordinates, rounded to doubles.
struct SliceLoop {
  std::vector<std::array<double, 2>> corners;
};

/// A face of the slice of the free space at one angle: the node of the cell graph it
/// belongs to, that node's cell, and its boundary loops (none for an unbounded face
/// with nothing in it). A point lies in a bounded face when an odd number of its
/// loops' edges cross a ray from it, in an unbounded one when an even number does.
struct SliceFace {
  std::uint32_t node = 0;
  std::uint32_t cell = 0;
  bool unbounded = false;
  std::vector<SliceLoop> loops;
  /// Every corner lies within this distance of the exact corner it rounds (infinite
  /// when intervals could not place one): the loops are the slice's boundary up to it.
  double cornerError = 0;
};

namespace cellgraph {
class PieceNeighbours;
struct IntervalLoops;
}  // namespace cellgraph

/// The faces of the free space's slices: the free pieces at an angle joined into
/// loops (slice_loops' PieceNeighbours, made once for every slice asked for), each
/// loop given the node the graph keeps for its pieces.
class SliceFaces {
 public:
  /// `algebra` places the slabs' ends among the graph's critical angles (once, here).
  SliceFaces(const Arrangement& arrangement, const CellGraph& graph, CellGraph::CellOfFace cellOf,
             AngleAlgebra& algebra);
  ~SliceFaces();
  SliceFaces(const SliceFaces&) = delete;
  SliceFaces& operator=(const SliceFaces&) = delete;

  /// The faces of the slice at a rational angle that is not critical (CellGraph).
  /// Throws std::invalid_argument for a critical angle.
  std::vector<SliceFace> at(const AlgebraicAngle& rationalAngle, AngleAlgebra& algebra) const;

  /// The face of one node in that slice (the same as at()'s, from the pieces of that
  /// node alone: a loop's pieces all bound one face); none when the node's run of
  /// intervals does not hold the angle. Throws std::invalid_argument for a critical
  /// angle.
  std::optional<SliceFace> faceOf(std::uint32_t node, const AlgebraicAngle& rationalAngle, AngleAlgebra& algebra) const;

 private:
  /// A free piece: (patch, slab, gap).
  using PieceId = std::array<std::uint32_t, 3>;
  /// A piece bounding a node's face over the intervals firstInterval .. lastInterval.
  struct NodePiece {
    PieceId piece;
    std::uint32_t firstInterval;
    std::uint32_t lastInterval;
  };

  /// Tables a free piece for the nodes whose faces it bounds over its slab's intervals
  /// (runs of them that do not wrap around: first, last).
  void tablePiece(const PieceId& piece, const std::vector<std::array<std::uint32_t, 2>>& slabIntervals);
  /// The faces the pieces' loops bound at their angle (in `interval`), by node; the
  /// unbounded node's (empty) among them when the interval has one.
  std::map<std::uint32_t, SliceFace> facesOf(const cellgraph::IntervalLoops& loops, std::uint32_t interval) const;

  const Arrangement& arrangement_;
  const CellGraph& graph_;
  CellGraph::CellOfFace cellOf_;
  std::unique_ptr<const cellgraph::PieceNeighbours> neighbours_;
  /// The pieces that bound each node's face, with the intervals over which they do
  /// (the face at an angle is made of those whose intervals hold the angle's: no
  /// search of slabs by angle), node by node, by CellGraph::pieceIndex.
  std::vector<std::vector<NodePiece>> piecesOfNode_;
};

}  // namespace freespace
