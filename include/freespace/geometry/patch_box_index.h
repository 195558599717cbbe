#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/geometry/patch_geometry.h"

namespace freespace {

/// The patches' (x, y, theta) boxes (patchBoxes), one per arc of a patch's range, on a
/// uniform (x, y) grid for the pairs that meet, and their boxes over pieces of at most
/// kPieceWidth radians, which follow the segment more closely, on another for queries
/// (the pieces also refine the pairs).
class PatchBoxIndex {
 public:
  explicit PatchBoxIndex(const std::vector<PatchGeometry>& patches, const Cancellation& cancellation = {});
  ~PatchBoxIndex();
  PatchBoxIndex(const PatchBoxIndex&) = delete;
  PatchBoxIndex& operator=(const PatchBoxIndex&) = delete;

  static constexpr double kPieceWidth = M_PI / 8;

  /// Each patch with a box that meets the query box, once, in increasing order.
  std::vector<std::uint32_t> meeting(const PatchBox& query) const;
  /// Each patch with a box that meets the (x, y) box from `low` to `high` at the
  /// angle `theta` (any radians, padded by far more than the error of a rational
  /// angle's radians), once, in increasing order: boxes stop at theta = +-pi, so near
  /// it both sides are looked at.
  std::vector<std::uint32_t> meetingAt(double theta, const std::array<double, 2>& low,
                                       const std::array<double, 2>& high) const;
  /// Every pair of patches (the smaller index first) with boxes that meet, once, in
  /// increasing order.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> meetingPairs(const Cancellation& cancellation = {}) const;
  /// Every box with its patch, patch by patch.
  const std::vector<std::pair<PatchBox, std::uint32_t>>& boxes() const { return boxes_; }

  /// The boxes' scales in x and y: the smallest square [low, low + side]^2 that holds
  /// every box's (x, y) part, and a typical box's width (the median over the boxes of
  /// the larger of their x and y widths). Zero without boxes.
  struct Scales {
    double low = 0, side = 0, typicalWidth = 0;
  };
  const Scales& scales() const { return scales_; }

 private:
  struct Grid;
  /// Whether a box over a piece of the patch meets the query box.
  bool pieceMeets(std::uint32_t patch, const PatchBox& query) const;
  /// Whether boxes over pieces of the two patches meet.
  bool piecesMeet(std::uint32_t first, std::uint32_t second) const;

  std::vector<std::pair<PatchBox, std::uint32_t>> boxes_;
  Scales scales_;
  /// The pieces' boxes, patch by patch: patch i's from firstPiece_[i] to firstPiece_[i + 1],
  /// each patch's sorted by their lowest angle.
  std::vector<PatchBox> pieces_;
  std::vector<std::size_t> firstPiece_;
  /// The largest difference of angles over a piece (a little more).
  double widestPiece_ = 0;
  std::unique_ptr<Grid> grid_;
};

}  // namespace freespace
