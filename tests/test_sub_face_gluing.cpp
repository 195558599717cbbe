// Gluing of sub-faces against the exact slice at the glue's angle. For a glue across
// a curve of f and g (or around a spiral), there are points just off the two glued
// sub-faces, on their positive sides, next to the crossing point (or the spiral's
// point), such that each point lies in the glued sub-face's trapezoid of its patch
// (exact crossing positions along the segment) and the straight path between them
// meets no active segment (exact). A wrong half of a patch puts the path across one
// of the two patches' segments at every distance.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <optional>

#include "bundled_scene.h"
#include "exact_geometry.h"
#include "freespace/topology/sub_face_gluing.h"
#include "random_scene.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

using Point = std::array<Rational, 2>;

/// Off-points are tried at distances 2^-10, 2^-14, ... down to this from the glued
/// point: near-degenerate slabs put other segments within 1e-15 of it.
const Rational kSmallestDelta = [] {
  Rational delta(1);
  for (int i = 0; i < 160; ++i) delta /= 2;
  return delta;
}();

int sideOf(const ExactSlice& s, const Point& p) { return signOfRational(s.valueAt(p)); }

/// Whether the closed segment pq meets the segment of s (exact orientation tests).
bool meets(const Point& p, const Point& q, const ExactSlice& s) {
  const ExactPoint2 a{p[0], p[1]}, b{q[0], q[1]}, c{s.end0[0], s.end0[1]}, d{s.end1[0], s.end1[1]};
  const int abc = orientation(a, b, c), abd = orientation(a, b, d), cda = orientation(c, d, a), cdb = orientation(c, d, b);
  return abc * abd <= 0 && cda * cdb <= 0 && !(abc == 0 && abd == 0 && cda == 0 && cdb == 0);
}

Point along(const Point& from, const Point& direction, const Rational& scale) {
  return {from[0] + scale * direction[0], from[1] + scale * direction[1]};
}

/// The sub-face of `patch` at point p of its segment (p on its line) in `slab`.
std::uint32_t faceAt(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                     std::uint32_t patch, const PatchSlab& slab, const ExactRotation& r, const Point& p) {
  const ExactSlice own = sliceOf(patches[patch], r);
  std::size_t gap = 0;
  for (std::uint32_t curve : slab.curves) {
    const std::uint32_t other = curves[curve].other(patch);
    const ExactSlice s = sliceOf(patches[other], r);
    // p is past the crossing when it is on the side of s's line opposite end 0.
    gap += sideOf(s, p) != sideOf(s, own.end0);
  }
  return slab.faces[gap];
}

struct GlueCheck {
  int curveGlues = 0;
  int spiralGlues = 0;
  int wrong = 0;
};

/// The active segments at a rational angle, with double boxes (padded far beyond
/// rounding) to skip the exact test for segments far from a path.
class SliceAt {
 public:
  SliceAt(const std::vector<PatchGeometry>& patches, const AlgebraicAngle& angle, AngleAlgebra& algebra)
      : rotation(rotationOf(angle)) {
    const double c = rotation.cosine.convert_to<double>(), s = rotation.sine.convert_to<double>();
    for (std::uint32_t i = 0; i < patches.size(); ++i) {
      if (!algebra.contains(patches[i].patch.range, angle)) continue;
      const auto e0 = spiralPoint(spiralOf<double>(patches[i].ends[0]), c, s);
      const auto e1 = spiralPoint(spiralOf<double>(patches[i].ends[1]), c, s);
      active.push_back({i, {std::min(e0[0], e1[0]) - kPad, std::min(e0[1], e1[1]) - kPad},
                        {std::max(e0[0], e1[0]) + kPad, std::max(e0[1], e1[1]) + kPad}});
    }
  }
  bool clear(const std::vector<PatchGeometry>& patches, const std::vector<Point>& path) const {
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const double x0 = path[i][0].convert_to<double>(), y0 = path[i][1].convert_to<double>();
      const double x1 = path[i + 1][0].convert_to<double>(), y1 = path[i + 1][1].convert_to<double>();
      for (const Active& a : active) {
        if (std::max(x0, x1) < a.low[0] || std::min(x0, x1) > a.high[0] || std::max(y0, y1) < a.low[1] ||
            std::min(y0, y1) > a.high[1]) {
          continue;
        }
        if (meets(path[i], path[i + 1], sliceOf(patches[a.patch], rotation))) return false;
      }
    }
    return true;
  }
  ExactRotation rotation;

 private:
  static constexpr double kPad = 1e-6;
  struct Active {
    std::uint32_t patch;
    std::array<double, 2> low, high;
  };
  std::vector<Active> active;
};

/// A point of patch's segment at distance ~delta from `from` toward `toward`,
/// pushed delta^2 to the positive side.
Point offPoint(const ExactSlice& s, const Point& from, const Point& direction, const Rational& delta) {
  return along(along(from, direction, delta), {s.nx, s.ny}, delta * delta);
}

bool curveGlueHolds(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                    const std::vector<PatchSubdivision>& subdivisions, const SubFaceGlue& glue, AngleAlgebra& algebra) {
  const SliceAt slice(patches, glue.at, algebra);
  const std::uint32_t f = glue.first.patch, g = glue.second.patch;
  const ExactSlice sf = sliceOf(patches[f], slice.rotation), sg = sliceOf(patches[g], slice.rotation);
  // The crossing of the two lines (Cramer's rule).
  const Rational det = sf.nx * sg.ny - sf.ny * sg.nx;
  const Point x{(sf.ny * sg.w - sg.ny * sf.w) / det, (sg.nx * sf.w - sf.nx * sg.w) / det};
  const Point df{sf.end1[0] - sf.end0[0], sf.end1[1] - sf.end0[1]}, dg{sg.end1[0] - sg.end0[0], sg.end1[1] - sg.end0[1]};
  const PatchSlab *slabF = slabAt(subdivisions[f], glue.at, algebra), *slabG = slabAt(subdivisions[g], glue.at, algebra);
  if (!slabF || !slabG) return false;
  for (Rational delta(1, 1024); delta > kSmallestDelta; delta /= 16) {
    for (int hf : {-1, 1}) {
      for (int hg : {-1, 1}) {
        const Point a = offPoint(sf, x, {hf * df[0], hf * df[1]}, delta);
        const Point b = offPoint(sg, x, {hg * dg[0], hg * dg[1]}, delta);
        const Point onF = along(x, {hf * df[0], hf * df[1]}, delta), onG = along(x, {hg * dg[0], hg * dg[1]}, delta);
        if (faceAt(patches, curves, f, *slabF, slice.rotation, onF) != glue.first.face) continue;
        if (faceAt(patches, curves, g, *slabG, slice.rotation, onG) != glue.second.face) continue;
        if (slice.clear(patches, {a, b})) return true;
      }
    }
  }
  return false;
}

bool spiralGlueHolds(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                     const std::vector<PatchSubdivision>& subdivisions, const SubFaceGlue& glue, AngleAlgebra& algebra) {
  const SliceAt slice(patches, glue.at, algebra);
  const std::uint32_t a = glue.first.patch, b = glue.second.patch;
  const ExactSlice sa = sliceOf(patches[a], slice.rotation), sb = sliceOf(patches[b], slice.rotation);
  const PatchSlab *slabA = slabAt(subdivisions[a], glue.at, algebra), *slabB = slabAt(subdivisions[b], glue.at, algebra);
  if (!slabA || !slabB) return false;
  for (int ka = 0; ka < 2; ++ka) {
    for (int kb = 0; kb < 2; ++kb) {
      if (!(patches[a].segment.ends[ka] == patches[b].segment.ends[kb])) continue;
      const Point p = ka == 0 ? sa.end0 : sa.end1;
      const Point qa = ka == 0 ? sa.end1 : sa.end0, qb = kb == 0 ? sb.end1 : sb.end0;
      const Point ua{qa[0] - p[0], qa[1] - p[1]}, ub{qb[0] - p[0], qb[1] - p[1]};
      for (Rational delta(1, 1024); delta > kSmallestDelta; delta /= 16) {
        const Point onA = along(p, ua, delta), onB = along(p, ub, delta);
        if (faceAt(patches, curves, a, *slabA, slice.rotation, onA) != glue.first.face) continue;
        if (faceAt(patches, curves, b, *slabB, slice.rotation, onB) != glue.second.face) continue;
        const Point pa = offPoint(sa, p, ua, delta), pb = offPoint(sb, p, ub, delta);
        // Around the point through the sector's inside (a sector wider than a half
        // turn): a quarter turn from each spoke toward its positive side, then across.
        const Point turnA = along(p, {sa.nx, sa.ny}, delta), turnB = along(p, {sb.nx, sb.ny}, delta);
        if (slice.clear(patches, {pa, pb}) || slice.clear(patches, {pa, turnA, turnB, pb})) return true;
      }
    }
  }
  return false;
}

GlueCheck checkGlues(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra) {
  const std::vector<PatchCurve> curves = patchCurves(patches, algebra);
  const std::vector<PatchOverlap> overlaps = patchOverlaps(patches, algebra);
  const std::vector<PatchVertex> vertices = patchVertices(patches, curves, overlaps, algebra);
  const std::vector<PatchSubdivision> subdivisions = patchSubdivisions(patches, curves, vertices, overlaps, algebra);
  GlueCheck check;
  for (const SubFaceGlue& glue : glueAcrossCurves(patches, curves, subdivisions, algebra).glues) {
    check.curveGlues++;
    check.wrong += !curveGlueHolds(patches, curves, subdivisions, glue, algebra);
  }
  for (const SubFaceGlue& glue : glueAroundSpirals(patches, subdivisions, algebra).glues) {
    check.spiralGlues++;
    check.wrong += !spiralGlueHolds(patches, curves, subdivisions, glue, algebra);
  }
  return check;
}

}  // namespace

RC_GTEST_PROP(SubFaceGluing, GluedSidesFaceOneRegionOfTheSlice, ()) {
  const std::unique_ptr<RandomScene> scene = randomCrowdedScene();
  RC_PRE(scene->hasDistinctHeights());
  const GlueCheck check = checkGlues(scene->allPatchGeometries(), scene->algebra);
  RC_ASSERT(check.wrong == 0);
  RC_TAG(check.curveGlues + check.spiralGlues > 0 ? "glues" : "no glue");
}

class BundledSceneGluing : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledSceneGluing, GluedSidesFaceOneRegionOfTheSlice) {
  BundledScene scene(GetParam());
  const GlueCheck check = checkGlues(scene.geometries, scene.algebra);
  EXPECT_GT(check.curveGlues, 0);
  EXPECT_GT(check.spiralGlues, 0);
  EXPECT_EQ(check.wrong, 0) << "of " << check.curveGlues + check.spiralGlues << " glues";
  std::cout << GetParam() << ": " << check.curveGlues << " glues across curves, " << check.spiralGlues
            << " around spirals\n";
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledSceneGluing, ::testing::Values("cage.cfg", "turn_around.cfg"));
