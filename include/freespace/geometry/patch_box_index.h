#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "freespace/geometry/patch_geometry.h"

namespace freespace {

/// An R-tree (Boost.Geometry) of the patches' (x, y, theta) boxes (patchBoxes).
class PatchBoxIndex {
 public:
  explicit PatchBoxIndex(const std::vector<PatchGeometry>& patches);
  ~PatchBoxIndex();
  PatchBoxIndex(const PatchBoxIndex&) = delete;
  PatchBoxIndex& operator=(const PatchBoxIndex&) = delete;

  /// Each patch with a box that meets the query box, once, in increasing order.
  std::vector<std::uint32_t> meeting(const PatchBox& query) const;
  /// Every pair of patches (the smaller index first) with boxes that meet, once, in
  /// increasing order.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> meetingPairs() const;
  /// Every box with its patch, patch by patch.
  const std::vector<std::pair<PatchBox, std::uint32_t>>& boxes() const { return boxes_; }

 private:
  struct Tree;
  std::vector<std::pair<PatchBox, std::uint32_t>> boxes_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace freespace
