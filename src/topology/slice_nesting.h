#pragma once

// Nesting of closed curves of a slice at a rational angle, shared by the free cells
// (a shell's slice, free_cells.cpp) and the cell graph (one boundary loop of a
// face, cell_graph.cpp): the leftmost point of the curve, and what a point just
// left of it sees (docs/design.md section 6, step 5).

#include <array>
#include <functional>
#include <optional>

#include "freespace/topology/slice_pieces.h"
#include "freespace/topology/slice_ray.h"

namespace freespace::slices {

/// Least x, then least y.
inline bool leftOf(const Point& a, const Point& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); }

/// The leftmost end among pieces of segments at one rational angle: each piece
/// offered is bounded in double intervals, and only those that may hold the
/// leftmost end are computed exactly.
class LeftmostEnd {
 public:
  LeftmostEnd(const Arrangement& arrangement, const AlgebraicAngle& rationalAngle);

  /// False once a piece whose patch's boxes start at `lowestX` cannot hold the
  /// leftmost end (pieces offered by increasing lowestX may stop there).
  bool worthOffering(double lowestX) const { return lowestX <= leftmostX_; }
  /// The piece at index `gap` of `slab`, a slab of `patch` holding the angle.
  void offer(std::uint32_t patch, const PatchSlab& slab, std::size_t gap);
  /// The leftmost end of the pieces offered, exactly; none when none was.
  std::optional<Point> exact() const;

 private:
  /// A piece offered, with the lower bounds of its ends' x.
  struct Offered {
    std::uint32_t patch;
    const PatchSlab* slab;
    std::size_t gap;
    std::array<double, 2> lowestX;
  };
  const Arrangement& arrangement_;
  AlgebraicAngle angle_;
  IntervalSlice slice_;
  std::vector<Offered> offered_;
  /// No piece end lies right of every point left of this.
  double leftmostX_ = HUGE_VAL;
};

/// What lies just outside a closed curve near its leftmost point, as a ray toward +x
/// from there shows: the curve itself seen from its free side (the curve is a hole
/// in the region outside it), a blocked side (the curve bounds its region from
/// outside), or something else in between (the point was too far).
enum class Outside { Hole, Outer, Unknown };

/// The answer of lookLeftOf: a hole, with the first sub-face met toward -x from a
/// point just left of the leftmost point (Nothing or SubFace), or an outer curve.
struct LeftOfLeftmost {
  bool hole = false;
  RayHit leftward;
};

/// Looks from points q up-left and down-left of the leftmost point p of a curve at a
/// rational angle: `seen` tells what a ray toward +x from q meets. The answer is
/// taken once two points at distances d and d / 2^16 from p agree (far points may
/// see other curves), d shrinking from 2^-24 of p's size to 2^-200. Throws
/// std::runtime_error when no point gives an answer.
LeftOfLeftmost lookLeftOf(const SliceRays& rays, const AlgebraicAngle& rationalAngle, const Point& leftmost,
                          const std::function<Outside(const RayHit& towardPlusX)>& seen);

}  // namespace freespace::slices
