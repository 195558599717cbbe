#include <algorithm>
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

/// det(v, u, u') of hingedCoincidence as an angle function, for EE points p and q whose
/// edges on the robot (robotHinge) or on the environment leave one vertex, at end
/// atP of p's edge and atQ of q's.
std::shared_ptr<const AngleFunction> hingeCoincidence(const ContactPoints& p, int atP, const ContactPoints& q, int atQ,
                                                      bool robotHinge) {
  const int first = robotHinge ? 0 : 2;  // where the hinged edges' points are
  const int shared = robotHinge ? 2 : 0;
  const Point3 x = p.points[first + atP], a = p.points[first + 1 - atP], b = q.points[first + 1 - atQ];
  const Point3 from = p.points[shared], to = p.points[shared + 1];
  const AngleFunction::RootKey key = detail::edgeFacetKey(
      !robotHinge, p.vertices[shared], p.vertices[shared + 1],
      {p.vertices[first + atP], p.vertices[first + 1 - atP], q.vertices[first + 1 - atQ]});
  return std::make_shared<AngleFunction>([x, a, b, from, to, robotHinge](auto type, int chart) {
    using T = typename decltype(type)::type;
    using detail::pointOf;
    const auto origin = pointOf<T>(x);
    const auto plane = detail::cross(detail::difference(pointOf<T>(a), origin), detail::difference(pointOf<T>(b), origin));
    const auto edge = detail::difference(pointOf<T>(to), pointOf<T>(from));
    // (R m) . v for a robot plane and an environment edge, (R u) . n the other way.
    return tangentPolynomial(robotHinge ? detail::rotatedDot(plane, edge) : detail::rotatedDot(edge, plane), chart);
  }, key);
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
/// its end 0): where the end lies along the other segment's direction. Zero only
/// for a shared end (the same spiral: two EE contacts with edges from one vertex
/// both end where it lies on the shared edge).
Sign alongSegment(const PatchGeometry& moving, int k, const PatchGeometry& fixed, int j, const AlgebraicAngle& angle,
                  AngleAlgebra& algebra) {
  if (moving.segment.ends[k] == fixed.segment.ends[j]) {
    algebra.statistics().recordIdentity(PredicateKind::SpiralFacet);
    return Sign::Zero;
  }
  const AngleFunction along([e = moving.ends[k], f = fixed.ends[j], f0 = fixed.ends[0], f1 = fixed.ends[1]](auto type,
                                                                                                        int chart) {
    using T = typename decltype(type)::type;
    return tangentPolynomial(spiralDifferenceDot(spiralOf<T>(e), spiralOf<T>(f), spiralOf<T>(f0), spiralOf<T>(f1)),
                             chart);
  });
  const Sign sign = algebra.signAt(along, angle);
  if (sign == Sign::Zero) throw std::logic_error("patchOverlaps: segment ends of coincident patches coincide");
  return sign;
}

/// Which ends of `fixed`'s segment the other segment reaches (runs up to or beyond),
/// at an angle where their lines coincide; nullopt when the segments do not overlap
/// (they may touch at a shared end).
std::optional<std::array<bool, 2>> endsReached(const PatchGeometry& fixed, const PatchGeometry& moving,
                                               const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  std::array<Sign, 2> fromStart{}, fromEnd{};
  for (int k = 0; k < 2; ++k) {
    fromStart[k] = alongSegment(moving, k, fixed, 0, angle, algebra);
    fromEnd[k] = alongSegment(moving, k, fixed, 1, angle, algebra);
  }
  const auto atOrBefore = [](Sign s) { return s != Sign::Positive; };
  const auto atOrAfter = [](Sign s) { return s != Sign::Negative; };
  if ((atOrBefore(fromStart[0]) && atOrBefore(fromStart[1])) || (atOrAfter(fromEnd[0]) && atOrAfter(fromEnd[1]))) {
    return std::nullopt;
  }
  return std::array<bool, 2>{atOrBefore(fromStart[0]) || atOrBefore(fromStart[1]),
                             atOrAfter(fromEnd[0]) || atOrAfter(fromEnd[1])};
}

/// Whether two edges (vertex index pairs) are one.
bool sameEdge(std::array<std::uint32_t, 2> e, std::array<std::uint32_t, 2> f) {
  return e == f || (e[0] == f[1] && e[1] == f[0]);
}

/// The vertex two edges share, if they share exactly one.
std::optional<int> sharedEnd(std::array<std::uint32_t, 2> e, std::array<std::uint32_t, 2> f) {
  if (sameEdge(e, f)) return std::nullopt;
  for (int i = 0; i < 2; ++i) {
    if (e[i] == f[0] || e[i] == f[1]) return i;
  }
  return std::nullopt;
}

/// The edge of `body` (0 robot, 1 environment) of an EE contact's points.
std::array<std::uint32_t, 2> edgeOf(const ContactPoints& line, int body) {
  return {line.vertices[2 * body], line.vertices[2 * body + 1]};
}

/// Two EE contacts that share one edge, whose other edges leave one vertex x, to a
/// and a': with the other edges' directions u, u' from x and the shared edge's
/// direction v, each line is "x + d lies on the plane through the shared edge
/// spanned by v and u (or u')", and when v lies in the plane of x, a, a' the two
/// planes are that plane: the lines coincide where det(v, u, u') = 0. For a shared
/// environment edge that is (R (u x u')) . v, for a shared robot edge (R u) . (v x
/// v'): an EF function of the shared edge and the plane (x, a, a'), keyed as one
/// (hingeCoincidence). When (x, a, a') is a triangle of the mesh, its roots are ends
/// of both ranges. Null for other pairs. EE points: robot edge a0 -> a1, environment
/// edge b0 -> b1.
std::shared_ptr<const AngleFunction> hingedCoincidence(const ContactPoints& p, const ContactPoints& q) {
  if (p.kind != ContactKind::EdgeEdge || q.kind != ContactKind::EdgeEdge) return nullptr;
  for (int shared = 0; shared < 2; ++shared) {
    if (!sameEdge(edgeOf(p, shared), edgeOf(q, shared))) continue;
    const int other = 1 - shared;  // the body whose edges differ
    const std::optional<int> atP = sharedEnd(edgeOf(p, other), edgeOf(q, other));
    if (!atP) return nullptr;  // the same two edges: one line at every angle
    const int atQ = q.vertices[2 * other] == p.vertices[2 * other + *atP] ? 0 : 1;
    return hingeCoincidence(p, *atP, q, atQ, other == 0);
  }
  return nullptr;
}

/// The function whose roots are the angles where two patches' lines coincide, for
/// the two structural kinds of pairs (PatchOverlap); null for other pairs. Contacts
/// of one facet with two vertices of the other body (shareFacet) have parallel lines
/// at every angle; the lines of hinged EE contacts coincide where the shared edge is
/// parallel to the plane of the other two (hingedCoincidence).
std::shared_ptr<const AngleFunction> coincidenceOfPair(const PatchGeometry& a, const PatchGeometry& b) {
  if (shareFacet(a.patch.contact, b.patch.contact)) return coincidence(a, b);
  return hingedCoincidence(a.line, b.line);
}

}  // namespace

std::vector<PatchOverlap> patchOverlaps(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra) {
  return patchOverlaps(patches, candidatePatchPairs(patches), algebra);
}

std::vector<PatchOverlap> patchOverlaps(const std::vector<PatchGeometry>& patches,
                                        const std::vector<std::pair<std::uint32_t, std::uint32_t>>& candidates,
                                        AngleAlgebra& algebra, const Cancellation& cancellation) {
  // Overlapping segments share points, so only pairs whose boxes meet can overlap.
  std::vector<PatchOverlap> overlaps;
  constexpr auto open = AngleAlgebra::Boundary::Excluded;
  for (const auto& [first, second] : candidates) {
    cancellation.check();
    const PatchGeometry &a = patches[first], &b = patches[second];
    const std::shared_ptr<const AngleFunction> coincident = coincidenceOfPair(a, b);
    if (!coincident) continue;
    for (const AlgebraicAngle& root : algebra.roots(coincident, PredicateKind::EdgeFacet)) {
      if (!algebra.contains(a.patch.range, root, open) || !algebra.contains(b.patch.range, root, open)) continue;
      const auto onA = endsReached(a, b, root, algebra);
      if (!onA) continue;
      overlaps.push_back({{first, second}, root, {*onA, *endsReached(b, a, root, algebra)}});
    }
  }
  // By pairs, each pair's roots in the order roots() gives them.
  std::stable_sort(overlaps.begin(), overlaps.end(),
                   [](const PatchOverlap& x, const PatchOverlap& y) { return x.patches < y.patches; });
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
                                       const std::vector<PatchOverlap>& overlaps, AngleAlgebra& algebra,
                                       const Cancellation& cancellation) {
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
    cancellation.check();
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
