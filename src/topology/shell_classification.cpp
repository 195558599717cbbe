#include "freespace/topology/shell_classification.h"

#include <cmath>
#include <stdexcept>

#include "slice_pieces.h"

namespace freespace {

namespace {

using slices::Point;

std::optional<SubFaceProbe> probeInSlab(const Arrangement& arrangement, const SliceRays& rays, SubFaceId face,
                                        const PatchSlab& slab, std::size_t gap) {
  const AlgebraicAngle& sample = slab.sample;
  if (sample.lower() != sample.upper()) return std::nullopt;  // not a double parameter
  const auto [cosine, sine] = exactCosSin(sample);
  const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[face.patch], cosine, sine);
  if (segment.nx == 0) return std::nullopt;
  const auto [low, high] = slices::pieceOf(arrangement, face.patch, slab, gap, segment, cosine, sine);
  const Point middle = segment.at((low + high) / 2);
  const double x = middle[0].convert_to<double>(), y = middle[1].convert_to<double>();
  const int toward = segment.nx > 0 ? 1 : -1;  // the positive side along x
  for (double distance = std::ldexp(1 + std::fabs(x), -8); distance > std::ldexp(1 + std::fabs(x), -48);
       distance /= 2) {
    const SubFaceProbe probe{{sample.chart(), sample.lower()}, x + toward * distance, y};
    const RayHit hit = rays.cast(sample, {Rational(probe.x), Rational(probe.y)}, -toward);
    if (hit.kind == RayHit::Kind::SubFace && hit.face == face && hit.fromPositiveSide) return probe;
  }
  return std::nullopt;
}

}  // namespace

std::optional<SubFaceProbe> probeSubFace(const Arrangement& arrangement, const SliceRays& rays, SubFaceId face,
                                         AngleAlgebra&) {
  for (const PatchSlab& slab : arrangement.subdivisions[face.patch].slabs) {
    for (std::size_t gap = 0; gap < slab.faces.size(); ++gap) {
      if (slab.faces[gap] != face.face) continue;
      if (auto probe = probeInSlab(arrangement, rays, face, slab, gap)) return probe;
    }
  }
  return std::nullopt;
}

std::vector<ShellSide> classifyShells(const Arrangement& arrangement, const SliceRays& rays,
                                      const ExactCollisionChecker& collision, AngleAlgebra& algebra) {
  const Shells& shells = arrangement.shells;
  std::vector<ShellSide> sides(shells.count(), ShellSide::Open);
  std::vector<bool> decided(shells.count(), false);
  for (std::uint32_t patch = 0; patch < arrangement.subdivisions.size(); ++patch) {
    for (std::uint32_t index = 0; index < arrangement.subdivisions[patch].faceCount; ++index) {
      const SubFaceId face{patch, index};
      const std::uint32_t shell = shells.shellOf(face);
      if (decided[shell] || !shells.closed(shell)) continue;
      const std::optional<SubFaceProbe> probe = probeSubFace(arrangement, rays, face, algebra);
      if (!probe) continue;
      sides[shell] = collision.inCollision(probe->angle, probe->x, probe->y) ? ShellSide::Blocked : ShellSide::Free;
      decided[shell] = true;
    }
  }
  for (std::uint32_t shell = 0; shell < shells.count(); ++shell) {
    if (shells.closed(shell) && !decided[shell]) throw std::runtime_error("classifyShells: a shell could not be probed");
  }
  return sides;
}

}  // namespace freespace
