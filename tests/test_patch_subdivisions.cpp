// Patch subdivisions against the exact slice geometry. At every slab's sample angle
// the slab's curves are exactly the patches whose segments cross the patch's segment
// (exact rationals), in increasing order along it. And two points of a patch's
// domain joined by a path at fixed lambda that meets none of the patch's curves
// (decided from the roots of the path's own SF functions) lie in one sub-face.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <optional>
#include <random>

#include "bundled_scene.h"
#include "exact_geometry.h"
#include "freespace/geometry/patch_subdivision.h"
#include "random_scene.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

bool strictlyOpposite(const Rational& a, const Rational& b) { return signOfRational(a) * signOfRational(b) < 0; }

/// Whether the segments of a and b at a rational angle whose parameter is a double
/// certainly do not cross (double intervals: a quick filter before exact slices).
bool certainlyApart(const PatchGeometry& a, const PatchGeometry& b, const AlgebraicAngle& angle) {
  if (angle.lower() != angle.upper()) return false;
  RoundingScope rounding;
  Interval cosine, sine;
  HalfAngle{angle.chart(), angle.lower()}.cosSin(cosine, sine);
  const auto oneSide = [&](const PatchGeometry& line, const PatchGeometry& segment) {
    const LineAtAngle<Interval> l = lineAtAngle(lineOf<Interval>(line.line), cosine, sine);
    std::array<std::optional<Sign>, 2> sides;
    for (int k = 0; k < 2; ++k) {
      const auto end = spiralPoint(spiralOf<Interval>(segment.ends[k]), cosine, sine);
      sides[k] = certainSign(l.nx * end[0] + l.ny * end[1] + l.w);
    }
    return sides[0] && sides[1] && (*sides[0] == *sides[1] || *sides[0] == Sign::Zero || *sides[1] == Sign::Zero);
  };
  return oneSide(a, b) || oneSide(b, a);
}

bool crossProperly(const ExactSlice& a, const ExactSlice& b) {
  return strictlyOpposite(b.valueAt(a.end0), b.valueAt(a.end1)) && strictlyOpposite(a.valueAt(b.end0), a.valueAt(b.end1));
}

/// Where b's line crosses a's segment, as lambda from a's end 0.
Rational crossingLambda(const ExactSlice& a, const ExactSlice& b) {
  const Rational v0 = b.valueAt(a.end0), v1 = b.valueAt(a.end1);
  return v0 / (v0 - v1);
}

struct SubdivisionCheck {
  int slabs = 0;
  int wrongSlabs = 0;    // slabs whose curves are not the crossing patches in lambda order
  int paths = 0;         // paths at fixed lambda that meet no curve and no overlap
  int splitPaths = 0;    // ... whose ends lie in different sub-faces
  int faces = 0;
};

/// `neighbours`: the patches whose boxes meet the patch's (candidatePatchPairs, a
/// superset of those that cross it, as the box test checks).
void checkSlabOrders(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                     std::uint32_t patch, const std::vector<std::uint32_t>& neighbours,
                     const PatchSubdivision& subdivision, AngleAlgebra& algebra, SubdivisionCheck& check) {
  for (const PatchSlab& slab : subdivision.slabs) {
    const ExactRotation r = rotationOf(slab.sample);
    const ExactSlice own = sliceOf(patches[patch], r);
    std::vector<std::uint32_t> crossing;
    for (std::uint32_t other : neighbours) {
      if (algebra.contains(patches[other].patch.range, slab.sample) &&
          !certainlyApart(patches[patch], patches[other], slab.sample) && crossProperly(own, sliceOf(patches[other], r))) {
        crossing.push_back(other);
      }
    }
    std::sort(crossing.begin(), crossing.end());
    std::vector<std::uint32_t> listed;
    bool increasing = true;
    for (std::size_t i = 0; i < slab.curves.size(); ++i) {
      listed.push_back(curves[slab.curves[i]].other(patch));
      if (i > 0) {
        increasing = increasing && crossingLambda(own, sliceOf(patches[listed[i - 1]], r)) <
                                       crossingLambda(own, sliceOf(patches[listed[i]], r));
      }
    }
    std::sort(listed.begin(), listed.end());
    check.slabs++;
    check.wrongSlabs += !(increasing && listed == crossing && slab.faces.size() == slab.curves.size() + 1);
  }
}

/// The point at `lambda` along the patch's segment as a moving point u + R v.
template <class T>
Spiral<T> pointAt(const PatchGeometry& patch, double lambda) {
  const Spiral<T> a = spiralOf<T>(patch.ends[0]), b = spiralOf<T>(patch.ends[1]);
  const T l(lambda), m = T(1) - l;
  return {m * a.ux + l * b.ux, m * a.uy + l * b.uy, m * a.vx + l * b.vx, m * a.vy + l * b.vy};
}

/// The SF function of the point at `lambda` along the patch's segment on another
/// patch's line: zero where a path at fixed lambda meets their curve.
std::shared_ptr<const AngleFunction> pointOnLine(const PatchGeometry& patch, double lambda,
                                                 const PatchGeometry& other) {
  return std::make_shared<AngleFunction>([patch, lambda, other](auto type, int chart) {
    using T = typename decltype(type)::type;
    return tangentPolynomial(spiralFacetForm(lineOf<T>(other.line), pointAt<T>(patch, lambda)), chart);
  });
}

/// (p - e_k) . (e_(1-k) - e_k) for the point p at `lambda` of the patch and the ends
/// e of the other's segment, all of the form u + R v: with x = p - e_k = u + R v and
/// y = e_(1-k) - e_k = a + R b, x . y = u . a + v . b + cos (u . b + a . v)
/// + sin ((u_y b_x - u_x b_y) + (a_y v_x - a_x v_y)). Positive for both k when p is
/// strictly inside the other segment (on its line).
AngleFunction insideOther(const PatchGeometry& patch, double lambda, const PatchGeometry& other, int k) {
  return AngleFunction([patch, lambda, other, k](auto type, int chart) {
    using T = typename decltype(type)::type;
    const Spiral<T> p = pointAt<T>(patch, lambda), e = spiralOf<T>(other.ends[k]), f = spiralOf<T>(other.ends[1 - k]);
    const T ux = p.ux - e.ux, uy = p.uy - e.uy, vx = p.vx - e.vx, vy = p.vy - e.vy;
    const T ax = f.ux - e.ux, ay = f.uy - e.uy, bx = f.vx - e.vx, by = f.vy - e.vy;
    return tangentPolynomial(TrigLinear<T>{(uy * bx - ux * by) + (ay * vx - ax * vy), ux * bx + uy * by + ax * vx + ay * vy,
                                           ux * ax + uy * ay + vx * bx + vy * by},
                             chart);
  });
}

/// Whether the path at `lambda` crosses the overlap's cut on the patch: the point is
/// inside (or at an end of) the other patch's segment at the overlap's angle.
bool crossesCut(const std::vector<PatchGeometry>& patches, std::uint32_t patch, const PatchOverlap& overlap,
                double lambda, AngleAlgebra& algebra) {
  const PatchGeometry& other = patches[overlap.patches[0] == patch ? overlap.patches[1] : overlap.patches[0]];
  for (int k = 0; k < 2; ++k) {
    if (algebra.signAt(insideOther(patches[patch], lambda, other, k), overlap.angle) == Sign::Negative) return false;
  }
  return true;
}

std::size_t gapAt(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                  std::uint32_t patch, const PatchSlab& slab, double lambda) {
  const ExactRotation r = rotationOf(slab.sample);
  const ExactSlice own = sliceOf(patches[patch], r);
  std::size_t gap = 0;
  for (std::uint32_t curve : slab.curves) {
    gap += crossingLambda(own, sliceOf(patches[curves[curve].other(patch)], r)) < Rational(lambda);
  }
  return gap;
}

bool slabsFollow(const PatchSubdivision& subdivision, std::size_t next, AngleAlgebra& algebra) {
  return algebra.compare(subdivision.slabs[next - 1].to, subdivision.slabs[next].from) == 0;
}

/// Paths at fixed lambda from one slab's sample to a later slab's sample of the same
/// arc (slabs follow one another while each one's `to` is the next one's `from`).
/// Paths that cross an overlap's cut are left out: the cut is an edge too.
void checkPaths(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                const std::vector<PatchOverlap>& overlapsOfPatch, std::uint32_t patch,
                const PatchSubdivision& subdivision, AngleAlgebra& algebra, std::mt19937_64& random,
                SubdivisionCheck& check) {
  std::vector<std::uint32_t> curvesOfPatch;
  for (std::uint32_t c = 0; c < curves.size(); ++c) {
    if (curves[c].first == patch || curves[c].second == patch) curvesOfPatch.push_back(c);
  }
  const std::size_t count = subdivision.slabs.size();
  for (std::size_t from = 0; from + 1 < count; ++from) {
    std::size_t to = from + 1;
    while (to + 1 < count && slabsFollow(subdivision, to + 1, algebra) &&
           std::uniform_int_distribution<int>(0, 1)(random)) {
      ++to;
    }
    bool follow = true;
    for (std::size_t k = from + 1; k <= to; ++k) follow = follow && slabsFollow(subdivision, k, algebra);
    if (!follow) continue;
    const double lambda = (1 + std::uniform_int_distribution<int>(0, 1022)(random)) / 1024.0;
    const AlgebraicAngle &start = subdivision.slabs[from].sample, &end = subdivision.slabs[to].sample;
    const AngleInterval path{start, end, algebra.compare(end, start) < 0};
    bool meets = false;
    for (const PatchOverlap& overlap : overlapsOfPatch) {
      meets = meets || (algebra.contains(path, overlap.angle) && crossesCut(patches, patch, overlap, lambda, algebra));
    }
    for (std::uint32_t c : curvesOfPatch) {
      const auto function = pointOnLine(patches[patch], lambda, patches[curves[c].other(patch)]);
      if (meets || function->isIdenticallyZero()) continue;
      for (const AlgebraicAngle& root : algebra.roots(function, PredicateKind::Other)) {
        meets = meets || (algebra.contains(path, root) && algebra.contains(curves[c].angles, root));
      }
    }
    if (meets) continue;
    check.paths++;
    const PatchSlab &first = subdivision.slabs[from], &last = subdivision.slabs[to];
    check.splitPaths += first.faces[gapAt(patches, curves, patch, first, lambda)] !=
                        last.faces[gapAt(patches, curves, patch, last, lambda)];
  }
}

SubdivisionCheck checkSubdivisions(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra) {
  const std::vector<PatchCurve> curves = patchCurves(patches, algebra);
  const std::vector<PatchOverlap> overlaps = patchOverlaps(patches, algebra);
  const std::vector<PatchVertex> vertices = patchVertices(patches, curves, overlaps, algebra);
  const std::vector<PatchSubdivision> subdivisions = patchSubdivisions(patches, curves, vertices, overlaps, algebra);
  std::vector<std::vector<std::uint32_t>> neighbours(patches.size());
  for (const auto& [a, b] : candidatePatchPairs(patches)) {
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  std::vector<std::vector<PatchOverlap>> overlapsOf(patches.size());
  for (const PatchOverlap& overlap : overlaps) {
    for (std::uint32_t patch : overlap.patches) overlapsOf[patch].push_back(overlap);
  }
  std::mt19937_64 random(3);
  SubdivisionCheck check;
  for (std::uint32_t patch = 0; patch < patches.size(); ++patch) {
    checkSlabOrders(patches, curves, patch, neighbours[patch], subdivisions[patch], algebra, check);
    checkPaths(patches, curves, overlapsOf[patch], patch, subdivisions[patch], algebra, random, check);
    check.faces += static_cast<int>(subdivisions[patch].faceCount);
  }
  return check;
}

}  // namespace

RC_GTEST_PROP(PatchSubdivision, SlabsAndSubFacesAgreeWithTheSlices, ()) {
  const std::unique_ptr<RandomScene> scene = randomCrowdedScene();
  RC_PRE(scene->hasDistinctHeights());
  const SubdivisionCheck check = checkSubdivisions(scene->allPatchGeometries(), scene->algebra);
  RC_ASSERT(check.wrongSlabs == 0);
  RC_ASSERT(check.splitPaths == 0);
  RC_TAG(check.paths > 0 ? "paths checked" : "no path");
}

class BundledSceneSubdivisions : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledSceneSubdivisions, SlabsAndSubFacesAgreeWithTheSlices) {
  BundledScene scene(GetParam());
  const SubdivisionCheck check = checkSubdivisions(scene.geometries, scene.algebra);
  EXPECT_GT(check.paths, 0);
  EXPECT_EQ(check.wrongSlabs, 0) << "of " << check.slabs << " slabs";
  EXPECT_EQ(check.splitPaths, 0) << "of " << check.paths << " paths";
  std::cout << GetParam() << ": " << check.slabs << " slabs, " << check.faces << " sub-faces, " << check.paths
            << " paths\n";
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledSceneSubdivisions,
                         ::testing::Values("cage.cfg", "keyhole.cfg", "keyhole_narrow.cfg", "turn_around.cfg",
                                           "random_polyhedra.cfg", "tetra_floorplan.cfg"));
