#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "angle_bounds.h"
#include "contact_vectors.h"
#include "freespace/geometry/patch_vertex.h"

namespace freespace {

namespace {

/// Ranges narrower than this (radians) are not split further by the rejection.
constexpr double kNarrowestPiece = 1.0 / 1024;

std::uint64_t pairKey(std::uint32_t low, std::uint32_t high) { return (std::uint64_t{low} << 32) | high; }

/// The curves by patch pair, and for each patch the patches it has a curve with.
struct CurveIndex {
  explicit CurveIndex(std::size_t patchCount, const std::vector<PatchCurve>& curves) : neighbours(patchCount) {
    for (std::uint32_t i = 0; i < curves.size(); ++i) {
      byPair.emplace(pairKey(curves[i].first, curves[i].second), i);
      neighbours[curves[i].first].push_back(curves[i].second);
      neighbours[curves[i].second].push_back(curves[i].first);
    }
    for (auto& list : neighbours) std::sort(list.begin(), list.end());
  }

  const PatchCurve* find(std::uint32_t a, std::uint32_t b, const std::vector<PatchCurve>& curves) const {
    const auto found = byPair.find(pairKey(std::min(a, b), std::max(a, b)));
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

/// The vertex where patch f crosses the two patches of an overlap.
PatchVertex crossingOfOverlap(std::uint32_t f, const PatchOverlap& overlap) {
  std::array<std::uint32_t, 3> sorted{f, overlap.patches[0], overlap.patches[1]};
  std::sort(sorted.begin(), sorted.end());
  return {sorted, overlap.angle, static_cast<int>(std::find(sorted.begin(), sorted.end(), f) - sorted.begin())};
}

/// w_a - w_b: zero where the parallel lines of a and b coincide. Keyed as the EF
/// function it is: for contacts of vertices x, y with one facet (normal n), (R (x -
/// y)) . n, with the same sign convention whichever body the vertices are on.
std::shared_ptr<const AngleFunction> coincidence(const PatchGeometry& a, const PatchGeometry& b) {
  const bool robotVertices = a.patch.contact.kind == ContactKind::VertexFacet;
  const auto& vertices = a.line.vertices;  // the vertex, then the facet's corners
  return std::make_shared<AngleFunction>([x = a.line, y = b.line](auto type, int chart) {
    using T = typename decltype(type)::type;
    const PatchLine<T> first = lineOf<T>(x), second = lineOf<T>(y);
    return tangentPolynomial(TrigLinear<T>{first.k1 - second.k1, first.k2 - second.k2, first.k3 - second.k3}, chart);
  }, detail::edgeFacetKey(robotVertices, vertices[0], b.line.vertices[0], {vertices[1], vertices[2], vertices[3]}));
}

/// (e - f) . (f1 - f0) for points e, f, f0, f1 moving as u + R v: linear in cos and
/// sin, because (R v) . (R v') = v . v' and u . (R v) = cos (u . v) + sin (v x u).
template <class T>
TrigLinear<T> spiralDifferenceDot(const Spiral<T>& e, const Spiral<T>& f, const Spiral<T>& f0, const Spiral<T>& f1) {
  const T ux = e.ux - f.ux, uy = e.uy - f.uy, vx = e.vx - f.vx, vy = e.vy - f.vy;
  const T px = f1.ux - f0.ux, py = f1.uy - f0.uy, qx = f1.vx - f0.vx, qy = f1.vy - f0.vy;
  // (u + R v) . (p + R q) = u . p + v . q + u . (R q) + p . (R v)
  return {(qx * uy - qy * ux) + (vx * py - vy * px), (ux * qx + uy * qy) + (px * vx + py * vy),
          ux * px + uy * py + vx * qx + vy * qy};
}

/// The sign at `angle` of (end k of `moving` - end j of `fixed`) . (fixed's end 1 -
/// its end 0): where the end lies along the other segment's direction.
Sign alongSegment(const PatchGeometry& moving, int k, const PatchGeometry& fixed, int j, const AlgebraicAngle& angle,
                  AngleAlgebra& algebra) {
  const AngleFunction along([e = moving.ends[k], f = fixed.ends[j], f0 = fixed.ends[0], f1 = fixed.ends[1]](auto type,
                                                                                                        int chart) {
    using T = typename decltype(type)::type;
    return tangentPolynomial(spiralDifferenceDot(spiralOf<T>(e), spiralOf<T>(f), spiralOf<T>(f0), spiralOf<T>(f1)),
                             chart);
  });
  const Sign sign = algebra.signAt(along, angle);
  if (sign == Sign::Zero) throw std::logic_error("patchOverlaps: segment ends of parallel patches coincide");
  return sign;
}

/// Which ends of `fixed`'s segment the other segment runs beyond, at an angle where
/// their lines coincide; nullopt when the segments do not overlap.
std::optional<std::array<bool, 2>> endsReached(const PatchGeometry& fixed, const PatchGeometry& moving,
                                               const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  std::array<bool, 2> beforeStart{}, afterEnd{};
  for (int k = 0; k < 2; ++k) {
    beforeStart[k] = alongSegment(moving, k, fixed, 0, angle, algebra) == Sign::Negative;
    afterEnd[k] = alongSegment(moving, k, fixed, 1, angle, algebra) == Sign::Positive;
  }
  if ((beforeStart[0] && beforeStart[1]) || (afterEnd[0] && afterEnd[1])) return std::nullopt;
  return std::array<bool, 2>{beforeStart[0] || beforeStart[1], afterEnd[0] || afterEnd[1]};
}

}  // namespace

std::vector<PatchOverlap> patchOverlaps(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra) {
  // Contacts with one facet, by kind and facet: two contacts of vertices with one
  // facet have the same normal n = R a1 + a2 at every angle, so parallel lines.
  std::map<std::pair<int, std::uint32_t>, std::vector<std::uint32_t>> byFacet;
  for (std::uint32_t i = 0; i < patches.size(); ++i) {
    const Contact& contact = patches[i].patch.contact;
    if (contact.kind == ContactKind::VertexFacet) byFacet[{0, contact.world}].push_back(i);
    if (contact.kind == ContactKind::FacetVertex) byFacet[{1, contact.robot}].push_back(i);
  }
  std::vector<PatchOverlap> overlaps;
  constexpr auto open = AngleAlgebra::Boundary::Excluded;
  for (const auto& [facet, members] : byFacet) {
    for (std::size_t i = 0; i < members.size(); ++i) {
      for (std::size_t j = i + 1; j < members.size(); ++j) {
        const PatchGeometry &a = patches[members[i]], &b = patches[members[j]];
        for (const AlgebraicAngle& root : algebra.roots(coincidence(a, b), PredicateKind::EdgeFacet)) {
          if (!algebra.contains(a.patch.range, root, open) || !algebra.contains(b.patch.range, root, open)) continue;
          const auto onA = endsReached(a, b, root, algebra);
          if (!onA) continue;
          overlaps.push_back({{members[i], members[j]}, root, {*onA, *endsReached(b, a, root, algebra)}});
        }
      }
    }
  }
  return overlaps;
}

std::shared_ptr<const AngleFunction> threePatchFunction(const ContactPoints& a, const ContactPoints& b,
                                                        const ContactPoints& c) {
  return std::make_shared<AngleFunction>([a, b, c](auto type, int chart) {
    using T = typename decltype(type)::type;
    return threePatchPolynomial(lineOf<T>(a), lineOf<T>(b), lineOf<T>(c), chart);
  });
}

std::vector<PatchVertex> patchVertices(const std::vector<PatchGeometry>& patches,
                                       const std::vector<PatchCurve>& curves,
                                       const std::vector<PatchOverlap>& overlaps, AngleAlgebra& algebra) {
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
      for (std::size_t j = i + 1; j < around.size(); ++j) {
        const std::uint32_t h = around[j];
        // Each triple once, from its smallest patch.
        const PatchCurve* gh = index.find(g, h, curves);
        if (!gh || f > g) continue;
        const PatchCurve *fg = index.find(f, g, curves), *fh = index.find(f, h, curves);
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
        // At a root inside the open curves fg and fh, f crosses g and h at one point,
        // inside the three segments.
        constexpr auto open = AngleAlgebra::Boundary::Excluded;
        for (const AlgebraicAngle& root : algebra.roots(concurrency, PredicateKind::ThreePatch)) {
          if (algebra.contains(fg->angles, root, open) && algebra.contains(fh->angles, root, open)) {
            vertices.push_back({{f, g, h}, root, -1});
          }
        }
      }
    }
  }
  for (const PatchOverlap& overlap : overlaps) {
    const auto& [g, h] = overlap.patches;
    for (std::uint32_t f : index.neighbours[g]) {
      const PatchCurve *fg = index.find(f, g, curves), *fh = index.find(f, h, curves);
      constexpr auto open = AngleAlgebra::Boundary::Excluded;
      if (fh && algebra.contains(fg->angles, overlap.angle, open) && algebra.contains(fh->angles, overlap.angle, open)) {
        vertices.push_back(crossingOfOverlap(f, overlap));
      }
    }
  }
  std::sort(vertices.begin(), vertices.end(), [&](const PatchVertex& a, const PatchVertex& b) {
    if (a.patches != b.patches) return a.patches < b.patches;
    return algebra.compare(a.angle, b.angle) < 0;
  });
  return vertices;
}

}  // namespace freespace
