#pragma once

// Where a face of a slice lies, for the nodes of the cell graph (cell_graph.cpp): a
// point inside it and the box of its outer loop, at the interval's sample angle.

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "freespace/topology/slice_pieces.h"
#include "freespace/topology/slice_ray.h"
#include "slice_loops.h"

namespace freespace::cellgraph {

class FacePlacement {
 public:
  FacePlacement(const Arrangement& arrangement, const SliceRays& rays) : arrangement_(arrangement), rays_(rays) {}

  /// A point left of every patch: in the unbounded face of every slice.
  std::array<double, 2> farPoint() const;
  /// A point of the face the loop made of `members` (pieces of `loops`) bounds.
  std::array<double, 2> pointOff(const IntervalLoops& loops, const std::vector<std::uint32_t>& members) const;
  /// The (x, y) box of the loop made of `members` (low x, low y, high x, high y).
  std::array<double, 4> boxOf(const IntervalLoops& loops, const std::vector<std::uint32_t>& members) const;

 private:
  const PatchSlab& slabOf(const Piece& piece) const;
  std::optional<std::array<double, 2>> pointBeside(const AlgebraicAngle& angle, const Piece& piece,
                                                   const slices::Point& middle, int direction) const;
  std::optional<std::pair<slices::Point, int>> exactMiddle(const AlgebraicAngle& angle, const Piece& piece) const;
  std::optional<std::pair<slices::Point, int>> nearMiddle(const AlgebraicAngle& angle, const Piece& piece) const;

  const Arrangement& arrangement_;
  const SliceRays& rays_;
};

}  // namespace freespace::cellgraph
