#pragma once

#include <cstdint>
#include <vector>

#include "freespace/topology/sub_face_gluing.h"

namespace freespace {

/// The shells of the arrangement (docs/design.md section 6, step 5): the positive sides
/// of the sub-faces, joined across every glue into connected surfaces. A shell is
/// closed when none of its sub-faces has an unmatched side; only closed shells bound
/// free cells.
class Shells {
 public:
  Shells() = default;
  Shells(const std::vector<PatchSubdivision>& subdivisions, const std::vector<const SubFaceGluing*>& gluings);

  std::uint32_t shellOf(SubFaceId face) const { return shellOfFace_[firstFace_[face.patch] + face.face]; }
  std::size_t count() const { return closed_.size(); }
  bool closed(std::uint32_t shell) const { return closed_[shell]; }

 private:
  std::vector<std::uint32_t> firstFace_;
  std::vector<std::uint32_t> shellOfFace_;
  std::vector<bool> closed_;
};

}  // namespace freespace
