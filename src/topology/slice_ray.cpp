#include "freespace/topology/slice_ray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "freespace/geometry/patch_box_index.h"
#include "freespace/topology/slice_pieces.h"

namespace freespace {

namespace {

using slices::Point;

/// A candidate met by the ray: the patch, where along the ray (signed distance
/// from the start) and where along its segment.
struct Crossing {
  std::uint32_t patch;
  Rational distance;
  Rational lambda;
  bool alongSegment;
};

/// A candidate met by the ray, in double intervals.
struct IntervalMeeting {
  std::uint32_t patch;
  Interval distance;
  Interval lambda;
  bool certain;
};

template <class T>
T enclosing(const Rational& value) {
  if constexpr (std::is_same_v<T, Interval>) {
    return enclosingInterval(value);
  } else {
    return T(value);
  }
}

/// The ray and the angle in the interval number type of a slice (double intervals,
/// or double-doubles where those leave the answer open): a filter before exact
/// crossings. Its results come as double intervals.
template <class Slice>
struct RayIn : Slice {
  using T = typename Slice::Number;
  std::array<T, 2> from, direction;

  RayIn(const Slice& slice, const Point& start, const Point& step) : Slice(slice) {
    for (int axis = 0; axis < 2; ++axis) {
      from[axis] = enclosing<T>(start[axis]);
      direction[axis] = enclosing<T>(step[axis]);
    }
  }

  /// Where along the ray (distance) and along the segment (lambda) the ray meets the
  /// patch's segment; none when it certainly misses it. `certain` when it certainly
  /// meets it at an inner point.
  std::optional<IntervalMeeting> meeting(std::uint32_t patch, const PatchGeometry& geometry, bool bounded) const {
    const std::array<T, 2> end0 = this->end(geometry, 0), end1 = this->end(geometry, 1);
    const T wx = end1[0] - end0[0], wy = end1[1] - end0[1];
    const T ox = end0[0] - from[0], oy = end0[1] - from[1];
    const T denominator = direction[0] * wy - direction[1] * wx;
    const std::optional<Sign> sign = certainSign(denominator);
    if (!sign || *sign == Sign::Zero) return IntervalMeeting{patch, Interval(0, HUGE_VAL), Interval(0, 1), false};
    const Interval s = slices::toInterval((ox * wy - oy * wx) / denominator);
    const Interval lambda = slices::toInterval((ox * direction[1] - oy * direction[0]) / denominator);
    if (s.upper() < 0 || (bounded && s.lower() > 1) || lambda.upper() < 0 || lambda.lower() > 1) return std::nullopt;
    const bool certain = s.lower() > 0 && (!bounded || s.upper() <= 1) && lambda.lower() > 0 && lambda.upper() < 1;
    return IntervalMeeting{patch, s, lambda, certain};
  }

  std::optional<Interval> lambdaOf(const PatchGeometry& segment, const PatchGeometry& other) const {
    const std::optional<T> lambda = this->crossingLambda(segment, other);
    if (!lambda) return std::nullopt;
    return slices::toInterval(*lambda);
  }

  /// The side of a patch's line the start lies on, when certain.
  std::optional<Sign> sideOfStart(const PatchGeometry& patch) const {
    const LineAtAngle<T> at = this->line(patch);
    return certainSign(at.nx * from[0] + at.ny * from[1] + at.w);
  }
};

}  // namespace

struct SliceRays::Impl {
  const Arrangement& arrangement;
  AngleAlgebra& algebra;
  const PatchBoxIndex& index;

  Impl(const Arrangement& a, AngleAlgebra& alg) : arrangement(a), algebra(alg), index(*a.boxIndex) {}

  /// The patches whose boxes meet the box of the ray from `from` along `direction`
  /// up to from + reach direction (to infinity without a reach); the boxes are padded
  /// far beyond the rounding of the query's doubles (see patchBoxes).
  std::vector<std::uint32_t> candidates(const AlgebraicAngle& angle, const Point& from, const Point& direction,
                                        std::optional<double> reach) const {
    const double huge = std::numeric_limits<double>::max();
    std::array<double, 2> low{}, high{};
    for (int axis = 0; axis < 2; ++axis) {
      const double start = nearDouble(from[axis]), step = nearDouble(direction[axis]);
      const double pad = 1e-9 * (1 + std::fabs(start) + std::fabs(step) * reach.value_or(0));
      const double end = reach ? start + *reach * step
                               : (direction[axis] > 0 ? huge : (direction[axis] < 0 ? -huge : start));
      low[axis] = std::min(start, end) - pad;
      high[axis] = std::max(start, end) + pad;
    }
    return index.meetingAt(angle.radians(), low, high);
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
  std::vector<IntervalMeeting> meetings(const AlgebraicAngle& angle, const RayIn<slices::IntervalSlice>& ray,
                                        const Point& from, const Point& direction, bool bounded) const;
  std::vector<IntervalMeeting> meetingsWithin(const AlgebraicAngle& angle, const RayIn<slices::IntervalSlice>& ray,
                                              const Point& from, const Point& direction, bool bounded,
                                              std::optional<double> reach) const;
  template <class Slice>
  std::optional<RayHit> castInIntervals(const AlgebraicAngle& angle, const RayIn<Slice>& ray,
                                        const std::vector<IntervalMeeting>& meetings) const;
  std::optional<RayHit> castInDoubleDoubles(const AlgebraicAngle& angle, const Point& from, const Point& direction,
                                            bool bounded, const std::vector<IntervalMeeting>& meetings) const;
  RayHit castExactly(const AlgebraicAngle& angle, const Point& from, const Point& direction, bool bounded,
                     std::vector<IntervalMeeting> meetings) const;
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
  std::vector<IntervalMeeting> met;
  std::optional<RayHit> hit;
  {
    RoundingScope rounding;
    const RayIn<slices::IntervalSlice> ray(slices::IntervalSlice(rationalAngle), from, direction);
    met = meetings(rationalAngle, ray, from, direction, bounded);
    if (met.empty()) return RayHit{};
    hit = castInIntervals(rationalAngle, ray, met);
  }
  if (!hit) hit = castInDoubleDoubles(rationalAngle, from, direction, bounded, met);
  return hit ? *hit : castExactly(rationalAngle, from, direction, bounded, std::move(met));
}

/// The ray's meetings with every patch that may be its first. An unbounded ray
/// looks near its start first (twice a typical box's width, at least 1/1024 of the
/// boxes' square: PatchBoxIndex::Scales), then four times as far each time: once it certainly meets a segment
/// within the reach, its first meeting is no farther, and every patch that meets it
/// that near has a box meeting the reach's box, so the patches beyond need not be
/// looked at (a ray crosses a floor plan of n rooms past about sqrt(n) of them).
std::vector<IntervalMeeting> SliceRays::Impl::meetings(const AlgebraicAngle& angle,
                                                       const RayIn<slices::IntervalSlice>& ray, const Point& from,
                                                       const Point& direction, bool bounded) const {
  if (!bounded) {
    const PatchBoxIndex::Scales& scales = index.scales();
    for (double reach = std::max(2 * scales.typicalWidth, scales.side / 1024); reach < 4 * scales.side; reach *= 4) {
      std::vector<IntervalMeeting> near = meetingsWithin(angle, ray, from, direction, false, reach);
      if (std::any_of(near.begin(), near.end(),
                      [&](const IntervalMeeting& m) { return m.certain && m.distance.upper() < reach; })) {
        return near;
      }
    }
  }
  return meetingsWithin(angle, ray, from, direction, bounded, bounded ? std::optional<double>(1) : std::nullopt);
}

/// The ray's meetings with the patches whose boxes meet the box of its part up to
/// the reach (all of it without one).
std::vector<IntervalMeeting> SliceRays::Impl::meetingsWithin(const AlgebraicAngle& angle,
                                                             const RayIn<slices::IntervalSlice>& ray,
                                                             const Point& from, const Point& direction, bool bounded,
                                                             std::optional<double> reach) const {
  std::vector<IntervalMeeting> found;
  for (std::uint32_t patch : candidates(angle, from, direction, reach)) {
    const std::optional<IntervalMeeting> meeting = ray.meeting(patch, arrangement.patches[patch], bounded);
    if (meeting && algebra.contains(arrangement.patches[patch].patch.range, angle)) found.push_back(*meeting);
  }
  return found;
}

/// The candidates met again in double-doubles (the segments' ends are often
/// spirals of edges that barely climb, known in double intervals to a fraction of
/// their length only).
std::optional<RayHit> SliceRays::Impl::castInDoubleDoubles(const AlgebraicAngle& angle, const Point& from,
                                                           const Point& direction, bool bounded,
                                                           const std::vector<IntervalMeeting>& meetings) const {
  const std::optional<slices::DoubleDoubleSlice> slice = slices::DoubleDoubleSlice::at(angle);
  if (!slice) return std::nullopt;
  const NearestRoundingScope rounding;
  const RayIn<slices::DoubleDoubleSlice> ray(*slice, from, direction);
  std::vector<IntervalMeeting> again;
  for (const IntervalMeeting& meeting : meetings) {
    if (auto found = ray.meeting(meeting.patch, arrangement.patches[meeting.patch], bounded)) again.push_back(*found);
  }
  if (again.empty()) return RayHit{};
  return castInIntervals(angle, ray, again);
}

/// The hit when double intervals decide it: the nearest meeting is certain and
/// certainly nearer than every other, and its sub-face and side are certain.
template <class Slice>
std::optional<RayHit> SliceRays::Impl::castInIntervals(const AlgebraicAngle& angle, const RayIn<Slice>& ray,
                                                       const std::vector<IntervalMeeting>& meetings) const {
  const auto nearest = std::min_element(meetings.begin(), meetings.end(), [](const auto& a, const auto& b) {
    return a.distance.upper() < b.distance.upper();
  });
  if (!nearest->certain) return std::nullopt;
  for (const IntervalMeeting& other : meetings) {
    if (&other != &*nearest && !(other.distance.lower() > nearest->distance.upper())) return std::nullopt;
  }
  const PatchSlab* slab = slabAt(arrangement.subdivisions[nearest->patch], angle, algebra);
  if (!slab) return std::nullopt;
  const PatchGeometry& patch = arrangement.patches[nearest->patch];
  std::size_t gap = 0;
  for (std::uint32_t curve : slab->curves) {
    const std::optional<Interval> lambda =
        ray.lambdaOf(patch, arrangement.patches[arrangement.curves[curve].other(nearest->patch)]);
    if (!lambda) return std::nullopt;
    if (lambda->upper() < nearest->lambda.lower()) {
      ++gap;
    } else if (!(lambda->lower() > nearest->lambda.upper())) {
      return std::nullopt;
    }
  }
  const std::optional<Sign> side = ray.sideOfStart(patch);
  if (!side || *side == Sign::Zero) return std::nullopt;
  RayHit hit;
  hit.kind = RayHit::Kind::SubFace;
  hit.face = {nearest->patch, slab->faces[gap]};
  hit.slab = static_cast<std::uint32_t>(slab - arrangement.subdivisions[nearest->patch].slabs.data());
  hit.gap = static_cast<std::uint32_t>(gap);
  hit.fromPositiveSide = *side == Sign::Positive;
  hit.along = nearest->distance.midpoint();
  return hit;
}

/// The hit decided exactly: candidates by a lower bound on their distance, nearest
/// first, until the next cannot be nearer than the nearest found.
RayHit SliceRays::Impl::castExactly(const AlgebraicAngle& angle, const Point& from, const Point& direction,
                                    bool bounded, std::vector<IntervalMeeting> meetings) const {
  std::sort(meetings.begin(), meetings.end(),
            [](const auto& a, const auto& b) { return a.distance.lower() < b.distance.lower(); });
  const auto [cosine, sine] = exactCosSin(angle);
  std::optional<Crossing> first;
  bool tie = false;
  for (const IntervalMeeting& meeting : meetings) {
    if (first && Rational(std::max(0.0, meeting.distance.lower())) > first->distance) break;
    const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[meeting.patch], cosine, sine);
    const std::optional<Crossing> found = crossing(meeting.patch, segment.end0, segment.end1, from, direction, bounded);
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
  hit.along = nearDouble(first->distance);
  if (tie || first->alongSegment || first->lambda == 0 || first->lambda == 1) return hit;
  const PatchSlab* slab = slabAt(arrangement.subdivisions[first->patch], angle, algebra);
  if (!slab) return hit;  // the angle is an event of the patch
  const slices::ExactSegment own = slices::segmentAt(arrangement.patches[first->patch], cosine, sine);
  std::size_t gap = 0;
  for (std::uint32_t curve : slab->curves) {
    const std::uint32_t other = arrangement.curves[curve].other(first->patch);
    const Rational lambda =
        slices::crossingLambda(own, slices::segmentAt(arrangement.patches[other], cosine, sine)).value();
    if (lambda == first->lambda) return hit;  // through a curve's crossing
    gap += lambda < first->lambda;
  }
  hit.kind = RayHit::Kind::SubFace;
  hit.face = {first->patch, slab->faces[gap]};
  hit.slab = static_cast<std::uint32_t>(slab - arrangement.subdivisions[first->patch].slabs.data());
  hit.gap = static_cast<std::uint32_t>(gap);
  // The ray arrives from the side of the start.
  hit.fromPositiveSide = own.valueAt(from) > 0;
  return hit;
}

}  // namespace freespace
