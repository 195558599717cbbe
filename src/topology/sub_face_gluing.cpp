#include "freespace/topology/sub_face_gluing.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>

namespace freespace {

namespace {

/// Keeps each glued pair of sub-faces once (the first angle it was seen at).
class GlueList {
 public:
  void add(SubFaceId a, SubFaceId b, GluedEdge edge, const AlgebraicAngle& at) {
    if (std::make_pair(b.patch, b.face) < std::make_pair(a.patch, a.face)) std::swap(a, b);
    if (seen_.insert({a.patch, a.face, b.patch, b.face}).second) glues_.push_back({a, b, edge, at});
  }
  std::vector<SubFaceGlue> take() { return std::move(glues_); }

 private:
  std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>> seen_;
  std::vector<SubFaceGlue> glues_;
};

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
/// and its direction from the point.
struct Spoke {
  std::uint32_t patch;
  int end;
  std::array<Rational, 2> direction;
};

/// Counterclockwise order of directions, starting along +x.
bool before(const std::array<Rational, 2>& a, const std::array<Rational, 2>& b) {
  const auto half = [](const std::array<Rational, 2>& u) { return u[1] > 0 || (u[1] == 0 && u[0] > 0) ? 0 : 1; };
  if (half(a) != half(b)) return half(a) < half(b);
  return a[0] * b[1] - a[1] * b[0] > 0;
}

bool holds(const PatchSlab& slab, const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  const int order = algebra.compare(slab.from, slab.to);
  // A slab from an event back to itself runs once around; one whose sample is its
  // `from` too is a whole circle without events.
  if (order == 0) return algebra.compare(slab.from, angle) != 0 || algebra.compare(slab.from, slab.sample) == 0;
  return algebra.contains(AngleInterval{slab.from, slab.to, order > 0}, angle, AngleAlgebra::Boundary::Excluded);
}

/// The index of the slab holding `angle`, searched from `start` on (wrapping): the
/// gluing asks mostly for rising angles, so the search usually ends at once.
std::optional<std::size_t> slabIndexAt(const PatchSubdivision& subdivision, const AlgebraicAngle& angle,
                                       AngleAlgebra& algebra, std::size_t start) {
  const std::size_t count = subdivision.slabs.size();
  for (std::size_t step = 0; step < count; ++step) {
    const std::size_t i = (start + step) % count;
    if (holds(subdivision.slabs[i], angle, algebra)) return i;
  }
  return std::nullopt;
}

/// Remembers, per patch, where the last search ended.
class SlabCursor {
 public:
  SlabCursor(const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra)
      : subdivisions_(subdivisions), algebra_(algebra), last_(subdivisions.size(), 0) {}

  const PatchSlab* at(std::uint32_t patch, const AlgebraicAngle& angle) {
    const auto found = slabIndexAt(subdivisions_[patch], angle, algebra_, last_[patch]);
    if (!found) return nullptr;
    last_[patch] = *found;
    return &subdivisions_[patch].slabs[*found];
  }

 private:
  const std::vector<PatchSubdivision>& subdivisions_;
  AngleAlgebra& algebra_;
  std::vector<std::size_t> last_;
};

/// One rational angle inside each interval between consecutive slab ends of the
/// patches around a spiral: the spokes around it and their slabs are the same over
/// each such interval.
std::vector<AlgebraicAngle> samplesAround(const std::vector<std::pair<std::uint32_t, int>>& around,
                                          const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra) {
  std::vector<AlgebraicAngle> ends;
  for (const auto& [patch, unusedEnd] : around) {
    for (const PatchSlab& slab : subdivisions[patch].slabs) {
      if (algebra.compare(slab.from, slab.sample) == 0) continue;  // a circle without events
      ends.push_back(slab.from);
      ends.push_back(slab.to);
    }
  }
  std::sort(ends.begin(), ends.end(), [&](const AlgebraicAngle& a, const AlgebraicAngle& b) {
    return algebra.compare(a, b) < 0;
  });
  ends.erase(std::unique(ends.begin(), ends.end(),
                         [&](const AlgebraicAngle& a, const AlgebraicAngle& b) { return algebra.compare(a, b) == 0; }),
             ends.end());
  if (ends.empty()) return {AlgebraicAngle::rational(0, 0.0)};
  if (ends.size() == 1) return {AlgebraicAngle::rational(1 - ends[0].chart(), 0.0)};
  std::vector<AlgebraicAngle> samples;
  for (std::size_t i = 0; i < ends.size(); ++i) samples.push_back(algebra.rationalBetween(ends[i], ends[(i + 1) % ends.size()]));
  return samples;
}

}  // namespace

const PatchSlab* slabAt(const PatchSubdivision& subdivision, const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  const auto found = slabIndexAt(subdivision, angle, algebra, 0);
  return found ? &subdivision.slabs[*found] : nullptr;
}

std::vector<SubFaceGlue> glueAcrossCurves(const std::vector<PatchGeometry>& patches,
                                          const std::vector<PatchCurve>& curves,
                                          const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra) {
  GlueList glues;
  SlabCursor slabs(subdivisions, algebra);
  for (std::uint32_t f = 0; f < patches.size(); ++f) {
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

std::vector<SubFaceGlue> glueAroundSpirals(const std::vector<PatchGeometry>& patches,
                                           const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra) {
  std::map<std::tuple<bool, std::uint32_t, std::uint32_t, std::uint32_t>, std::vector<std::pair<std::uint32_t, int>>>
      bySpiral;
  for (std::uint32_t patch = 0; patch < patches.size(); ++patch) {
    for (int k = 0; k < 2; ++k) {
      const SegmentEnd& end = patches[patch].segment.ends[k];
      bySpiral[{end.robotVertex, end.vertex, end.edge[0], end.edge[1]}].push_back({patch, k});
    }
  }
  GlueList glues;
  SlabCursor cursor(subdivisions, algebra);
  for (const auto& [spiral, around] : bySpiral) {
    if (around.size() < 2) continue;
    for (const AlgebraicAngle& sample : samplesAround(around, subdivisions, algebra)) {
      const auto [cosine, sine] = exactCosSin(sample);
      std::vector<Spoke> spokes;
      std::vector<const PatchSlab*> slabs;
      for (const auto& [patch, k] : around) {
        if (!algebra.contains(patches[patch].patch.range, sample)) continue;
        const PatchSlab* at = cursor.at(patch, sample);
        if (!at) throw std::logic_error("glueAroundSpirals: an active patch has no slab at a sample");
        const auto from = spiralPoint(spiralOf<Rational>(patches[patch].ends[k]), cosine, sine);
        const auto to = spiralPoint(spiralOf<Rational>(patches[patch].ends[1 - k]), cosine, sine);
        spokes.push_back({patch, k, {to[0] - from[0], to[1] - from[1]}});
        slabs.push_back(at);
      }
      if (spokes.size() < 2) continue;
      std::vector<std::size_t> order(spokes.size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
      std::sort(order.begin(), order.end(),
                [&](std::size_t a, std::size_t b) { return before(spokes[a].direction, spokes[b].direction); });
      // The sector counterclockwise from spoke a to the next spoke b: a's positive
      // side (right of end 0 -> end 1, PatchSegment) faces it when the spiral is a's
      // end 1, b's when it is b's end 0.
      for (std::size_t i = 0; i < order.size(); ++i) {
        const std::size_t a = order[i], b = order[(i + 1) % order.size()];
        if (spokes[a].end != 1 || spokes[b].end != 0) continue;
        glues.add({spokes[a].patch, slabs[a]->faces.back()}, {spokes[b].patch, slabs[b]->faces.front()},
                  GluedEdge::Spiral, sample);
      }
    }
  }
  return glues.take();
}

}  // namespace freespace
