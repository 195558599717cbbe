#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "freespace/numbers/interval.h"
#include "freespace/numbers/rational.h"
#include "freespace/topology/arrangement.h"

namespace freespace {

/// The point of the free space's boundary nearest to a point of the slice at a fixed
/// angle (docs/design.md section 7, clearance).
struct BoundaryDistance {
  /// The distance: the exact one lies in it.
  Interval distance;
  /// The sub-face whose piece of segment holds the nearest point (one of them when
  /// several are equally near, within the interval's width).
  SubFaceId face;
  /// The nearest point, rounded to doubles.
  std::array<double, 2> nearest{};
  /// The side of that sub-face's segment the point lies on (true: positive), when
  /// every other piece is certainly farther and the side certain: no point of the
  /// boundary lies on the way to the nearest point (it would be nearer), so that
  /// sub-face is the first the way meets, from that side (the nearest point lies
  /// inside its piece: at an end, the piece its loop goes on with would be as near).
  std::optional<bool> fromPositiveSide;
};

/// Distances from points of the slices of an arrangement at rational angles to the
/// boundary of its free space there: the pieces of segments whose sub-faces bound a
/// free cell. Candidates come from the index of the patches' boxes, looked up near
/// the point first, then farther; each piece's distance is bounded in double
/// intervals, and found exactly (rationals, then a square root in intervals) for the
/// pieces that may be nearest when the intervals leave the answer wider than asked.
class SliceBoundaryDistance {
 public:
  /// `boundsFree` tells whether a sub-face bounds a free cell (on its positive side).
  SliceBoundaryDistance(const Arrangement& arrangement, AngleAlgebra& algebra,
                        std::function<bool(SubFaceId)> boundsFree);
  ~SliceBoundaryDistance();
  SliceBoundaryDistance(const SliceBoundaryDistance&) = delete;
  SliceBoundaryDistance& operator=(const SliceBoundaryDistance&) = delete;

  /// The nearest point of the boundary at a rational angle (AlgebraicAngle::isRational)
  /// from `from`, with a distance interval whose width is at most `relativeWidth`
  /// times its upper end where exact arithmetic can make it so; nothing when the
  /// slice has no boundary. The pieces are looked for a little beyond `searchRadius`
  /// of `from` first, then four times as far, and so on: a hint that changes no
  /// answer, only how many pieces are looked at (fewest when it is about the distance
  /// or above it); by default, from a radius of the index's typical patch width.
  std::optional<BoundaryDistance> nearest(const AlgebraicAngle& rationalAngle, const std::array<Rational, 2>& from,
                                          double relativeWidth = 1e-13, double searchRadius = HUGE_VAL) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace freespace
