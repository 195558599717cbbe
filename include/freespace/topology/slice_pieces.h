#pragma once

// The exact slice of a patch at a rational angle, and the piece of its segment that
// one of its sub-faces covers there.

#include <array>
#include <optional>
#include <tuple>
#include <utility>

#include "freespace/numbers/half_angle.h"
#include "freespace/numbers/rational.h"

#include "freespace/topology/arrangement.h"

namespace freespace::slices {

using Point = std::array<Rational, 2>;

/// A patch's segment and line at an angle given by its exact cosine and sine.
struct ExactSegment {
  Point end0, end1;
  Rational nx, ny, w;

  Rational valueAt(const Point& p) const { return nx * p[0] + ny * p[1] + w; }
  Point at(const Rational& lambda) const {
    return {end0[0] + lambda * (end1[0] - end0[0]), end0[1] + lambda * (end1[1] - end0[1])};
  }
};

inline ExactSegment segmentAt(const PatchGeometry& patch, const Rational& cosine, const Rational& sine) {
  const LineAtAngle<Rational> line = lineAtAngle(lineOf<Rational>(patch.line), cosine, sine);
  return {spiralPoint(spiralOf<Rational>(patch.ends[0]), cosine, sine),
          spiralPoint(spiralOf<Rational>(patch.ends[1]), cosine, sine), line.nx, line.ny, line.w};
}

/// Where the line of `other` crosses the segment, as lambda from end 0; nothing when
/// it is parallel to the segment (which a curve's other patch can be only at one of
/// the slab's ends, never inside it).
inline std::optional<Rational> crossingLambda(const ExactSegment& segment, const ExactSegment& other) {
  const Rational v0 = other.valueAt(segment.end0), v1 = other.valueAt(segment.end1);
  if (v0 == v1) return std::nullopt;
  return Rational(v0 / (v0 - v1));
}

/// The lambda of end `end` (0: the first, 1: the last) of the sub-face at index `gap`
/// of `slab` (a slab of `patch` holding the angle of `segment`, or ending or starting
/// there); nothing when it is a crossing with a parallel line (see crossingLambda).
inline std::optional<Rational> pieceEndOf(const Arrangement& arrangement, std::uint32_t patch, const PatchSlab& slab,
                                          std::size_t gap, int end, const ExactSegment& segment, const Rational& cosine,
                                          const Rational& sine) {
  if (end == 0 && gap == 0) return Rational(0);
  if (end == 1 && gap == slab.curves.size()) return Rational(1);
  const std::uint32_t curve = slab.curves[gap + end - 1];
  return crossingLambda(segment, segmentAt(arrangement.patches[arrangement.curves[curve].other(patch)], cosine, sine));
}

/// The first and last lambda of the sub-face (see pieceEndOf); nothing when an end is
/// a crossing with a parallel line.
inline std::optional<std::pair<Rational, Rational>> pieceOf(const Arrangement& arrangement, std::uint32_t patch,
                                                            const PatchSlab& slab, std::size_t gap,
                                                            const ExactSegment& segment, const Rational& cosine,
                                                            const Rational& sine) {
  const std::optional<Rational> low = pieceEndOf(arrangement, patch, slab, gap, 0, segment, cosine, sine);
  const std::optional<Rational> high = pieceEndOf(arrangement, patch, slab, gap, 1, segment, cosine, sine);
  if (!low || !high) return std::nullopt;
  return std::make_pair(*low, *high);
}

/// The slice at an angle in an interval number type T, a filter before the exact
/// one: the angle's cosine and sine enclosed, and the patches' segments and lines
/// there. Use its arithmetic inside a T::Rounding scope.
template <class T>
struct SliceIn {
  using Number = T;
  T cosine, sine;

  std::array<T, 2> end(const PatchGeometry& patch, int k) const {
    return spiralPoint(spiralOf<T>(patch.ends[k]), cosine, sine);
  }

  LineAtAngle<T> line(const PatchGeometry& patch) const { return lineAtAngle(lineOf<T>(patch.line), cosine, sine); }

  /// The point a fraction lambda along a patch's segment, from end 0.
  std::array<T, 2> pointOn(const PatchGeometry& patch, const T& lambda) const {
    const std::array<T, 2> end0 = end(patch, 0), end1 = end(patch, 1);
    return {end0[0] + lambda * (end1[0] - end0[0]), end0[1] + lambda * (end1[1] - end0[1])};
  }

  /// Where another patch's line crosses a patch's segment, as lambda; nothing when
  /// the segment may be parallel to it.
  std::optional<T> crossingLambda(const PatchGeometry& segment, const PatchGeometry& other) const {
    const LineAtAngle<T> at = line(other);
    const auto valueAt = [&](int k) {
      const std::array<T, 2> p = end(segment, k);
      return at.nx * p[0] + at.ny * p[1] + at.w;
    };
    const T v0 = valueAt(0), difference = v0 - valueAt(1);
    const std::optional<Sign> sign = certainSign(difference);
    if (!sign || *sign == Sign::Zero) return std::nullopt;
    return v0 / difference;
  }

  /// pieceOf in intervals; nothing when a crossing is uncertain.
  std::optional<std::pair<T, T>> pieceOf(const Arrangement& arrangement, std::uint32_t patch, const PatchSlab& slab,
                                         std::size_t gap) const {
    const auto lambdaOf = [&](std::uint32_t curve) {
      return crossingLambda(arrangement.patches[patch], arrangement.patches[arrangement.curves[curve].other(patch)]);
    };
    const std::optional<T> low = gap == 0 ? T(0) : lambdaOf(slab.curves[gap - 1]);
    const std::optional<T> high = gap == slab.curves.size() ? T(1) : lambdaOf(slab.curves[gap]);
    if (!low || !high) return std::nullopt;
    return std::make_pair(*low, *high);
  }

  /// The ends of the piece at index `gap` of `slab` (low lambda, then high); the
  /// segment's ends when a crossing is uncertain (they hold the piece).
  std::array<std::array<T, 2>, 2> pieceEnds(const Arrangement& arrangement, std::uint32_t patch,
                                            const PatchSlab& slab, std::size_t gap) const {
    const PatchGeometry& geometry = arrangement.patches[patch];
    const std::array<T, 2> end0 = end(geometry, 0), end1 = end(geometry, 1);
    const auto lambdas = pieceOf(arrangement, patch, slab, gap);
    const auto at = [&](const T& lambda) {
      return std::array<T, 2>{end0[0] + lambda * (end1[0] - end0[0]), end0[1] + lambda * (end1[1] - end0[1])};
    };
    return {at(lambdas ? lambdas->first : T(0)), at(lambdas ? lambdas->second : T(1))};
  }
};

/// The slice in double intervals (inside a RoundingScope): a rational angle's cosine
/// and sine enclosed, or those of an algebraic angle's enclosure.
struct IntervalSlice : SliceIn<Interval> {
  /// The rounding its arithmetic needs.
  using Rounding = RoundingScope;

  explicit IntervalSlice(const AlgebraicAngle& angle) { std::tie(cosine, sine) = cosSinEnclosure(angle); }
  static std::optional<IntervalSlice> at(const AlgebraicAngle& angle) {
    const RoundingScope rounding;
    return IntervalSlice(angle);
  }
};

/// The slice in double-double intervals (inside a NearestRoundingScope), for what
/// double intervals leave open: the cosine and sine of the angle's parameter t
/// refined to about 2^-100 (doubleDoubleParameter).
struct DoubleDoubleSlice : SliceIn<DoubleDoubleInterval> {
  using Rounding = NearestRoundingScope;

  /// Nothing when t cannot be refined.
  static std::optional<DoubleDoubleSlice> at(const AlgebraicAngle& angle) {
    const std::optional<DoubleDoubleInterval> t = doubleDoubleParameter(angle);
    if (!t) return std::nullopt;
    DoubleDoubleSlice slice;
    std::tie(slice.cosine, slice.sine) = doubleDoubleCosSin(*t, angle.chart());
    return slice;
  }
};

/// The double interval holding a value of either slice's number type.
inline Interval toInterval(const Interval& value) { return value; }
inline Interval toInterval(const DoubleDoubleInterval& value) { return enclosingInterval(value); }

}  // namespace freespace::slices
