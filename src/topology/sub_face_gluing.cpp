#include "freespace/topology/sub_face_gluing.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "gluing_parts.h"
#include "slab_end_order.h"

namespace freespace {

namespace {

using gluing::SlabEndOrder;

using gluing::GlueList;
using gluing::SlabCursor;

/// The sub-face of the slab on the side of `curve` (at index `at` of its curves)
/// that holds end 1 of the segment when `towardEnd1`, else end 0.
std::uint32_t faceBeside(const PatchSlab& slab, std::size_t at, bool towardEnd1) {
  return slab.faces[towardEnd1 ? at + 1 : at];
}

std::size_t indexOf(const PatchSlab& slab, std::uint32_t curve) {
  const auto found = std::find(slab.curves.begin(), slab.curves.end(), curve);
  if (found == slab.curves.end()) throw std::logic_error("glueAcrossCurves: a curve is missing from a slab");
  return static_cast<std::size_t>(found - slab.curves.begin());
}

/// A segment leaving a spiral's point: its patch, which of its ends the spiral is,
/// and its sub-face there.
struct Spoke {
  std::uint32_t patch;
  int end;
  std::uint32_t face;
};

/// The direction of a spoke at an angle: from the spiral to the segment's other end.
template <class T>
std::array<T, 2> directionOf(const PatchGeometry& patch, int end, const T& cosine, const T& sine) {
  const auto from = spiralPoint(spiralOf<T>(patch.ends[end]), cosine, sine);
  const auto to = spiralPoint(spiralOf<T>(patch.ends[1 - end]), cosine, sine);
  return {to[0] - from[0], to[1] - from[1]};
}

/// Counterclockwise order of directions, starting along +x.
bool before(const std::array<Rational, 2>& a, const std::array<Rational, 2>& b) {
  const auto half = [](const std::array<Rational, 2>& u) { return u[1] > 0 || (u[1] == 0 && u[0] > 0) ? 0 : 1; };
  if (half(a) != half(b)) return half(a) < half(b);
  return a[0] * b[1] - a[1] * b[0] > 0;
}

/// Directions at which a counterclockwise order may start: the order around a
/// spiral is cyclic, so any start will do, and one that no spoke is near lets
/// double intervals decide (spokes along the axes are common in floor plans).
constexpr std::array<std::array<double, 2>, 4> kOrderStarts{{{1, 0}, {0, 1}, {1, 1}, {1, -1}}};

/// The half turn counterclockwise from `start` that holds direction u (0: the
/// first), when certain in double intervals.
std::optional<int> halfFrom(const std::array<double, 2>& start, const std::array<Interval, 2>& u) {
  const std::optional<Sign> side = certainSign(Interval(start[0]) * u[1] - Interval(start[1]) * u[0]);
  if (!side || *side == Sign::Zero) return std::nullopt;
  return *side == Sign::Positive ? 0 : 1;
}

/// The spokes' counterclockwise order from `start` in double intervals (as indices),
/// when every comparison is certain.
std::optional<std::vector<std::size_t>> certainOrderFrom(const std::array<double, 2>& start,
                                                         const std::vector<std::array<Interval, 2>>& directions) {
  std::vector<int> halves;
  for (const auto& direction : directions) {
    const std::optional<int> half = halfFrom(start, direction);
    if (!half) return std::nullopt;
    halves.push_back(*half);
  }
  // Every pair certain first: a comparison that may be wrong must not reach the sort.
  const std::size_t n = directions.size();
  std::vector<char> isBefore(n * n, 0);  // a before b at a * n + b
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (halves[a] != halves[b]) {
        isBefore[a * n + b] = halves[a] < halves[b];
      } else {
        const auto& u = directions[a];
        const auto& v = directions[b];
        const std::optional<Sign> cross = certainSign(u[0] * v[1] - u[1] * v[0]);
        if (!cross || *cross == Sign::Zero) return std::nullopt;
        isBefore[a * n + b] = *cross == Sign::Positive;
      }
      isBefore[b * n + a] = !isBefore[a * n + b];
    }
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return isBefore[a * n + b] != 0; });
  return order;
}

/// Sorts the spokes counterclockwise (cyclically) at a rational angle: in double
/// intervals when every comparison is certain from one of the starts, exactly
/// otherwise.
void sortCounterclockwise(std::vector<Spoke>& spokes, const std::vector<PatchGeometry>& patches,
                          const AlgebraicAngle& angle) {
  {
    RoundingScope rounding;
    const auto [cosine, sine] = cosSinEnclosure(angle);
    std::vector<std::array<Interval, 2>> directions;
    for (const Spoke& spoke : spokes) directions.push_back(directionOf(patches[spoke.patch], spoke.end, cosine, sine));
    for (const auto& start : kOrderStarts) {
      if (const auto order = certainOrderFrom(start, directions)) {
        std::vector<Spoke> sorted;
        for (std::size_t i : *order) sorted.push_back(spokes[i]);
        spokes = std::move(sorted);
        return;
      }
    }
  }
  const auto [cosine, sine] = exactCosSin(angle);
  std::vector<std::pair<std::array<Rational, 2>, Spoke>> exact;
  for (const Spoke& spoke : spokes) exact.push_back({directionOf(patches[spoke.patch], spoke.end, cosine, sine), spoke});
  std::sort(exact.begin(), exact.end(), [](const auto& a, const auto& b) { return before(a.first, b.first); });
  for (std::size_t i = 0; i < spokes.size(); ++i) spokes[i] = exact[i].second;
}

/// A rational angle inside the open arc from angle `gap` of a sorted list of
/// distinct angles to the next (the last around to the first).
AlgebraicAngle sampleInGap(const std::vector<AlgebraicAngle>& angles, std::size_t gap, AngleAlgebra& algebra) {
  if (angles.empty()) return AlgebraicAngle::rational(0, 0.0);
  if (angles.size() == 1) return AlgebraicAngle::rational(1 - angles[0].chart(), 0.0);
  return algebra.rationalBetween(angles[gap], angles[(gap + 1) % angles.size()]);
}

/// The segment ends (patch, end) at each spiral, spirals in the order of their
/// features, each spiral's ends by patch and end.
std::vector<std::vector<std::pair<std::uint32_t, int>>> endsBySpiral(const std::vector<PatchGeometry>& patches) {
  using SpiralKey = std::tuple<bool, std::uint32_t, std::uint32_t, std::uint32_t>;
  std::vector<std::tuple<SpiralKey, std::uint32_t, int>> ends;
  ends.reserve(2 * patches.size());
  for (std::uint32_t patch = 0; patch < patches.size(); ++patch) {
    for (int k = 0; k < 2; ++k) {
      const SegmentEnd& end = patches[patch].segment.ends[k];
      ends.emplace_back(SpiralKey{end.robotVertex, end.vertex, end.edge[0], end.edge[1]}, patch, k);
    }
  }
  std::sort(ends.begin(), ends.end());
  std::vector<std::vector<std::pair<std::uint32_t, int>>> groups;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    if (i == 0 || std::get<0>(ends[i]) != std::get<0>(ends[i - 1])) groups.emplace_back();
    groups.back().emplace_back(std::get<1>(ends[i]), std::get<2>(ends[i]));
  }
  return groups;
}

}  // namespace

SubFaceGluing glueAcrossCurves(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                               const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra,
                               const Cancellation& cancellation) {
  GlueList glues;
  SlabCursor slabs(subdivisions, algebra);
  for (std::uint32_t f = 0; f < patches.size(); ++f) {
    cancellation.check();
    for (const PatchSlab& slab : subdivisions[f].slabs) {
      for (std::size_t i = 0; i < slab.curves.size(); ++i) {
        const std::uint32_t g = curves[slab.curves[i]].other(f);
        if (g < f) continue;  // each curve from its first patch's slabs
        const PatchSlab* across = slabs.at(g, slab.sample);
        if (!across) throw std::logic_error("glueAcrossCurves: a curve's other patch has no slab there");
        // f's half on g's positive side is the one holding f's end that is there.
        const bool fTowardEnd1 = sideOfEnd(patches[f], 1, patches[g], slab.sample, algebra) == Sign::Positive;
        const bool gTowardEnd1 = sideOfEnd(patches[g], 1, patches[f], slab.sample, algebra) == Sign::Positive;
        glues.add({f, faceBeside(slab, i, fTowardEnd1)},
                  {g, faceBeside(*across, indexOf(*across, slab.curves[i]), gTowardEnd1)}, GluedEdge::Curve,
                  slab.sample);
      }
    }
  }
  return glues.take();
}

SubFaceGluing glueAroundSpirals(const std::vector<PatchGeometry>& patches,
                                const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra,
                                const Cancellation& cancellation) {
  GlueList glues;
  for (const std::vector<std::pair<std::uint32_t, int>>& around : endsBySpiral(patches)) {
    cancellation.check();
    // Over each arc between consecutive slab ends of the patches around the spiral,
    // the spokes and their slabs stay the same: one sample decides the arc.
    std::vector<std::uint32_t> aroundPatches;
    for (const auto& [patch, unusedEnd] : around) aroundPatches.push_back(patch);
    const SlabEndOrder order(aroundPatches, subdivisions, algebra);
    const std::size_t gaps = std::max<std::size_t>(order.angles().size(), 1);
    std::vector<std::vector<std::optional<std::uint32_t>>> slabsOverGaps;
    for (std::size_t i = 0; i < around.size(); ++i) slabsOverGaps.push_back(order.slabsOverGaps(i));
    for (std::size_t gap = 0; gap < gaps; ++gap) {
      std::vector<Spoke> spokes;
      for (std::size_t i = 0; i < around.size(); ++i) {
        const auto [patch, k] = around[i];
        const std::optional<std::uint32_t> slab = slabsOverGaps[i][gap];
        if (!slab) continue;  // outside the patch's range
        const PatchSlab& at = subdivisions[patch].slabs[*slab];
        spokes.push_back({patch, k, k == 0 ? at.faces.front() : at.faces.back()});
      }
      // Sampled only where needed: one or two spokes are in their one cyclic order
      // (most gaps have two), and a lone spoke glues nothing.
      std::optional<AlgebraicAngle> sample;
      const auto sampleHere = [&]() -> const AlgebraicAngle& {
        if (!sample) sample = sampleInGap(order.angles(), gap, algebra);
        return *sample;
      };
      if (spokes.size() > 2) sortCounterclockwise(spokes, patches, sampleHere());
      // The sector counterclockwise after a spoke: its positive side (right of end
      // 0 -> end 1, PatchSegment) faces it when the spiral is the spoke's end 1.
      gluing::glueAround(
          spokes, [](const Spoke& spoke) { return spoke.end == 1; },
          [](const Spoke& spoke, bool) { return SubFaceId{spoke.patch, spoke.face}; }, GluedEdge::Spiral,
          [&](const Spoke&, const Spoke&) { return sampleHere(); }, glues);
    }
  }
  return glues.take();
}

}  // namespace freespace
