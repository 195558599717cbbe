#pragma once

#include <optional>
#include <vector>

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/topology/slice_ray.h"

namespace freespace {

/// A configuration just off a sub-face on its positive side, exactly: the straight
/// path from it to the sub-face meets no other segment.
struct SubFaceProbe {
  ExactPose pose;
};

enum class ProbeSide { Positive, Negative };

/// A probe of the sub-face at the sample angle of one of its slabs, at the middle of
/// its piece of segment, moved along the line's normal toward its positive (or
/// negative) side by a distance that shrinks until the path back meets the sub-face
/// first, from that side (SliceRays, exact). None when no slab of the sub-face
/// allows it.
std::optional<SubFaceProbe> probeSubFace(const Arrangement& arrangement, const SliceRays& rays, SubFaceId face,
                                         ProbeSide side = ProbeSide::Positive);

enum class ShellSide { Free, Blocked, Open };

/// Each shell: Open when it is not closed, else whether its positive side is free,
/// by one exact collision test at a probe of one of its sub-faces. Throws
/// std::runtime_error when no sub-face of a closed shell can be probed.
std::vector<ShellSide> classifyShells(const Arrangement& arrangement, const SliceRays& rays,
                                      const ExactCollisionChecker& collision, const Cancellation& cancellation = {});

}  // namespace freespace
