// Patch curves against the slice: at rational angles, two active patches' segments
// (exact rational end points) cross properly exactly when a curve of the pair
// contains the angle. Every pair of patches is checked, so the candidate pairs from
// the bounding boxes are checked too.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "exact_geometry.h"
#include "freespace/geometry/patch_curve.h"
#include "random_scene.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

std::array<ExactPoint2, 2> segmentAt(const PatchGeometry& patch, const ExactRotation& r) {
  std::array<ExactPoint2, 2> ends;
  for (int e = 0; e < 2; ++e) {
    const auto point = spiralPoint(spiralOf<Rational>(patch.ends[e]), r.cosine, r.sine);
    ends[e] = {point[0], point[1]};
  }
  return ends;
}

}  // namespace

RC_GTEST_PROP(PatchCurves, ContainExactlyTheAnglesWhereTwoSegmentsCross, ()) {
  const std::unique_ptr<RandomScene> scene = randomTwoObstacleScene();
  RC_PRE(scene->hasDistinctHeights());
  const std::vector<Patch> patches = scene->allPatches();
  const std::vector<PatchGeometry> geometries = patchGeometries(patches, scene->robot, scene->robotTopology,
                                                                scene->world, scene->worldTopology, scene->statistics);
  std::map<std::pair<std::uint32_t, std::uint32_t>, const PatchCurve*> curveOf;
  const std::vector<PatchCurve> curves = patchCurves(geometries, scene->algebra);
  for (const PatchCurve& curve : curves) curveOf[{curve.first, curve.second}] = &curve;

  int crossings = 0;
  for (int k = 0; k < 16; ++k) {
    const double theta = -M_PI + (k + 0.37) * (2 * M_PI / 16);
    const AlgebraicAngle angle = AlgebraicAngle::rational(HalfAngle::fromRadians(theta));
    const ExactRotation r = rotationAt(theta);
    std::vector<std::uint32_t> active;
    for (std::uint32_t i = 0; i < geometries.size(); ++i) {
      if (scene->algebra.contains(patches[i].range, angle)) active.push_back(i);
    }
    for (std::size_t i = 0; i < active.size(); ++i) {
      const auto a = segmentAt(geometries[active[i]], r);
      for (std::size_t j = i + 1; j < active.size(); ++j) {
        const auto b = segmentAt(geometries[active[j]], r);
        const int a0 = orientation(b[0], b[1], a[0]), a1 = orientation(b[0], b[1], a[1]);
        const int b0 = orientation(a[0], a[1], b[0]), b1 = orientation(a[0], a[1], b[1]);
        if (a0 == 0 || a1 == 0 || b0 == 0 || b1 == 0) continue;  // touching: a curve's end, or shared ends
        const bool cross = a0 == -a1 && b0 == -b1;
        const auto found = curveOf.find({active[i], active[j]});
        const bool inCurve = found != curveOf.end() && scene->algebra.contains(found->second->angles, angle);
        RC_ASSERT(cross == inCurve);
        crossings += cross;
      }
    }
  }
  RC_TAG(crossings > 0 ? "crossing segments" : "no crossing");
}

namespace {

/// The exact polynomial, in the chart, of (R a) . b = cos (a . b)_xy + sin (a x b)_xy
/// + a_z b_z, straight from the definition.
RationalPolynomial rotatedDotPolynomial(const Exact3& a, const Exact3& b, int chart) {
  return tangentPolynomial(TrigLinear<Rational>{a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y, a.z * b.z}, chart);
}

bool proportional(const RationalPolynomial& p, const RationalPolynomial& q) {
  const auto &a = p.coefficients(), &b = q.coefficients();
  const std::size_t size = std::max(a.size(), b.size());
  const auto at = [](const std::vector<Rational>& c, std::size_t i) { return i < c.size() ? c[i] : Rational(0); };
  bool anyNonzero = false;
  for (std::size_t i = 0; i < size; ++i) {
    anyNonzero = anyNonzero || at(a, i) != 0;
    for (std::size_t j = 0; j < size; ++j) {
      if (at(a, i) * at(b, j) != at(a, j) * at(b, i)) return false;
    }
  }
  return anyNonzero;
}

/// The EF function a key names (edgeFacetKey): (R (x - y)) . n for robot vertices x,
/// y and the normal n of an environment plane, or (R m) . (x - y) for environment
/// vertices and a robot plane.
RationalPolynomial keyedPolynomial(const AngleFunction::RootKey& key, const Mesh& robot, const Mesh& world, int chart) {
  const bool robotPair = key[0] == 0;
  const Mesh& pairMesh = robotPair ? robot : world;
  const Mesh& planeMesh = robotPair ? world : robot;
  const Exact3 difference = minus(exactPoint(pairMesh.vertices()[key[1]]), exactPoint(pairMesh.vertices()[key[2]]));
  const Exact3 p0 = exactPoint(planeMesh.vertices()[key[3]]);
  const Exact3 normal = cross(minus(exactPoint(planeMesh.vertices()[key[4]]), p0),
                              minus(exactPoint(planeMesh.vertices()[key[5]]), p0));
  return robotPair ? rotatedDotPolynomial(difference, normal, chart) : rotatedDotPolynomial(normal, difference, chart);
}

}  // namespace

RC_GTEST_PROP(PatchCurves, KeyedSpiralFacetFunctionsAreTheirKeysEdgeFacetFunctions, ()) {
  // EF keys (kind 0 or 1) name an EF function; the others name the SF function's
  // own inputs. A function that vanishes identically is zero by its formula.
  const std::unique_ptr<RandomScene> scene = randomTwoObstacleScene();
  RC_PRE(scene->hasDistinctHeights());
  const std::vector<PatchGeometry> patches = scene->allPatchGeometries();
  int keyed = 0, zero = 0;
  for (const PatchGeometry& line : patches) {
    for (const PatchGeometry& other : patches) {
      for (int k = 0; k < 2; ++k) {
        const auto function = spiralOnLine(line.line, other.ends[k], other.segment.ends[k]);
        if (function->isIdenticallyZero()) {
          // A patch's line at its own end, say (or a key that names the zero
          // function): the SF formula itself must vanish.
          for (int chart = 0; chart < 2; ++chart) {
            const RationalPolynomial formula = tangentPolynomial(
                spiralFacetForm(lineOf<Rational>(line.line), spiralOf<Rational>(other.ends[k])), chart);
            RC_ASSERT(isZero(trimmed(formula)));
          }
          zero++;
          continue;
        }
        const AngleFunction::RootKey& key = *function->key();
        if (key[0] > 1) continue;
        keyed++;
        for (int chart = 0; chart < 2; ++chart) {
          RC_ASSERT(proportional(function->exact(chart), keyedPolynomial(key, scene->robot, scene->world, chart)));
        }
      }
    }
  }
  RC_TAG(keyed > 0 ? "keyed functions" : "no keyed function");
  RC_TAG(zero > 0 ? "zero functions" : "no zero function");
}
