#pragma once

// The exact slice of a patch at a rational angle, and the piece of its segment that
// one of its sub-faces covers there.

#include <array>
#include <utility>

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

/// Where the line of `other` crosses the segment, as lambda from end 0.
inline Rational crossingLambda(const ExactSegment& segment, const ExactSegment& other) {
  const Rational v0 = other.valueAt(segment.end0), v1 = other.valueAt(segment.end1);
  return v0 / (v0 - v1);
}

/// The first and last lambda of the sub-face at index `gap` of `slab` (a slab of
/// `patch` holding the angle of `segment`).
inline std::pair<Rational, Rational> pieceOf(const Arrangement& arrangement, std::uint32_t patch,
                                             const PatchSlab& slab, std::size_t gap, const ExactSegment& segment,
                                             const Rational& cosine, const Rational& sine) {
  const auto lambdaOf = [&](std::uint32_t curve) {
    return crossingLambda(segment, segmentAt(arrangement.patches[arrangement.curves[curve].other(patch)], cosine, sine));
  };
  return {gap == 0 ? Rational(0) : lambdaOf(slab.curves[gap - 1]),
          gap == slab.curves.size() ? Rational(1) : lambdaOf(slab.curves[gap])};
}

}  // namespace freespace::slices
