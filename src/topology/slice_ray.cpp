#include "freespace/topology/slice_ray.h"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <stdexcept>

#include "slice_pieces.h"

namespace freespace {

namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BoxPoint = bg::model::point<double, 3, bg::cs::cartesian>;
using Box = bg::model::box<BoxPoint>;
using BoxEntry = std::pair<Box, std::uint32_t>;
using slices::Point;

/// Padding of a query's angle: far more than the error of a rational angle's radians.
constexpr double kAnglePad = 1e-9;

/// A candidate met by the ray: the patch, where along the ray (signed distance
/// from the start) and where along its segment.
struct Crossing {
  std::uint32_t patch;
  Rational distance;
  Rational lambda;
  bool alongSegment;
};

}  // namespace

struct SliceRays::Impl {
  const Arrangement& arrangement;
  AngleAlgebra& algebra;
  bgi::rtree<BoxEntry, bgi::rstar<16>> tree;

  Impl(const Arrangement& a, AngleAlgebra& alg) : arrangement(a), algebra(alg) {
    std::vector<BoxEntry> entries;
    for (std::uint32_t i = 0; i < arrangement.patches.size(); ++i) {
      for (const PatchBox& box : patchBoxes(arrangement.patches[i])) {
        entries.emplace_back(Box(BoxPoint(box.low[0], box.low[1], box.low[2]), BoxPoint(box.high[0], box.high[1], box.high[2])), i);
      }
    }
    tree = bgi::rtree<BoxEntry, bgi::rstar<16>>(entries.begin(), entries.end());
  }

  /// The patches whose boxes meet the box of the ray from `from` along `direction`
  /// (as far as `to` when bounded); the boxes are padded far beyond the rounding of
  /// the query's doubles (see patchBoxes).
  std::vector<std::uint32_t> candidates(const AlgebraicAngle& angle, const Point& from, const Point& direction,
                                        bool bounded) const {
    const double theta = std::remainder(angle.radians(), 2 * M_PI);
    const double huge = std::numeric_limits<double>::max();
    double low[2], high[2];
    for (int axis = 0; axis < 2; ++axis) {
      const double start = from[axis].convert_to<double>(), step = direction[axis].convert_to<double>();
      const double pad = 1e-9 * (1 + std::fabs(start) + std::fabs(step));
      const double end = bounded ? start + step : (direction[axis] > 0 ? huge : (direction[axis] < 0 ? -huge : start));
      low[axis] = std::min(start, end) - pad;
      high[axis] = std::max(start, end) + pad;
    }
    std::vector<BoxEntry> found;
    // Boxes stop at theta = +-pi: near it, look on both sides.
    for (const double at : {theta, theta - 2 * M_PI, theta + 2 * M_PI}) {
      if (at < -M_PI - kAnglePad || at > M_PI + kAnglePad) continue;
      const Box query(BoxPoint(low[0], low[1], at - kAnglePad), BoxPoint(high[0], high[1], at + kAnglePad));
      tree.query(bgi::intersects(query), std::back_inserter(found));
    }
    std::vector<std::uint32_t> patches;
    for (const BoxEntry& entry : found) patches.push_back(entry.second);
    std::sort(patches.begin(), patches.end());
    patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
    return patches;
  }

  /// Where the ray from + s direction (s >= 0, and s <= 1 when bounded) meets the
  /// segment from end0 to end1, if it does: s by Cramer's rule on
  /// from + s direction = end0 + lambda (end1 - end0).
  static std::optional<Crossing> crossing(std::uint32_t patch, const Point& end0, const Point& end1, const Point& from,
                                          const Point& direction, bool bounded) {
    const auto cross = [](const Rational& ax, const Rational& ay, const Rational& bx, const Rational& by) {
      return Rational(ax * by - ay * bx);
    };
    const Rational wx = end1[0] - end0[0], wy = end1[1] - end0[1];
    const Rational ox = end0[0] - from[0], oy = end0[1] - from[1];
    const Rational denominator = cross(direction[0], direction[1], wx, wy);
    if (denominator == 0) {
      if (cross(ox, oy, direction[0], direction[1]) != 0) return std::nullopt;  // parallel, apart
      // Along the ray: where the segment's ends are on it.
      const Rational length = direction[0] * direction[0] + direction[1] * direction[1];
      const Rational s0 = (ox * direction[0] + oy * direction[1]) / length;
      const Rational s1 = s0 + (wx * direction[0] + wy * direction[1]) / length;
      const Rational nearest = std::max(Rational(0), std::min(s0, s1));
      if (std::max(s0, s1) < 0 || (bounded && nearest > 1)) return std::nullopt;
      return Crossing{patch, nearest, 0, true};
    }
    const Rational s = cross(ox, oy, wx, wy) / denominator;
    const Rational lambda = cross(ox, oy, direction[0], direction[1]) / denominator;
    if (s < 0 || (bounded && s > 1) || lambda < 0 || lambda > 1) return std::nullopt;
    return Crossing{patch, s, lambda, false};
  }

  RayHit cast(const AlgebraicAngle& angle, const Point& from, const Point& direction, bool bounded) const;
};

/// The ray and the angle in double intervals: a filter before exact crossings.
struct IntervalRay {
  Interval cosine, sine;
  std::array<Interval, 2> from, direction;

  IntervalRay(const AlgebraicAngle& angle, const Point& start, const Point& step) {
    if (angle.lower() == angle.upper()) {
      HalfAngle{angle.chart(), angle.lower()}.cosSin(cosine, sine);
    } else {
      const auto [c, s] = exactCosSin(angle);
      cosine = enclosingInterval(c);
      sine = enclosingInterval(s);
    }
    for (int axis = 0; axis < 2; ++axis) {
      from[axis] = enclosingInterval(start[axis]);
      direction[axis] = enclosingInterval(step[axis]);
    }
  }

  /// A lower bound on where along the ray it meets the patch's segment, or none when
  /// it certainly misses it (inside a RoundingScope).
  std::optional<double> nearestMeeting(const PatchGeometry& patch, bool bounded) const {
    const std::array<Interval, 2> end0 = spiralPoint(spiralOf<Interval>(patch.ends[0]), cosine, sine);
    const std::array<Interval, 2> end1 = spiralPoint(spiralOf<Interval>(patch.ends[1]), cosine, sine);
    const Interval wx = end1[0] - end0[0], wy = end1[1] - end0[1];
    const Interval ox = end0[0] - from[0], oy = end0[1] - from[1];
    const Interval denominator = direction[0] * wy - direction[1] * wx;
    const std::optional<Sign> sign = certainSign(denominator);
    if (!sign || *sign == Sign::Zero) return 0.0;
    const Interval s = (ox * wy - oy * wx) / denominator;
    const Interval lambda = (ox * direction[1] - oy * direction[0]) / denominator;
    if (s.upper() < 0 || (bounded && s.lower() > 1) || lambda.upper() < 0 || lambda.lower() > 1) return std::nullopt;
    return std::max(0.0, s.lower());
  }
};

SliceRays::SliceRays(const Arrangement& arrangement, AngleAlgebra& algebra)
    : impl_(std::make_unique<Impl>(arrangement, algebra)) {}

SliceRays::~SliceRays() = default;

RayHit SliceRays::cast(const AlgebraicAngle& rationalAngle, const Point& from, int direction) const {
  return impl_->cast(rationalAngle, from, {Rational(direction), Rational(0)}, false);
}

RayHit SliceRays::castTo(const AlgebraicAngle& rationalAngle, const Point& from, const Point& to) const {
  return impl_->cast(rationalAngle, from, {to[0] - from[0], to[1] - from[1]}, true);
}

RayHit SliceRays::Impl::cast(const AlgebraicAngle& rationalAngle, const Point& from, const Point& direction,
                             bool bounded) const {
  if (!rationalAngle.isRational()) throw std::invalid_argument("SliceRays::cast: the angle must be rational");
  const auto [cosine, sine] = exactCosSin(rationalAngle);
  // Candidates by a lower bound on their distance, then exactly, nearest first,
  // until the next cannot be nearer than the nearest found.
  std::vector<std::pair<double, std::uint32_t>> byDistance;
  {
    RoundingScope rounding;
    const IntervalRay approximate(rationalAngle, from, direction);
    for (std::uint32_t patch : candidates(rationalAngle, from, direction, bounded)) {
      if (const std::optional<double> low = approximate.nearestMeeting(arrangement.patches[patch], bounded)) {
        byDistance.emplace_back(*low, patch);
      }
    }
  }
  std::sort(byDistance.begin(), byDistance.end());
  std::optional<Crossing> first;
  bool tie = false;
  for (const auto& [low, patch] : byDistance) {
    if (first && Rational(low) > first->distance) break;
    if (!algebra.contains(arrangement.patches[patch].patch.range, rationalAngle)) continue;
    const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[patch], cosine, sine);
    const std::optional<Crossing> found = crossing(patch, segment.end0, segment.end1, from, direction, bounded);
    if (!found) continue;
    if (!first || found->distance < first->distance) {
      first = found;
      tie = false;
    } else if (found->distance == first->distance) {
      tie = true;
    }
  }
  RayHit hit;
  if (!first) return hit;
  if (first->distance == 0) {
    hit.kind = RayHit::Kind::OnSegment;
    return hit;
  }
  hit.kind = RayHit::Kind::Degenerate;
  if (tie || first->alongSegment || first->lambda == 0 || first->lambda == 1) return hit;
  const PatchSlab* slab = slabAt(arrangement.subdivisions[first->patch], rationalAngle, algebra);
  if (!slab) return hit;  // the angle is an event of the patch
  const slices::ExactSegment own = slices::segmentAt(arrangement.patches[first->patch], cosine, sine);
  std::size_t gap = 0;
  for (std::uint32_t curve : slab->curves) {
    const std::uint32_t other = arrangement.curves[curve].other(first->patch);
    const Rational lambda = slices::crossingLambda(own, slices::segmentAt(arrangement.patches[other], cosine, sine));
    if (lambda == first->lambda) return hit;  // through a curve's crossing
    gap += lambda < first->lambda;
  }
  hit.kind = RayHit::Kind::SubFace;
  hit.face = {first->patch, slab->faces[gap]};
  hit.point = {from[0] + first->distance * direction[0], from[1] + first->distance * direction[1]};
  // The ray arrives from the side of the start.
  hit.fromPositiveSide = own.valueAt(from) > 0;
  return hit;
}

}  // namespace freespace
