// Patch vertices against the slice: on patch f, the points where the segments of
// g and h cross f's segment (exact rationals at rational angles) swap their order
// along f exactly when the three lines pass through concurrency. So a reported
// vertex of (f, g, h) has the two crossings on either side of it in swapped order,
// and between two sample angles at which f crosses g and h, the order swaps exactly
// when an odd number of vertices of (f, g, h) lie between them.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <map>
#include <optional>

#include "bundled_scene.h"
#include "exact_geometry.h"
#include "freespace/geometry/patch_vertex.h"
#include "random_scene.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

using Triple = std::array<std::uint32_t, 3>;

int signOfRational(const Rational& value) { return value > 0 ? 1 : (value < 0 ? -1 : 0); }

struct ExactSlice {
  Rational nx, ny, w;  // the line n . d + w = 0
  std::array<Rational, 2> from, to;
};

ExactSlice sliceOf(const PatchGeometry& patch, const ExactRotation& r) {
  const PatchLine<Rational> line = lineOf<Rational>(patch.line);
  const LineAtAngle<Rational> at = lineAtAngle(line, r.cosine, r.sine);
  return {at.nx, at.ny, at.w, spiralPoint(spiralOf<Rational>(patch.ends[0]), r.cosine, r.sine),
          spiralPoint(spiralOf<Rational>(patch.ends[1]), r.cosine, r.sine)};
}

int side(const ExactSlice& line, const std::array<Rational, 2>& point) {
  return signOfRational(line.nx * point[0] + line.ny * point[1] + line.w);
}

/// Whether the two segments cross at a point inside both (no end on the other line).
bool crossProperly(const ExactSlice& a, const ExactSlice& b) {
  const int a0 = side(b, a.from), a1 = side(b, a.to), b0 = side(a, b.from), b1 = side(a, b.to);
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
  const IsolatingInterval t = angle.root();
  const Rational w = 1 + t.lo * t.lo;
  const Rational sign(angle.chart() == 0 ? 1 : -1);
  return crossingOrder(patches, triple, {sign * (1 - t.lo * t.lo) / w, sign * 2 * t.lo / w});
}

/// Soundness: at rational angles between each vertex and the nearest event on either
/// side (an end of the arcs of f's curves with g and h, or another vertex of the
/// three), f crosses g and h, in swapped order.
void checkEachVertexSwaps(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                          const std::vector<PatchVertex>& vertices, AngleAlgebra& algebra, VertexCheck& check) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, const PatchCurve*> curveOf;
  for (const PatchCurve& curve : curves) curveOf[{curve.first, curve.second}] = &curve;
  for (const PatchVertex& vertex : vertices) {
    const auto& [f, g, h] = vertex.patches;
    check.vertices++;
    if (!(f < g && g < h && curveOf.count({f, g}) && curveOf.count({f, h}))) {
      check.unsound++;
      continue;
    }
    std::vector<const AlgebraicAngle*> events;
    for (const PatchCurve* curve : {curveOf[{f, g}], curveOf[{f, h}]}) {
      for (const AngleInterval& arc : curve->angles.arcs) events.insert(events.end(), {&arc.from, &arc.to});
    }
    for (const PatchVertex& other : vertices) {
      if (&other != &vertex && other.patches == vertex.patches) events.push_back(&other.angle);
    }
    if (events.empty()) continue;  // two full circles and one vertex: nothing to compare with
    const AlgebraicAngle before = algebra.rationalBetween(*nearest(algebra, vertex.angle, events, true), vertex.angle);
    const AlgebraicAngle after = algebra.rationalBetween(vertex.angle, *nearest(algebra, vertex.angle, events, false));
    const auto orderBefore = crossingOrderAt(patches, vertex.patches, before);
    const auto orderAfter = crossingOrderAt(patches, vertex.patches, after);
    check.unsound += !(orderBefore && orderAfter && *orderBefore == -*orderAfter);
  }
}

/// Completeness: for every three patches with three curves, between consecutive
/// sample angles where f's curves with g and h both run on, the crossings swap
/// exactly when an odd number of the triple's vertices lie between the samples.
void checkSwapsBetweenSamples(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                              const std::vector<PatchVertex>& vertices, AngleAlgebra& algebra, VertexCheck& check) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, const PatchCurve*> curveOf;
  for (const PatchCurve& curve : curves) curveOf[{curve.first, curve.second}] = &curve;
  std::map<Triple, std::vector<const PatchVertex*>> verticesOf;
  for (const PatchVertex& vertex : vertices) verticesOf[vertex.patches].push_back(&vertex);
  constexpr int kSamples = 48;
  std::vector<AlgebraicAngle> samples;  // increasing in the cut order, from theta = -pi/2
  for (int k = 0; k < kSamples; ++k) {
    samples.push_back(AlgebraicAngle::rational(HalfAngle::fromRadians(-M_PI / 2 + (k + 0.37) * (2 * M_PI / kSamples))));
  }
  for (const auto& [pair, fg] : curveOf) {
    for (auto other = curveOf.upper_bound(pair); other != curveOf.end() && other->first.first == pair.first; ++other) {
      if (!curveOf.count({pair.second, other->first.second})) continue;
      const PatchCurve* fh = other->second;
      const Triple triple{pair.first, pair.second, other->first.second};
      for (int k = 0; k + 1 < kSamples; ++k) {
        const AlgebraicAngle &a = samples[k], &b = samples[k + 1];
        if (!coversGap(algebra, fg->angles, a, b) || !coversGap(algebra, fh->angles, a, b)) continue;
        const auto orderA = crossingOrderAt(patches, triple, a);
        const auto orderB = crossingOrderAt(patches, triple, b);
        int between = 0;
        for (const PatchVertex* vertex : verticesOf[triple]) {
          between += algebra.compare(a, vertex->angle) < 0 && algebra.compare(vertex->angle, b) < 0;
        }
        check.gaps++;
        check.missed += !(orderA && orderB && (*orderA != *orderB) == (between % 2 == 1));
        check.swaps += between;
      }
    }
  }
}

VertexCheck checkVertices(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra) {
  const std::vector<PatchCurve> curves = patchCurves(patches, algebra);
  const std::vector<PatchVertex> vertices = patchVertices(patches, curves, algebra);
  VertexCheck check;
  checkEachVertexSwaps(patches, curves, vertices, algebra, check);
  checkSwapsBetweenSamples(patches, curves, vertices, algebra, check);
  return check;
}

}  // namespace

RC_GTEST_PROP(PatchVertices, AreExactlyWhereTwoCrossingsOnAPatchSwap, ()) {
  const std::unique_ptr<RandomScene> scene = randomCrowdedScene();
  RC_PRE(scene->hasDistinctHeights());
  const std::vector<PatchGeometry> patches = patchGeometries(scene->allPatches(), scene->robot, scene->robotTopology,
                                                             scene->world, scene->worldTopology, scene->statistics);
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
  EXPECT_EQ(check.missed, 0) << "of " << check.gaps << " gaps";
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledSceneVertices, ::testing::Values("cage.cfg", "keyhole.cfg", "turn_around.cfg"));
