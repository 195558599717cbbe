#include "slab_end_order.h"

#include <algorithm>
#include <stdexcept>

#include "gluing_parts.h"

namespace freespace::gluing {

namespace {

/// A slab end to be sorted: its angle, whose end it is, and where it goes.
struct TaggedEnd {
  const AlgebraicAngle* angle;
  std::size_t patch;
  std::size_t slab;
  bool to;
};

/// Merges the sorted runs of `ends` that start at `starts` (increasing, the first
/// at 0) pairwise, round by round: log(runs) passes over the ends.
template <class Before>
void mergeRuns(std::vector<TaggedEnd>& ends, std::vector<std::size_t> starts, const Before& before) {
  const auto at = [&](std::size_t index) { return ends.begin() + static_cast<std::ptrdiff_t>(index); };
  while (starts.size() > 1) {
    std::vector<std::size_t> merged;
    for (std::size_t r = 0; r < starts.size(); r += 2) {
      merged.push_back(starts[r]);
      if (r + 1 == starts.size()) break;
      const std::size_t end = r + 2 < starts.size() ? starts[r + 2] : ends.size();
      std::inplace_merge(at(starts[r]), at(starts[r + 1]), at(end), before);
    }
    starts = std::move(merged);
  }
}

}  // namespace

SlabEndOrder::SlabEndOrder(const std::vector<std::uint32_t>& patches, const std::vector<PatchSubdivision>& subdivisions,
                           AngleAlgebra& algebra) {
  const auto before = [&](const TaggedEnd& a, const TaggedEnd& b) { return algebra.compare(*a.angle, *b.angle) < 0; };
  // A patch's sweep makes its slabs follow each other counterclockwise, each ending
  // where the next begins, from the first event after the cut at theta = -pi/2: its
  // ends in slab order are sorted but for one descent where they pass the cut, and
  // the part after it moved to the front makes one sorted run. The runs are merged
  // (a run still out of order, which no sweep makes, is sorted first).
  std::size_t slabCount = 0;
  for (std::uint32_t patch : patches) slabCount += subdivisions[patch].slabs.size();
  std::vector<TaggedEnd> tagged;
  tagged.reserve(2 * slabCount);
  ends_.reserve(patches.size());
  std::vector<std::size_t> runStarts;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    const std::vector<PatchSlab>& slabs = subdivisions[patches[i]].slabs;
    ends_.emplace_back(slabs.size());
    if (slabs.empty() || wholeCircleWithoutEvents(subdivisions[patches[i]], algebra)) continue;
    const std::size_t start = tagged.size();
    for (std::size_t s = 0; s < slabs.size(); ++s) {
      tagged.push_back({&slabs[s].from, i, s, false});
      tagged.push_back({&slabs[s].to, i, s, true});
    }
    const auto run = tagged.begin() + static_cast<std::ptrdiff_t>(start);
    std::rotate(run, std::is_sorted_until(run, tagged.end(), before), tagged.end());
    if (!std::is_sorted(run, tagged.end(), before)) std::sort(run, tagged.end(), before);
    runStarts.push_back(start);
  }
  mergeRuns(tagged, std::move(runStarts), before);
  for (const TaggedEnd& end : tagged) {
    if (angles_.empty() || algebra.compare(angles_.back(), *end.angle) != 0) angles_.push_back(*end.angle);
    auto& slabEnds = ends_[end.patch][end.slab];
    if (!slabEnds) slabEnds.emplace(0, 0);
    (end.to ? slabEnds->second : slabEnds->first) = angles_.size() - 1;
  }
}

std::size_t SlabEndOrder::indexOf(const AlgebraicAngle& angle, AngleAlgebra& algebra) const {
  const auto found = std::lower_bound(angles_.begin(), angles_.end(), angle,
                                      [&](const AlgebraicAngle& a, const AlgebraicAngle& b) {
                                        return algebra.compare(a, b) < 0;
                                      });
  if (found == angles_.end() || algebra.compare(*found, angle) != 0) {
    throw std::logic_error("SlabEndOrder: an angle is no slab's end");
  }
  return static_cast<std::size_t>(found - angles_.begin());
}

template <class Holds>
std::optional<std::uint32_t> SlabEndOrder::firstSlab(std::size_t i, const Holds& holds) const {
  const std::size_t n = angles_.size();
  for (std::uint32_t slab = 0; slab < ends_[i].size(); ++slab) {
    const auto& ends = ends_[i][slab];
    if (!ends) return slab;  // a whole circle without events holds everything
    const auto [from, to] = *ends;
    // A slab from an event back to it spans every arc.
    if (holds(from, from == to ? n : (to + n - from) % n)) return slab;
  }
  return std::nullopt;
}

std::vector<std::optional<std::uint32_t>> SlabEndOrder::slabsOverGaps(std::size_t i) const {
  const std::size_t n = angles_.size();
  std::vector<std::optional<std::uint32_t>> slabs(std::max<std::size_t>(n, 1));
  // Slabs filled last to first: a gap that two slabs hold goes to the first, as in
  // firstSlab. A patch's slabs do not overlap, so this is one pass over the gaps.
  for (std::size_t slab = ends_[i].size(); slab-- > 0;) {
    const auto& ends = ends_[i][slab];
    if (!ends) {  // a whole circle without events holds everything
      std::fill(slabs.begin(), slabs.end(), static_cast<std::uint32_t>(slab));
      continue;
    }
    const auto [from, to] = *ends;
    const std::size_t arcs = from == to ? n : (to + n - from) % n;
    for (std::size_t step = 0; step < arcs; ++step) slabs[(from + step) % n] = static_cast<std::uint32_t>(slab);
  }
  return slabs;
}

std::optional<std::uint32_t> SlabEndOrder::slabHoldingAngle(std::size_t i, std::size_t k) const {
  const std::size_t n = angles_.size();
  return firstSlab(i, [&](std::size_t from, std::size_t arcs) {
    const std::size_t step = (k + n - from) % n;
    return step != 0 && step < arcs;
  });
}

}  // namespace freespace::gluing
