#include "face_placement.h"

#include <cmath>
#include <stdexcept>

namespace freespace::cellgraph {

using slices::Point;

const PatchSlab& FacePlacement::slabOf(const Piece& piece) const {
  return arrangement_.subdivisions[piece.patch].slabs[piece.slab];
}

/// A point left of every patch: in the unbounded face of every slice.
std::array<double, 2> FacePlacement::farPoint() const {
  double lowest = 0, highest = 0;
  for (const auto& [box, patch] : arrangement_.boxIndex->boxes()) {
    lowest = std::min({lowest, box.low[0], box.low[1]});
    highest = std::max({highest, box.high[0], box.high[1]});
  }
  return {lowest - (highest - lowest) - 1, 0.0};
}

/// A point of the face a loop bounds: from near the middle of one of its pieces
/// (placed in double intervals, else exactly), half way along x to whatever lies
/// next on the piece's free side, once a ray shows that the start sees that piece
/// first, from its free side.
std::array<double, 2> FacePlacement::pointOff(const IntervalLoops& loops,
                                              const std::vector<std::uint32_t>& members) const {
  for (const bool exact : {false, true}) {
    for (std::uint32_t index : members) {
      const Piece& piece = loops.pieces[index];
      const auto near = exact ? exactMiddle(loops.sample, piece) : nearMiddle(loops.sample, piece);
      if (!near) continue;
      if (const auto point = pointBeside(loops.sample, piece, near->first, near->second)) return *point;
    }
  }
  throw std::runtime_error("CellGraph: no point could be placed inside a face");
}

std::optional<std::array<double, 2>> FacePlacement::pointBeside(const AlgebraicAngle& angle, const Piece& piece,
                                                                const Point& middle, int direction) const {
  const Rational scale = 1 + abs(middle[0]) + abs(middle[1]);
  for (Rational step = scale * powerOfHalf(20); step > scale * powerOfHalf(120); step /= 1024) {
    const Point off{middle[0] + direction * step, middle[1]};
    const Point beyond{middle[0] - direction * step, middle[1]};
    const RayHit back = rays_.castTo(angle, off, beyond);
    if (back.kind != RayHit::Kind::SubFace || !back.fromPositiveSide || back.face.patch != piece.patch ||
        back.slab != piece.slab || back.gap != piece.gap) {
      continue;
    }
    const RayHit ahead = rays_.cast(angle, off, direction);
    const Rational room = ahead.kind == RayHit::Kind::Nothing ? scale : Rational(ahead.along) / 2;
    return std::array<double, 2>{nearDouble(off[0] + direction * room), nearDouble(off[1])};
  }
  return std::nullopt;
}

/// The middle of a piece at a rational angle, exactly, and the direction along x
/// toward its free side; none for a piece along x.
std::optional<std::pair<slices::Point, int>> FacePlacement::exactMiddle(const AlgebraicAngle& angle,
                                                                        const Piece& piece) const {
  const auto [cosine, sine] = exactCosSin(angle);
  const slices::ExactSegment segment = slices::segmentAt(arrangement_.patches[piece.patch], cosine, sine);
  const auto lambdas = slices::pieceOf(arrangement_, piece.patch, slabOf(piece), piece.gap, segment, cosine, sine);
  if (segment.nx == 0 || !lambdas) return std::nullopt;
  return std::pair(segment.at((lambdas->first + lambdas->second) / 2), segment.nx > 0 ? 1 : -1);
}

/// A point near the middle of a piece at a rational angle, and the direction along
/// x toward its free side; none when the doubles cannot tell.
std::optional<std::pair<slices::Point, int>> FacePlacement::nearMiddle(const AlgebraicAngle& angle,
                                                                       const Piece& piece) const {
  const RoundingScope rounding;
  const slices::IntervalSlice slice(angle);
  const PatchGeometry& patch = arrangement_.patches[piece.patch];
  const std::optional<Sign> side = certainSign(slice.line(patch).nx);
  const auto lambdas = slice.pieceOf(arrangement_, piece.patch, slabOf(piece), piece.gap);
  if (!side || *side == Sign::Zero || !lambdas) return std::nullopt;
  const std::array<Interval, 2> middle = slice.pointOn(patch, (lambdas->first + lambdas->second) / Interval(2));
  return std::pair(Point{Rational(middle[0].midpoint()), Rational(middle[1].midpoint())},
                   *side == Sign::Positive ? 1 : -1);
}

std::array<double, 4> FacePlacement::boxOf(const IntervalLoops& loops,
                                           const std::vector<std::uint32_t>& members) const {
  const RoundingScope rounding;
  const slices::IntervalSlice slice(loops.sample);
  std::array<double, 4> box{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::uint32_t index : members) {
    const Piece& piece = loops.pieces[index];
    for (const std::array<Interval, 2>& point : slice.pieceEnds(arrangement_, piece.patch, slabOf(piece), piece.gap)) {
      for (int axis : {0, 1}) {
        box[axis] = std::min(box[axis], point[axis].lower());
        box[axis + 2] = std::max(box[axis + 2], point[axis].upper());
      }
    }
  }
  return box;
}

}  // namespace freespace::cellgraph
