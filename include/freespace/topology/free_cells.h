#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "freespace/topology/shell_classification.h"

namespace freespace {

/// The free cells (docs/design.md section 6, step 5): the free closed shells nested into
/// cells by rays at fixed angles. Cell 0 is the unbounded cell, where the robot is
/// far from the environment; the others are numbered 1, 2, ...
///
/// Nesting. For a shell S and a set A_S of rational angles, let p be the leftmost
/// point (least x, then y) of the slices of S at the angles of A_S. A point just left
/// of p lies outside S; when it sees S from S's free side, S is a hole in its cell,
/// and the ray from it toward -x stays in the cell up to the first sub-face it meets,
/// of a shell S' of the same cell (or meets nothing: the unbounded cell). The point
/// met lies left of p, at an angle that is then added to A_S', so that the leftmost
/// point of S' lies left of p too. Repeated until no set grows, every hole's ray leads
/// to a shell with a leftmost point further left, so every hole of a cell is joined
/// to the cell's outer shell (the one whose free side faces +x at its leftmost
/// point) or to the unbounded cell. theta is circular throughout: cells meeting at
/// theta = +-pi are one.
class FreeCells {
 public:
  FreeCells(const Arrangement& arrangement, const SliceRays& rays, const std::vector<ShellSide>& sides,
            AngleAlgebra& algebra, const Cancellation& cancellation = {});
  /// Cells as found before (read back from a saved free space).
  FreeCells(std::vector<std::optional<std::uint32_t>> cellOfShell, std::size_t count)
      : cellOfShell_(std::move(cellOfShell)), count_(count) {}

  /// The number of free cells, the unbounded one included.
  std::size_t count() const { return count_; }
  /// The cell a free closed shell bounds; none for other shells.
  std::optional<std::uint32_t> cellOfShell(std::uint32_t shell) const;
  static constexpr std::uint32_t kUnbounded = 0;

 private:
  std::vector<std::optional<std::uint32_t>> cellOfShell_;
  std::size_t count_ = 0;
};

}  // namespace freespace
