// Patch vertices against the slice: on patch f, the points where the segments of
// g and h cross f's segment (exact rationals at rational angles) swap their order
// along f exactly when the three lines pass through concurrency. So a reported
// vertex of (f, g, h) has the two crossings on either side of it in swapped order,
// and between two sample angles at which f crosses g and h, the order swaps exactly
// when an odd number of vertices of (f, g, h) lie between them.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <map>
#include <optional>

#include "bundled_scene.h"
#include "exact_geometry.h"
#include "freespace/geometry/patch_vertex.h"
#include "random_scene.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

/// Three patches (f, g, h) where f is the one whose crossings with g and h are
/// compared: a vertex's patches in increasing order, or for two parallel patches
/// with the crossing one first.
using Triple = std::array<std::uint32_t, 3>;

Triple orderedTriple(const PatchVertex& vertex) {
  if (vertex.crossing < 0) return vertex.patches;
  Triple triple{vertex.patches[vertex.crossing], 0, 0};
  int next = 1;
  for (int i = 0; i < 3; ++i) {
    if (i != vertex.crossing) triple[next++] = vertex.patches[i];
  }
  return triple;
}

int side(const ExactSlice& line, const std::array<Rational, 2>& point) {
  return signOfRational(line.valueAt(point));
}

/// Whether the two segments cross at a point inside both (no end on the other line).
bool crossProperly(const ExactSlice& a, const ExactSlice& b) {
  const int a0 = side(b, a.end0), a1 = side(b, a.end1), b0 = side(a, b.end0), b1 = side(a, b.end1);
  return a0 != 0 && a0 == -a1 && b0 != 0 && b0 == -b1;
}

/// Where the lines of a and b meet, as a multiple of a's direction (-n_y, n_x)
/// measured from the origin: only its order with another such value is used.
Rational positionAlong(const ExactSlice& a, const ExactSlice& b) {
  const Rational det = a.nx * b.ny - a.ny * b.nx;
  const Rational x = (a.ny * b.w - b.ny * a.w) / det, y = (b.nx * a.w - a.nx * b.w) / det;
  return -a.ny * x + a.nx * y;
}

/// The order along f of its crossings with g and h at the angle, when f crosses both
/// segments properly there; nullopt otherwise.
std::optional<int> crossingOrder(const std::vector<PatchGeometry>& patches, const Triple& triple,
                                 const ExactRotation& r) {
  const ExactSlice f = sliceOf(patches[triple[0]], r), g = sliceOf(patches[triple[1]], r),
                   h = sliceOf(patches[triple[2]], r);
  if (!crossProperly(f, g) || !crossProperly(f, h)) return std::nullopt;
  return signOfRational(positionAlong(f, h) - positionAlong(f, g));
}

/// Whether no end of an arc of the set lies strictly between the two rational
/// angles a < b (in the cut order), and the set contains both.
bool coversGap(AngleAlgebra& algebra, const AngleSet& set, const AlgebraicAngle& a, const AlgebraicAngle& b) {
  if (!algebra.contains(set, a) || !algebra.contains(set, b)) return false;
  for (const AngleInterval& arc : set.arcs) {
    for (const AlgebraicAngle* end : {&arc.from, &arc.to}) {
      if (algebra.compare(a, *end) < 0 && algebra.compare(*end, b) < 0) return false;
    }
  }
  return true;
}

/// What the oracle found: how many vertices were checked, how many were wrong, how
/// many gaps between sample angles were checked, in how many of them the order of
/// crossings disagreed with the vertices, and how many swaps they held.
struct VertexCheck {
  int vertices = 0;
  int unsound = 0;
  int gaps = 0;
  int parallelGaps = 0;  // gaps of triples with two parallel patches
  int missed = 0;
  int swaps = 0;
};

/// Among the candidates, the one reached first going clockwise (`backwards`) or
/// counterclockwise from `angle` (none equals it).
const AlgebraicAngle* nearest(AngleAlgebra& algebra, const AlgebraicAngle& angle,
                              const std::vector<const AlgebraicAngle*>& candidates, bool backwards) {
  // Distance along the circle in the direction, as (passes the cut, position).
  const auto closer = [&](const AlgebraicAngle* a, const AlgebraicAngle* b) {
    const int sideA = backwards ? algebra.compare(*a, angle) : algebra.compare(angle, *a);
    const int sideB = backwards ? algebra.compare(*b, angle) : algebra.compare(angle, *b);
    if ((sideA < 0) != (sideB < 0)) return sideA < 0;
    return backwards ? algebra.compare(*a, *b) > 0 : algebra.compare(*a, *b) < 0;
  };
  const AlgebraicAngle* best = nullptr;
  for (const AlgebraicAngle* candidate : candidates) {
    if (!best || closer(candidate, best)) best = candidate;
  }
  return best;
}

/// The order of f's crossings with g and h at a rational angle.
std::optional<int> crossingOrderAt(const std::vector<PatchGeometry>& patches, const Triple& triple,
                                   const AlgebraicAngle& angle) {
  return crossingOrder(patches, triple, rotationOf(angle));
}

/// Soundness: at rational angles between each vertex and the nearest event on either
/// side (an end of the arcs of f's curves with g and h, or another vertex of the
/// three), f crosses g and h, in swapped order (f: see Triple).
void checkEachVertexSwaps(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                          const std::vector<PatchVertex>& vertices, AngleAlgebra& algebra, VertexCheck& check) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, const PatchCurve*> curveOf;
  for (const PatchCurve& curve : curves) curveOf[{curve.first, curve.second}] = &curve;
  const auto curveOfPair = [&](std::uint32_t a, std::uint32_t b) { return curveOf[{std::min(a, b), std::max(a, b)}]; };
  for (const PatchVertex& vertex : vertices) {
    const Triple triple = orderedTriple(vertex);
    const auto& [f, g, h] = triple;
    check.vertices++;
    const bool sorted = vertex.patches[0] < vertex.patches[1] && vertex.patches[1] < vertex.patches[2];
    if (!(sorted && curveOfPair(f, g) && curveOfPair(f, h))) {
      check.unsound++;
      continue;
    }
    std::vector<const AlgebraicAngle*> events;
    for (const PatchCurve* curve : {curveOfPair(f, g), curveOfPair(f, h)}) {
      for (const AngleInterval& arc : curve->angles.arcs) events.insert(events.end(), {&arc.from, &arc.to});
    }
    for (const PatchVertex& other : vertices) {
      if (&other != &vertex && orderedTriple(other) == triple) events.push_back(&other.angle);
    }
    if (events.empty()) continue;  // two full circles and one vertex: nothing to compare with
    const AlgebraicAngle before = algebra.rationalBetween(*nearest(algebra, vertex.angle, events, true), vertex.angle);
    const AlgebraicAngle after = algebra.rationalBetween(vertex.angle, *nearest(algebra, vertex.angle, events, false));
    const auto orderBefore = crossingOrderAt(patches, triple, before);
    const auto orderAfter = crossingOrderAt(patches, triple, after);
    check.unsound += !(orderBefore && orderAfter && *orderBefore == -*orderAfter);
  }
}

/// Whether the two patches' lines are parallel at the rational angle (exactly).
bool parallelAt(const PatchGeometry& a, const PatchGeometry& b, const AlgebraicAngle& angle) {
  const ExactRotation r = rotationOf(angle);
  const ExactSlice x = sliceOf(a, r), y = sliceOf(b, r);
  return x.nx * y.ny - x.ny * y.nx == 0;
}

/// Completeness: for every three patches f, g, h where f has curves with g and h and
/// either g and h have a curve too (f the smallest) or their lines are parallel,
/// between consecutive sample angles where f's curves with g and h both run on, the
/// crossings swap exactly when an odd number of the triple's vertices lie between
/// the samples.
void checkSwapsBetweenSamples(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                              const std::vector<PatchVertex>& vertices, AngleAlgebra& algebra, VertexCheck& check) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, const PatchCurve*> curveOf;
  std::map<std::uint32_t, std::vector<std::uint32_t>> partners;
  for (const PatchCurve& curve : curves) {
    curveOf[{curve.first, curve.second}] = &curve;
    partners[curve.first].push_back(curve.second);
    partners[curve.second].push_back(curve.first);
  }
  const auto curveOfPair = [&](std::uint32_t a, std::uint32_t b) -> const PatchCurve* {
    const auto found = curveOf.find({std::min(a, b), std::max(a, b)});
    return found == curveOf.end() ? nullptr : found->second;
  };
  std::map<Triple, std::vector<const PatchVertex*>> verticesOf;
  for (const PatchVertex& vertex : vertices) verticesOf[orderedTriple(vertex)].push_back(&vertex);
  constexpr int kSamples = 48;
  std::vector<AlgebraicAngle> samples;  // increasing in the cut order, from theta = -pi/2
  for (int k = 0; k < kSamples; ++k) {
    samples.push_back(AlgebraicAngle::rational(HalfAngle::fromRadians(-M_PI / 2 + (k + 0.37) * (2 * M_PI / kSamples))));
  }
  for (auto& [f, around] : partners) {
    std::sort(around.begin(), around.end());
    for (std::size_t i = 0; i < around.size(); ++i) {
      for (std::size_t j = i + 1; j < around.size(); ++j) {
        const std::uint32_t g = around[i], h = around[j];
        const bool threeCurves = curveOfPair(g, h) != nullptr;
        if (threeCurves && f > g) continue;
        const Triple triple{f, g, h};
        const PatchCurve *fg = curveOfPair(f, g), *fh = curveOfPair(f, h);
        for (int k = 0; k + 1 < kSamples; ++k) {
          const AlgebraicAngle &a = samples[k], &b = samples[k + 1];
          if (!coversGap(algebra, fg->angles, a, b) || !coversGap(algebra, fh->angles, a, b)) continue;
          if (!threeCurves && !(parallelAt(patches[g], patches[h], a) && parallelAt(patches[g], patches[h], b))) continue;
          const auto orderA = crossingOrderAt(patches, triple, a);
          const auto orderB = crossingOrderAt(patches, triple, b);
          int between = 0;
          for (const PatchVertex* vertex : verticesOf[triple]) {
            between += algebra.compare(a, vertex->angle) < 0 && algebra.compare(vertex->angle, b) < 0;
          }
          check.gaps++;
          check.parallelGaps += !threeCurves;
          check.missed += !(orderA && orderB && (*orderA != *orderB) == (between % 2 == 1));
          check.swaps += between;
        }
      }
    }
  }
}

VertexCheck checkVertices(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra) {
  const std::vector<PatchCurve> curves = patchCurves(patches, algebra);
  const std::vector<PatchOverlap> overlaps = patchOverlaps(patches, algebra);
  const std::vector<PatchVertex> vertices = patchVertices(patches, curves, overlaps, algebra);
  VertexCheck check;
  checkEachVertexSwaps(patches, curves, vertices, algebra, check);
  checkSwapsBetweenSamples(patches, curves, vertices, algebra, check);
  return check;
}

}  // namespace

RC_GTEST_PROP(PatchVertices, AreExactlyWhereTwoCrossingsOnAPatchSwap, ()) {
  const std::unique_ptr<RandomScene> scene = randomCrowdedScene();
  RC_PRE(scene->hasDistinctHeights());
  const std::vector<PatchGeometry> patches = scene->allPatchGeometries();
  const VertexCheck check = checkVertices(patches, scene->algebra);
  RC_ASSERT(check.unsound == 0);
  RC_ASSERT(check.missed == 0);
  RC_TAG(check.vertices == 0 ? "no vertex" : "vertices");
  RC_TAG(check.swaps > 0 ? "swaps between samples" : "no swap between samples");
}

class BundledSceneVertices : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledSceneVertices, AreExactlyWhereTwoCrossingsOnAPatchSwap) {
  BundledScene scene(GetParam());
  const VertexCheck check = checkVertices(scene.geometries, scene.algebra);
  EXPECT_GT(check.vertices, 0);
  EXPECT_GT(check.swaps, 0);
  EXPECT_EQ(check.unsound, 0) << "of " << check.vertices << " vertices";
  EXPECT_EQ(check.missed, 0) << "of " << check.gaps << " gaps, " << check.parallelGaps << " of parallel patches";
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledSceneVertices,
                         ::testing::Values("cage.cfg", "keyhole.cfg", "overhang.cfg", "table.cfg", "turn_around.cfg"));

namespace {

/// Overlaps against the slice, at rational angles just before and just after each
/// overlap's angle (the ends of its isolating interval, narrowed). The lines pass
/// through each other there: every end of one segment that is not also an end of the
/// other (a shared end stays on both lines) changes side of the other's line. And the
/// ends of one segment lie along the other's direction as the overlap's flags say,
/// a shared end reaching the end it is. Returns how many overlaps disagree.
int wrongOverlaps(const std::vector<PatchGeometry>& patches, const std::vector<PatchOverlap>& overlaps) {
  int wrong = 0;
  for (const PatchOverlap& overlap : overlaps) {
    AlgebraicAngle narrow = overlap.angle;
    while (narrow.upper() - narrow.lower() > 1e-12 && narrow.refineInDoubles()) {
    }
    const ExactRotation before = rotationOf(AlgebraicAngle::rational(narrow.chart(), narrow.lower()));
    const ExactRotation after = rotationOf(AlgebraicAngle::rational(narrow.chart(), narrow.upper()));
    bool right = overlap.patches[0] < overlap.patches[1];
    for (int p = 0; p < 2; ++p) {
      const PatchGeometry &fixedPatch = patches[overlap.patches[p]], &movingPatch = patches[overlap.patches[1 - p]];
      const ExactSlice fixed = sliceOf(fixedPatch, before), moving = sliceOf(movingPatch, before);
      const ExactSlice fixedAfter = sliceOf(fixedPatch, after), movingAfter = sliceOf(movingPatch, after);
      const auto shared = [&](int k, int j) { return movingPatch.segment.ends[k] == fixedPatch.segment.ends[j]; };
      for (int k = 0; k < 2; ++k) {
        const std::array<Rational, 2>& end = k == 0 ? moving.end0 : moving.end1;
        const std::array<Rational, 2>& endAfter = k == 0 ? movingAfter.end0 : movingAfter.end1;
        if (!shared(k, 0) && !shared(k, 1)) right = right && side(fixed, end) * side(fixedAfter, endAfter) < 0;
      }
      const Rational dx = fixed.end1[0] - fixed.end0[0], dy = fixed.end1[1] - fixed.end0[1];
      const auto along = [&](const std::array<Rational, 2>& point, const std::array<Rational, 2>& from) {
        return (point[0] - from[0]) * dx + (point[1] - from[1]) * dy;
      };
      const bool beforeStart = along(moving.end0, fixed.end0) < 0 || along(moving.end1, fixed.end0) < 0 ||
                               shared(0, 0) || shared(1, 0);
      const bool afterEnd = along(moving.end0, fixed.end1) > 0 || along(moving.end1, fixed.end1) > 0 || shared(0, 1) ||
                            shared(1, 1);
      right = right && beforeStart == overlap.reachesEnd[p][0] && afterEnd == overlap.reachesEnd[p][1];
    }
    wrong += !right;
  }
  return wrong;
}

}  // namespace

RC_GTEST_PROP(PatchOverlaps, ReachTheEndsTheOtherSegmentRunsBeyond, ()) {
  const std::unique_ptr<RandomScene> scene = randomCrowdedScene();
  RC_PRE(scene->hasDistinctHeights());
  const std::vector<PatchGeometry> patches = scene->allPatchGeometries();
  const std::vector<PatchOverlap> overlaps = patchOverlaps(patches, scene->algebra);
  RC_ASSERT(wrongOverlaps(patches, overlaps) == 0);
  RC_TAG(overlaps.empty() ? "no overlap" : "overlaps");
}

TEST(PatchOverlaps, BundledScenesReachTheEndsTheOtherSegmentRunsBeyond) {
  for (const char* name : {"cage.cfg", "turn_around.cfg", "table.cfg"}) {
    BundledScene scene(name);
    const std::vector<PatchOverlap> overlaps = patchOverlaps(scene.geometries, scene.algebra);
    EXPECT_GT(overlaps.size(), 0u) << name;
    // Of both kinds: two contacts with one facet, and two EE contacts hinged at one edge.
    const auto hinged = std::count_if(overlaps.begin(), overlaps.end(), [&](const PatchOverlap& overlap) {
      return scene.geometries[overlap.patches[0]].patch.contact.kind == ContactKind::EdgeEdge;
    });
    EXPECT_GT(hinged, 0) << name;
    EXPECT_LT(hinged, static_cast<long>(overlaps.size())) << name;
    EXPECT_EQ(wrongOverlaps(scene.geometries, overlaps), 0) << name << ", of " << overlaps.size();
  }
}
