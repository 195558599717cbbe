#include "freespace/topology/shell_classification.h"

#include <cmath>
#include <stdexcept>

#include "freespace/topology/slice_pieces.h"

namespace freespace {

namespace {

using slices::Point;

/// The smallest distance tried from a sub-face, relative to its size.
const Rational kSmallest = powerOfHalf(200);

std::optional<SubFaceProbe> probeInSlab(const Arrangement& arrangement, const SliceRays& rays, SubFaceId face,
                                        const PatchSlab& slab, std::size_t gap, ProbeSide side) {
  const int sign = side == ProbeSide::Positive ? 1 : -1;
  const AlgebraicAngle& sample = slab.sample;
  const auto [cosine, sine] = exactCosSin(sample);
  const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[face.patch], cosine, sine);
  const auto [low, high] = slices::pieceOf(arrangement, face.patch, slab, gap, segment, cosine, sine);
  const Point middle = segment.at((low + high) / 2);
  const Rational scale = (1 + abs(middle[0]) + abs(middle[1])) / (abs(segment.nx) + abs(segment.ny));
  for (Rational distance = scale / 1024; distance > scale * kSmallest; distance /= 16) {
    const Point off{middle[0] + sign * distance * segment.nx, middle[1] + sign * distance * segment.ny};
    // Toward the mirror point across the segment, so that the segment is met inside
    // the ray (where double intervals can tell) rather than at its end.
    const Point mirror{2 * middle[0] - off[0], 2 * middle[1] - off[1]};
    const RayHit hit = rays.castTo(sample, off, mirror);
    if (hit.kind == RayHit::Kind::SubFace && hit.face == face && hit.fromPositiveSide == (sign > 0)) {
      return SubFaceProbe{{cosine, sine, off[0], off[1]}};
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<SubFaceProbe> probeSubFace(const Arrangement& arrangement, const SliceRays& rays, SubFaceId face,
                                         ProbeSide side) {
  for (const PatchSlab& slab : arrangement.subdivisions[face.patch].slabs) {
    for (std::size_t gap = 0; gap < slab.faces.size(); ++gap) {
      if (slab.faces[gap] != face.face) continue;
      if (auto probe = probeInSlab(arrangement, rays, face, slab, gap, side)) return probe;
    }
  }
  return std::nullopt;
}

std::vector<ShellSide> classifyShells(const Arrangement& arrangement, const SliceRays& rays,
                                      const ExactCollisionChecker& collision, const Cancellation& cancellation) {
  const Shells& shells = arrangement.shells;
  std::vector<ShellSide> sides(shells.count(), ShellSide::Open);
  std::vector<bool> decided(shells.count(), false);
  for (std::uint32_t patch = 0; patch < arrangement.subdivisions.size(); ++patch) {
    for (std::uint32_t index = 0; index < arrangement.subdivisions[patch].faceCount; ++index) {
      const SubFaceId face{patch, index};
      const std::uint32_t shell = shells.shellOf(face);
      if (decided[shell] || !shells.closed(shell)) continue;
      cancellation.check();
      const std::optional<SubFaceProbe> probe = probeSubFace(arrangement, rays, face);
      if (!probe) continue;
      sides[shell] = collision.inCollisionAt(probe->pose) ? ShellSide::Blocked : ShellSide::Free;
      decided[shell] = true;
    }
  }
  for (std::uint32_t shell = 0; shell < shells.count(); ++shell) {
    if (shells.closed(shell) && !decided[shell]) throw std::runtime_error("classifyShells: a shell could not be probed");
  }
  return sides;
}

}  // namespace freespace
