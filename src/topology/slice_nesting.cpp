#include "slice_nesting.h"

#include <stdexcept>

namespace freespace::slices {

namespace {

/// The distances tried from a curve's leftmost point, relative to its size.
const Rational kLargest = powerOfHalf(24);
const Rational kSmallest = powerOfHalf(200);

}  // namespace

LeftmostEnd::LeftmostEnd(const Arrangement& arrangement, const AlgebraicAngle& rationalAngle)
    : arrangement_(arrangement), angle_(rationalAngle), slice_(*IntervalSlice::at(rationalAngle)) {}

void LeftmostEnd::offer(std::uint32_t patch, const PatchSlab& slab, std::size_t gap) {
  const RoundingScope rounding;
  const PatchGeometry& geometry = arrangement_.patches[patch];
  const std::array<Interval, 2> end0 = slice_.end(geometry, 0), end1 = slice_.end(geometry, 1);
  std::array<Interval, 2> x{Interval(-HUGE_VAL, HUGE_VAL), Interval(-HUGE_VAL, HUGE_VAL)};
  if (const auto piece = slice_.pieceOf(arrangement_, patch, slab, gap)) {
    x = {end0[0] + piece->first * (end1[0] - end0[0]), end0[0] + piece->second * (end1[0] - end0[0])};
  }
  offered_.push_back({patch, &slab, gap, {x[0].lower(), x[1].lower()}});
  leftmostX_ = std::min({leftmostX_, x[0].upper(), x[1].upper()});
}

std::optional<Point> LeftmostEnd::exact() const {
  std::optional<Point> best;
  const auto [cosine, sine] = exactCosSin(angle_);
  // Only the ends that may be leftmost are placed exactly (a crossing each).
  for (const Offered& piece : offered_) {
    if (piece.lowestX[0] > leftmostX_ && piece.lowestX[1] > leftmostX_) continue;
    const ExactSegment segment = segmentAt(arrangement_.patches[piece.patch], cosine, sine);
    for (int end : {0, 1}) {
      if (piece.lowestX[end] > leftmostX_) continue;
      const Point point =
          segment.at(pieceEndOf(arrangement_, piece.patch, *piece.slab, piece.gap, end, segment, cosine, sine).value());
      if (!best || leftOf(point, *best)) best = point;
    }
  }
  return best;
}

LeftOfLeftmost lookLeftOf(const SliceRays& rays, const AlgebraicAngle& rationalAngle, const Point& leftmost,
                          const std::function<Outside(const RayHit& towardPlusX)>& seen) {
  const Rational scale = 1 + abs(leftmost[0]) + abs(leftmost[1]);
  const auto near = [&](const Rational& distance, int up) {
    return Point{leftmost[0] - distance, leftmost[1] + up * distance};
  };
  const auto outsideAt = [&](const Point& start) { return seen(rays.cast(rationalAngle, start, +1)); };
  for (Rational distance = scale * kLargest; distance > scale * kSmallest; distance /= 256) {
    for (int up : {1, -1}) {
      const Outside far = outsideAt(near(distance, up));
      const Point start = near(distance / 65536, up);
      if (far == Outside::Unknown || outsideAt(start) != far) continue;
      if (far == Outside::Outer) return {};
      const RayHit hit = rays.cast(rationalAngle, start, -1);
      if (hit.kind == RayHit::Kind::Nothing || hit.kind == RayHit::Kind::SubFace) return {true, hit};
    }
  }
  throw std::runtime_error("no ray could be shot from the leftmost point of a curve of a slice");
}

}  // namespace freespace::slices
