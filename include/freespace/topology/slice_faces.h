#pragma once

#include <array>
#include <cstdint>
#include <functional>
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
};

namespace cellgraph {
class PieceNeighbours;
}

/// The faces of the free space's slices: the free pieces at an angle joined into
/// loops (slice_loops' PieceNeighbours, made once for every slice asked for), each
/// loop given the node the graph keeps for its pieces.
class SliceFaces {
 public:
  SliceFaces(const Arrangement& arrangement, const CellGraph& graph, CellGraph::CellOfFace cellOf);
  ~SliceFaces();
  SliceFaces(const SliceFaces&) = delete;
  SliceFaces& operator=(const SliceFaces&) = delete;

  /// The faces of the slice at a rational angle that is not critical (CellGraph).
  /// Throws std::invalid_argument for a critical angle.
  std::vector<SliceFace> at(const AlgebraicAngle& rationalAngle, AngleAlgebra& algebra) const;

 private:
  const Arrangement& arrangement_;
  const CellGraph& graph_;
  CellGraph::CellOfFace cellOf_;
  std::unique_ptr<const cellgraph::PieceNeighbours> neighbours_;
};

}  // namespace freespace
