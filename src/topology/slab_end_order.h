#pragma once

// The slab ends of some patches in one counterclockwise order, so that which slab of
// a patch holds a place of that order is found by counting, with no comparison of
// angles after the sort (used around spirals and by the Euler characteristic sweep).

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "freespace/geometry/patch_subdivision.h"

namespace freespace::gluing {

class SlabEndOrder {
 public:
  /// The ends of every slab of the given patches, sorted counterclockwise (from the
  /// cut at theta = -pi/2), equal angles once.
  SlabEndOrder(const std::vector<std::uint32_t>& patches, const std::vector<PatchSubdivision>& subdivisions,
               AngleAlgebra& algebra);

  const std::vector<AlgebraicAngle>& angles() const { return angles_; }

  /// The place of an angle of the order (std::logic_error if it is none of them).
  std::size_t indexOf(const AlgebraicAngle& angle, AngleAlgebra& algebra) const;

  /// For each gap of the order (the open arc from an angle to the next, around to
  /// the first after the last; one gap when there are no angles), the slab of the
  /// i-th patch whose open angles hold it, if any.
  std::vector<std::optional<std::uint32_t>> slabsOverGaps(std::size_t i) const;
  /// The slab of the i-th patch whose open angles hold angle k of the order.
  std::optional<std::uint32_t> slabHoldingAngle(std::size_t i, std::size_t k) const;

 private:
  /// The first slab of the i-th patch for which `holds(from, to, arcs)` (the places
  /// of its ends, and the number of arcs it spans).
  template <class Holds>
  std::optional<std::uint32_t> firstSlab(std::size_t i, const Holds& holds) const;

  std::vector<AlgebraicAngle> angles_;
  /// Per patch and slab, the places of its ends; none for a whole circle without
  /// events.
  std::vector<std::vector<std::optional<std::pair<std::size_t, std::size_t>>>> ends_;
};

}  // namespace freespace::gluing
