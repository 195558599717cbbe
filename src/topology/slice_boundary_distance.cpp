#include "freespace/topology/slice_boundary_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "freespace/geometry/interval_segment_distance.h"
#include "freespace/geometry/patch_box_index.h"
#include "freespace/topology/slice_pieces.h"
#include "gluing_parts.h"

namespace freespace {

namespace {

using slices::Point;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A piece of a patch's segment at the angle whose sub-face bounds free space: the
/// gap `gap` between the curves of one of the patch's slabs there.
struct BoundaryPiece {
  std::uint32_t patch;
  const PatchSlab* slab;
  std::size_t gap;
  /// The angle is one of the patch's events: the piece is a limit of a slab's.
  bool atEvent;
};

/// A piece's distance from the point, bounded, and its point nearest to it (rounded).
struct PieceDistance {
  BoundaryPiece piece;
  Interval distance;
  std::array<double, 2> nearest;
};

/// The distance from `from` to a piece, the part of the segment from e0 to e1 between
/// `low` and `high` (inside a RoundingScope).
PieceDistance distanceToPiece(const BoundaryPiece& piece, const IntervalPoint& e0, const IntervalPoint& e1,
                              const Interval& low, const Interval& high, const IntervalPoint& from) {
  const SegmentDistanceBounds bounds = segmentDistanceBounds(from, e0, e1, low, high);
  const double lambda = bounds.nearestLambda;
  const std::array<double, 2> nearest{e0[0].midpoint() + lambda * (e1[0] - e0[0]).midpoint(),
                                      e0[1].midpoint() + lambda * (e1[1] - e0[1]).midpoint()};
  return {piece, Interval(bounds.lower, bounds.upper), nearest};
}

/// The slabs of a patch whose gaps are the pieces of its segment at the angle: the
/// slab holding it, or at one of the patch's events (`event`) the slabs ending and
/// starting there (the pieces at an event are limits of theirs).
struct SlabsAt {
  std::vector<const PatchSlab*> slabs;
  bool event = false;
};
SlabsAt slabsAt(const PatchSubdivision& subdivision, const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  if (const PatchSlab* slab = slabAt(subdivision, angle, algebra)) return {{slab}, false};
  SlabsAt found{{}, true};
  for (const bool ending : {true, false}) {
    if (const PatchSlab* slab = gluing::slabMeeting(subdivision, angle, ending, algebra)) found.slabs.push_back(slab);
  }
  return found;
}

}  // namespace

struct SliceBoundaryDistance::Impl {
  const Arrangement& arrangement;
  AngleAlgebra& algebra;
  std::function<bool(SubFaceId)> boundsFree;

  /// The pieces of the boundary on patches whose boxes meet the square of half side
  /// `reach` around `from`, with their distance bounds.
  std::vector<PieceDistance> piecesWithin(const AlgebraicAngle& angle, const slices::IntervalSlice& slice,
                                          const Point& from, const IntervalPoint& fromInterval, double reach) const {
    std::array<double, 2> low{}, high{};
    for (int axis = 0; axis < 2; ++axis) {
      const double centre = nearDouble(from[axis]);
      const double pad = 1e-9 * (1 + std::fabs(centre) + reach);
      low[axis] = std::isinf(reach) ? -std::numeric_limits<double>::max() : centre - reach - pad;
      high[axis] = std::isinf(reach) ? std::numeric_limits<double>::max() : centre + reach + pad;
    }
    std::vector<PieceDistance> pieces;
    for (std::uint32_t patch : arrangement.boxIndex->meetingAt(angle.radians(), low, high)) {
      const PatchGeometry& geometry = arrangement.patches[patch];
      if (!algebra.contains(geometry.patch.range, angle)) continue;
      const SlabsAt found = slabsAt(arrangement.subdivisions[patch], angle, algebra);
      for (const PatchSlab* slab : found.slabs) {
        for (std::size_t gap = 0; gap < slab->faces.size(); ++gap) {
          if (!boundsFree({patch, slab->faces[gap]})) continue;
          const RoundingScope rounding;
          // An end that the intervals cannot place: the whole segment bounds the piece from outside.
          const auto ends = slice.pieceOf(arrangement, patch, *slab, gap);
          PieceDistance piece =
              distanceToPiece({patch, slab, gap, found.event}, slice.end(geometry, 0), slice.end(geometry, 1),
                              ends ? ends->first : Interval(0), ends ? ends->second : Interval(1), fromInterval);
          if (!ends) piece.distance = Interval(piece.distance.lower(), kInfinity);
          pieces.push_back(piece);
        }
      }
    }
    return pieces;
  }

  /// The piece's distance exactly (enclosed in a narrow interval); nothing when an
  /// end of the piece is a crossing with a line parallel to the segment.
  std::optional<Interval> exactDistance(const PieceDistance& found, const AlgebraicAngle& angle,
                                        const Point& from) const {
    const auto [cosine, sine] = exactCosSin(angle);
    const std::uint32_t patch = found.piece.patch;
    const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[patch], cosine, sine);
    const auto piece = slices::pieceOf(arrangement, patch, *found.piece.slab, found.piece.gap, segment, cosine, sine);
    if (!piece) return std::nullopt;
    const auto& [low, high] = *piece;
    const Rational wx = segment.end1[0] - segment.end0[0], wy = segment.end1[1] - segment.end0[1];
    const Rational vx = from[0] - segment.end0[0], vy = from[1] - segment.end0[1];
    const Rational squaredLength = wx * wx + wy * wy;
    Rational lambda = low;
    if (squaredLength != 0) lambda = std::max(low, std::min(Rational((vx * wx + vy * wy) / squaredLength), high));
    const Rational dx = vx - lambda * wx, dy = vy - lambda * wy;
    const Rational squaredDistance = dx * dx + dy * dy;
    const RoundingScope rounding;
    return sqrt(enclosingInterval(squaredDistance));
  }

  /// The side of the nearest piece's segment the point lies on (BoundaryDistance::
  /// fromPositiveSide), when every other piece is certainly farther (`pieces` holds
  /// every piece within the nearest one's distance: see nearest()) and the angle is
  /// not an event of the nearest piece's patch (where the rays do not decide either).
  std::optional<bool> sideOfNearest(const std::vector<PieceDistance>& pieces, const PieceDistance& nearest,
                                    const slices::IntervalSlice& slice, const IntervalPoint& from) const {
    if (nearest.piece.atEvent) return std::nullopt;
    for (const PieceDistance& other : pieces) {
      if (&other != &nearest && !(other.distance.lower() > nearest.distance.upper())) return std::nullopt;
    }
    const RoundingScope rounding;
    const LineAtAngle<Interval> line = slice.line(arrangement.patches[nearest.piece.patch]);
    const std::optional<Sign> side = certainSign(line.nx * from[0] + line.ny * from[1] + line.w);
    if (!side || *side == Sign::Zero) return std::nullopt;
    return *side == Sign::Positive;
  }

  /// The nearest of the pieces that may be nearest, exactly where the intervals are
  /// wider than asked.
  BoundaryDistance nearestOf(std::vector<PieceDistance> pieces, const AlgebraicAngle& angle, const Point& from,
                             const slices::IntervalSlice& slice, const IntervalPoint& fromInterval,
                             double relativeWidth) const {
    const auto byUpper = [](const PieceDistance& a, const PieceDistance& b) {
      return a.distance.upper() < b.distance.upper();
    };
    // The distance, the least of the pieces', is at least their least lower bound.
    const auto lowest = [&] {
      return std::min_element(
                 pieces.begin(), pieces.end(),
                 [](const PieceDistance& a, const PieceDistance& b) { return a.distance.lower() < b.distance.lower(); })
          ->distance.lower();
    };
    const double best = std::min_element(pieces.begin(), pieces.end(), byUpper)->distance.upper();
    if (std::isinf(best) || best - lowest() > relativeWidth * best) {
      for (PieceDistance& piece : pieces) {
        if (piece.distance.lower() > best) continue;  // certainly not the nearest
        if (const std::optional<Interval> exact = exactDistance(piece, angle, from)) piece.distance = *exact;
      }
    }
    const PieceDistance& nearest = *std::min_element(pieces.begin(), pieces.end(), byUpper);
    const PatchSlab& slab = *nearest.piece.slab;
    return {Interval(lowest(), nearest.distance.upper()),
            {nearest.piece.patch, slab.faces[nearest.piece.gap]},
            nearest.nearest,
            sideOfNearest(pieces, nearest, slice, fromInterval)};
  }
};

SliceBoundaryDistance::SliceBoundaryDistance(const Arrangement& arrangement, AngleAlgebra& algebra,
                                             std::function<bool(SubFaceId)> boundsFree)
    : impl_(std::make_unique<Impl>(Impl{arrangement, algebra, std::move(boundsFree)})) {}

SliceBoundaryDistance::~SliceBoundaryDistance() = default;

/// Looks near the point first (like the rays of SliceRays: twice a typical box's
/// width, or a little beyond the search radius given when that is nearer, then four
/// times as far each time): once a piece is certainly within the reach, every piece
/// nearer has a box meeting the reach's square, so the first reach changes no answer.
std::optional<BoundaryDistance> SliceBoundaryDistance::nearest(const AlgebraicAngle& rationalAngle, const Point& from,
                                                               double relativeWidth, double searchRadius) const {
  if (!rationalAngle.isRational()) {
    throw std::invalid_argument("SliceBoundaryDistance::nearest: the angle must be rational");
  }
  std::optional<slices::IntervalSlice> slice;
  IntervalPoint fromInterval;
  {
    const RoundingScope rounding;
    slice.emplace(rationalAngle);
    fromInterval = {enclosingInterval(from[0]), enclosingInterval(from[1])};
  }
  const PatchBoxIndex::Scales& scales = impl_->arrangement.boxIndex->scales();
  std::vector<PieceDistance> pieces;
  const double typicalRadius = std::max(2 * scales.typicalWidth, scales.side / 1024);
  // A little beyond the radius given: a piece certainly within it, at about the
  // distance expected, is then found in the first pass.
  const double firstRadius =
      searchRadius > 0 ? std::clamp(1.01 * searchRadius, 1e-3 * typicalRadius, typicalRadius) : typicalRadius;
  for (double reach = firstRadius;; reach *= 4) {
    if (reach >= 4 * scales.side) reach = kInfinity;
    pieces = impl_->piecesWithin(rationalAngle, *slice, from, fromInterval, reach);
    if (std::any_of(pieces.begin(), pieces.end(),
                    [&](const PieceDistance& p) { return p.distance.upper() <= reach; })) {
      break;
    }
    if (std::isinf(reach)) break;
  }
  if (pieces.empty()) return std::nullopt;
  return impl_->nearestOf(std::move(pieces), rationalAngle, from, *slice, fromInterval, relativeWidth);
}

}  // namespace freespace
