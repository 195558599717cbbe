#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "freespace/topology/arrangement.h"

namespace freespace {

/// What a ray in the slice of configuration space at a fixed angle meets first.
struct RayHit {
  enum class Kind {
    /// It meets a sub-face at a point inside its slice's piece of segment.
    SubFace,
    /// It meets nothing.
    Nothing,
    /// It starts on a segment.
    OnSegment,
    /// Its first point on segments is a point where pieces meet (a segment end or a
    /// curve's crossing), or it runs along a segment: a ray in another direction (or
    /// from another point) decides.
    Degenerate,
  };
  Kind kind = Kind::Nothing;
  SubFaceId face;
  /// The piece met (a SubFace hit): the index of face.patch's slab whose open angles
  /// hold the ray's angle, and the gap of that slab.
  std::uint32_t slab = 0;
  std::uint32_t gap = 0;
  /// Whether the ray arrives from the sub-face's positive (free) side.
  bool fromPositiveSide = false;
  /// Where it meets the first segment, as s in start + s * direction (rounded to a
  /// double; a SubFace or Degenerate hit not at the start only).
  double along = 0;
};

/// Rays in the slices of an arrangement at rational angles, decided exactly: the
/// candidate patches come from the index of their (x, y, theta) boxes, then every
/// test is on the exact slice (rational cosine and sine, rational points).
class SliceRays {
 public:
  SliceRays(const Arrangement& arrangement, AngleAlgebra& algebra);
  ~SliceRays();
  SliceRays(const SliceRays&) = delete;
  SliceRays& operator=(const SliceRays&) = delete;

  /// The first sub-face met by the ray from `from` in direction (`direction`, 0),
  /// direction +1 or -1, at a rational angle (AlgebraicAngle::isRational).
  RayHit cast(const AlgebraicAngle& rationalAngle, const std::array<Rational, 2>& from, int direction) const;

  /// The first sub-face met by the segment from `from` to `to` (its end included).
  RayHit castTo(const AlgebraicAngle& rationalAngle, const std::array<Rational, 2>& from,
                const std::array<Rational, 2>& to) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace freespace
