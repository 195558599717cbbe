#include "freespace/topology/shell_classification.h"

#include <cmath>
#include <stdexcept>

namespace freespace {

namespace {

using Point = std::array<Rational, 2>;

/// The first and last lambda of the sub-face at index `gap` of the slab at its
/// sample angle.
std::pair<Rational, Rational> pieceOf(const Arrangement& arrangement, std::uint32_t patch, const PatchSlab& slab,
                                      std::size_t gap, const Point& end0, const Point& end1, const Rational& cosine,
                                      const Rational& sine) {
  const auto lambdaOf = [&](std::uint32_t curve) {
    const PatchGeometry& other = arrangement.patches[arrangement.curves[curve].other(patch)];
    const LineAtAngle<Rational> line = lineAtAngle(lineOf<Rational>(other.line), cosine, sine);
    const Rational v0 = line.nx * end0[0] + line.ny * end0[1] + line.w;
    const Rational v1 = line.nx * end1[0] + line.ny * end1[1] + line.w;
    return Rational(v0 / (v0 - v1));
  };
  return {gap == 0 ? Rational(0) : lambdaOf(slab.curves[gap - 1]),
          gap == slab.curves.size() ? Rational(1) : lambdaOf(slab.curves[gap])};
}

std::optional<SubFaceProbe> probeInSlab(const Arrangement& arrangement, const SliceRays& rays, SubFaceId face,
                                        const PatchSlab& slab, std::size_t gap) {
  const AlgebraicAngle& sample = slab.sample;
  if (sample.lower() != sample.upper()) return std::nullopt;  // not a double parameter
  const auto [cosine, sine] = exactCosSin(sample);
  const PatchGeometry& patch = arrangement.patches[face.patch];
  const LineAtAngle<Rational> line = lineAtAngle(lineOf<Rational>(patch.line), cosine, sine);
  if (line.nx == 0) return std::nullopt;
  const Point end0 = spiralPoint(spiralOf<Rational>(patch.ends[0]), cosine, sine);
  const Point end1 = spiralPoint(spiralOf<Rational>(patch.ends[1]), cosine, sine);
  const auto [low, high] = pieceOf(arrangement, face.patch, slab, gap, end0, end1, cosine, sine);
  const Rational middle = (low + high) / 2;
  const double x = (end0[0] + middle * (end1[0] - end0[0])).convert_to<double>();
  const double y = (end0[1] + middle * (end1[1] - end0[1])).convert_to<double>();
  const int toward = line.nx > 0 ? 1 : -1;  // the positive side along x
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
