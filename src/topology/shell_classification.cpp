#include "freespace/topology/shell_classification.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "freespace/topology/slice_pieces.h"

namespace freespace {

namespace {

using slices::Point;

/// The first distance tried from a sub-face, relative to its size.
const Rational kLargest = powerOfHalf(10);
/// The smallest distance tried from a sub-face, relative to its size: from the exact
/// middle of its piece, and from one found in doubles.
const Rational kSmallest = powerOfHalf(200);
const Rational kSmallestInDoubles = powerOfHalf(36);

/// The middle of a sub-face's piece of segment and the line's normal there, at the
/// slab's sample angle.
struct PieceMiddle {
  Point middle;
  Rational nx, ny;
};

/// The middle in doubles: as good as exact for probes well above the rounding (the
/// ray back to the sub-face decides exactly whether a probe is valid).
std::optional<PieceMiddle> middleInDoubles(const Arrangement& arrangement, SubFaceId face, const PatchSlab& slab,
                                           std::size_t gap) {
  const RoundingScope rounding;
  const slices::IntervalSlice slice(slab.sample);
  const PatchGeometry& patch = arrangement.patches[face.patch];
  const auto piece = slice.pieceOf(arrangement, face.patch, slab, gap);
  if (!piece || !(piece->first.upper() < piece->second.lower())) return std::nullopt;
  const double lambda = 0.5 * piece->first.upper() + 0.5 * piece->second.lower();
  const std::array<Interval, 2> middle = slice.pointOn(patch, Interval(lambda));
  const LineAtAngle<Interval> line = slice.line(patch);
  PieceMiddle result;
  for (int axis = 0; axis < 2; ++axis) result.middle[axis] = middle[axis].midpoint();
  result.nx = line.nx.midpoint();
  result.ny = line.ny.midpoint();
  if (result.nx == 0 && result.ny == 0) return std::nullopt;
  return result;
}

PieceMiddle middleExactly(const Arrangement& arrangement, SubFaceId face, const PatchSlab& slab, std::size_t gap) {
  const auto [cosine, sine] = exactCosSin(slab.sample);
  const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[face.patch], cosine, sine);
  const auto [low, high] = slices::pieceOf(arrangement, face.patch, slab, gap, segment, cosine, sine).value();
  return {segment.at((low + high) / 2), segment.nx, segment.ny};
}

/// A probe off the middle along the normal, at distances shrinking from kLargest of
/// the size to `smallest`, until the ray from it across the segment meets the sub-face
/// first, from the probe's side. A ray that meets another segment first tells how
/// near that one is: the next probe is nearer the sub-face than it (or 16 times
/// nearer than the last, if that is nearer still).
std::optional<SubFaceProbe> probeFrom(const PieceMiddle& at, const SliceRays& rays, SubFaceId face,
                                      const PatchSlab& slab, ProbeSide side, const Rational& smallest) {
  const int sign = side == ProbeSide::Positive ? 1 : -1;
  const Point& middle = at.middle;
  const Rational scale = (1 + abs(middle[0]) + abs(middle[1])) / (abs(at.nx) + abs(at.ny));
  for (Rational distance = scale * kLargest; distance > scale * smallest;) {
    const Point off{middle[0] + sign * distance * at.nx, middle[1] + sign * distance * at.ny};
    // Toward the mirror point across the segment, so that the segment is met inside
    // the ray (where double intervals can tell) rather than at its end.
    const Point mirror{2 * middle[0] - off[0], 2 * middle[1] - off[1]};
    const RayHit hit = rays.castTo(slab.sample, off, mirror);
    if (hit.kind == RayHit::Kind::SubFace && hit.face == face && hit.fromPositiveSide == (sign > 0)) {
      const auto [cosine, sine] = exactCosSin(slab.sample);
      return SubFaceProbe{{cosine, sine, off[0], off[1]}};
    }
    // The sub-face is half way to the mirror point: a segment met at a fraction f < 1/2
    // of the way crosses the normal (1 - 2 f) distance from the middle, on the probe's
    // side; the next probe goes half as far.
    Rational next = distance / 16;
    if (hit.kind != RayHit::Kind::Nothing && hit.along > 0 && hit.along < 0.5) {
      next = std::min(next, distance * Rational(0.5 - hit.along));
    }
    distance = next;
  }
  return std::nullopt;
}

/// Where probes are looked for: from middles found in doubles only (cheap, and
/// enough for most sub-faces), from exact middles only (where those in doubles are
/// known to fail), or from both in turn.
enum class ProbeSearch { InDoubles, Exactly, Everywhere };

std::optional<SubFaceProbe> probeInSlab(const Arrangement& arrangement, const SliceRays& rays, SubFaceId face,
                                        const PatchSlab& slab, std::size_t gap, ProbeSide side, ProbeSearch search) {
  if (search != ProbeSearch::Exactly) {
    if (const std::optional<PieceMiddle> middle = middleInDoubles(arrangement, face, slab, gap)) {
      if (auto probe = probeFrom(*middle, rays, face, slab, side, kSmallestInDoubles)) return probe;
    }
  }
  if (search == ProbeSearch::InDoubles) return std::nullopt;
  return probeFrom(middleExactly(arrangement, face, slab, gap), rays, face, slab, side, kSmallest);
}

std::optional<SubFaceProbe> probeSubFace(const Arrangement& arrangement, const SliceRays& rays, SubFaceId face,
                                         ProbeSide side, ProbeSearch search) {
  for (const PatchSlab& slab : arrangement.subdivisions[face.patch].slabs) {
    for (std::size_t gap = 0; gap < slab.faces.size(); ++gap) {
      if (slab.faces[gap] != face.face) continue;
      if (auto probe = probeInSlab(arrangement, rays, face, slab, gap, side, search)) return probe;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<SubFaceProbe> probeSubFace(const Arrangement& arrangement, const SliceRays& rays, SubFaceId face,
                                         ProbeSide side) {
  return probeSubFace(arrangement, rays, face, side, ProbeSearch::Everywhere);
}

std::vector<ShellSide> classifyShells(const Arrangement& arrangement, const SliceRays& rays,
                                      const ExactCollisionChecker& collision, const Cancellation& cancellation) {
  const Shells& shells = arrangement.shells;
  std::vector<ShellSide> sides(shells.count(), ShellSide::Open);
  std::vector<bool> decided(shells.count(), false);
  // Every sub-face of a shell is tried in doubles before any is tried exactly; a
  // shell left undecided had every sub-face tried in doubles, so the second pass
  // tries exact middles only.
  for (const ProbeSearch search : {ProbeSearch::InDoubles, ProbeSearch::Exactly}) {
    for (std::uint32_t patch = 0; patch < arrangement.subdivisions.size(); ++patch) {
      for (std::uint32_t index = 0; index < arrangement.subdivisions[patch].faceCount; ++index) {
        const SubFaceId face{patch, index};
        const std::uint32_t shell = shells.shellOf(face);
        if (decided[shell] || !shells.closed(shell)) continue;
        cancellation.check();
        const std::optional<SubFaceProbe> probe = probeSubFace(arrangement, rays, face, ProbeSide::Positive, search);
        if (!probe) continue;
        sides[shell] = collision.inCollisionAt(probe->pose) ? ShellSide::Blocked : ShellSide::Free;
        decided[shell] = true;
      }
    }
  }
  for (std::uint32_t shell = 0; shell < shells.count(); ++shell) {
    if (shells.closed(shell) && !decided[shell]) throw std::runtime_error("classifyShells: a shell could not be probed");
  }
  return sides;
}

}  // namespace freespace
