#include <algorithm>
#include <unordered_map>

#include "angle_bounds.h"
#include "freespace/geometry/patch_vertex.h"

namespace freespace {

namespace {

/// Ranges narrower than this (radians) are not split further by the rejection.
constexpr double kNarrowestPiece = 1.0 / 1024;

std::uint64_t pairKey(std::uint32_t low, std::uint32_t high) { return (std::uint64_t{low} << 32) | high; }

/// The curves by patch pair, and for each patch the patches of higher index it has
/// a curve with.
struct CurveIndex {
  explicit CurveIndex(std::size_t patchCount, const std::vector<PatchCurve>& curves) : neighbours(patchCount) {
    for (std::uint32_t i = 0; i < curves.size(); ++i) {
      byPair.emplace(pairKey(curves[i].first, curves[i].second), i);
      neighbours[curves[i].first].push_back(curves[i].second);
    }
    for (auto& list : neighbours) std::sort(list.begin(), list.end());
  }

  const PatchCurve* find(std::uint32_t low, std::uint32_t high, const std::vector<PatchCurve>& curves) const {
    const auto found = byPair.find(pairKey(low, high));
    return found == byPair.end() ? nullptr : &curves[found->second];
  }

  std::unordered_map<std::uint64_t, std::uint32_t> byPair;
  std::vector<std::vector<std::uint32_t>> neighbours;
};

/// True when the FFF determinant of the three lines has a certain nonzero sign at
/// every angle of [from, to], found by bisection down to kNarrowestPiece.
bool certainlyNotConcurrent(const std::array<const PatchLine<Interval>*, 3>& lines, double from, double to) {
  const auto [cosine, sine] = detail::cosSinOver(from, to);
  if (certainSign(threePatchDeterminant(*lines[0], *lines[1], *lines[2], cosine, sine)).value_or(Sign::Zero) !=
      Sign::Zero) {
    return true;
  }
  if (to - from < kNarrowestPiece) return false;
  const double middle = 0.5 * (from + to);
  return certainlyNotConcurrent(lines, from, middle) && certainlyNotConcurrent(lines, middle, to);
}

}  // namespace

std::shared_ptr<const AngleFunction> threePatchFunction(const ContactPoints& a, const ContactPoints& b,
                                                        const ContactPoints& c) {
  return std::make_shared<AngleFunction>([a, b, c](auto type, int chart) {
    using T = typename decltype(type)::type;
    return threePatchPolynomial(lineOf<T>(a), lineOf<T>(b), lineOf<T>(c), chart);
  });
}

std::vector<PatchVertex> patchVertices(const std::vector<PatchGeometry>& patches,
                                       const std::vector<PatchCurve>& curves, AngleAlgebra& algebra) {
  const CurveIndex index(patches.size(), curves);
  std::vector<PatchLine<Interval>> lines;
  std::vector<std::vector<detail::RadianRange>> curveRanges;
  {
    RoundingScope rounding;
    lines.reserve(patches.size());
    for (const PatchGeometry& patch : patches) lines.push_back(lineOf<Interval>(patch.line));
  }
  curveRanges.reserve(curves.size());
  for (const PatchCurve& curve : curves) curveRanges.push_back(detail::radianRanges(curve.angles));
  const auto rangesOf = [&](const PatchCurve* curve) -> const std::vector<detail::RadianRange>& {
    return curveRanges[static_cast<std::size_t>(curve - curves.data())];
  };

  std::vector<PatchVertex> vertices;
  for (std::uint32_t f = 0; f < patches.size(); ++f) {
    const std::vector<std::uint32_t>& around = index.neighbours[f];
    for (std::size_t i = 0; i < around.size(); ++i) {
      const std::uint32_t g = around[i];
      const PatchCurve* fg = index.find(f, g, curves);
      for (std::size_t j = i + 1; j < around.size(); ++j) {
        const std::uint32_t h = around[j];
        const PatchCurve* gh = index.find(g, h, curves);
        if (!gh) continue;
        const PatchCurve* fh = index.find(f, h, curves);
        const auto common = detail::overlap(detail::overlap(rangesOf(fg), rangesOf(fh)), rangesOf(gh));
        bool mayMeet = false;
        {
          RoundingScope rounding;
          for (const auto& [from, to] : common) {
            mayMeet = mayMeet || !certainlyNotConcurrent({&lines[f], &lines[g], &lines[h]}, from, to);
          }
        }
        if (!mayMeet) continue;
        const auto concurrency = threePatchFunction(patches[f].line, patches[g].line, patches[h].line);
        if (concurrency->isIdenticallyZero()) {
          // Concurrent at every angle: the three crossings are one moving point, a
          // curve shared by the three patches, not a vertex.
          algebra.statistics().recordIdentity(PredicateKind::ThreePatch);
          continue;
        }
        // At a root inside the open curves fg and gh the three lines meet at one point
        // inside g's segment and (by these curves) inside f's and h's: it is then
        // inside the curve fh too.
        constexpr auto open = AngleAlgebra::Boundary::Excluded;
        for (const AlgebraicAngle& root : algebra.roots(concurrency, PredicateKind::ThreePatch)) {
          if (algebra.contains(fg->angles, root, open) && algebra.contains(gh->angles, root, open)) {
            vertices.push_back({{f, g, h}, root});
          }
        }
      }
    }
  }
  return vertices;
}

}  // namespace freespace
