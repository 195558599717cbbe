#include "gluing_parts.h"

namespace freespace::gluing {

bool holds(const PatchSlab& slab, const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  const int order = algebra.compare(slab.from, slab.to);
  // A slab from an event back to itself runs once around; one whose sample is its
  // `from` too is a whole circle without events.
  if (order == 0) return algebra.compare(slab.from, angle) != 0 || algebra.compare(slab.from, slab.sample) == 0;
  return algebra.contains(slab.from, slab.to, order > 0, angle, AngleAlgebra::Boundary::Excluded);
}

std::optional<std::size_t> slabIndexAt(const PatchSubdivision& subdivision, const AlgebraicAngle& angle,
                                       AngleAlgebra& algebra, std::size_t start) {
  const std::size_t count = subdivision.slabs.size();
  for (std::size_t step = 0; step < count; ++step) {
    const std::size_t i = (start + step) % count;
    if (holds(subdivision.slabs[i], angle, algebra)) return i;
  }
  return std::nullopt;
}

bool wholeCircleWithoutEvents(const PatchSubdivision& subdivision, AngleAlgebra& algebra) {
  return subdivision.slabs.size() == 1 && algebra.compare(subdivision.slabs[0].from, subdivision.slabs[0].sample) == 0;
}

const PatchSlab* slabMeeting(const PatchSubdivision& subdivision, const AlgebraicAngle& angle, bool ending,
                             AngleAlgebra& algebra) {
  if (wholeCircleWithoutEvents(subdivision, algebra)) return nullptr;
  // Searched from the end the slab is most likely at: horizontal edges are mostly
  // where a patch's range ends (its last slab) or starts (its first).
  const std::size_t count = subdivision.slabs.size();
  for (std::size_t step = 0; step < count; ++step) {
    const PatchSlab& slab = subdivision.slabs[ending ? count - 1 - step : step];
    if (algebra.compare(ending ? slab.to : slab.from, angle) == 0) return &slab;
  }
  return nullptr;
}

}  // namespace freespace::gluing

namespace freespace {

namespace {

/// Below this many slabs, a patch's slabs are searched from the first.
constexpr std::size_t kBisectedSlabs = 8;

/// The slab likeliest to hold the angle, by bisection: the slabs follow one another
/// around the patch's range from the first one's `from`, each starting where the last
/// ended, so the first whose `to` lies past the angle along the range holds it. Only
/// where the search starts (slabIndexAt tests it and goes on from there when it does
/// not hold the angle): the answer stays the slabs' own.
std::size_t likeliestSlab(const std::vector<PatchSlab>& slabs, const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  if (slabs.size() < kBisectedSlabs) return 0;
  const AlgebraicAngle& start = slabs.front().from;
  // Whether the angle lies on the arc from the range's start to slab k's end.
  const auto reachedBy = [&](std::size_t k) {
    const int order = algebra.compare(start, slabs[k].to);
    if (order == 0) return true;  // around the whole circle
    return algebra.contains(start, slabs[k].to, order > 0, angle, AngleAlgebra::Boundary::Excluded);
  };
  std::size_t low = 0, high = slabs.size() - 1;
  while (low < high) {
    const std::size_t middle = (low + high) / 2;
    if (reachedBy(middle)) {
      high = middle;
    } else {
      low = middle + 1;
    }
  }
  return low;
}

}  // namespace

const PatchSlab* slabAt(const PatchSubdivision& subdivision, const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  const auto found = gluing::slabIndexAt(subdivision, angle, algebra, likeliestSlab(subdivision.slabs, angle, algebra));
  return found ? &subdivision.slabs[*found] : nullptr;
}

}  // namespace freespace
