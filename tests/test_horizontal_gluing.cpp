// The gluing across horizontal edges read in double intervals at the edges' angles
// (slopes as first derivatives), and in double-double intervals where those leave an
// order open, against the exact reading at rational angles next to them: the same
// sub-faces glued, the same ones unmatched, on every bundled scene and on random
// crowded scenes.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>
#include <tuple>

#include "bundled_scene.h"
#include "freespace/topology/arrangement.h"
#include "random_scene.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

using GlueSet = std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>>;
using FaceSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

GlueSet gluesOf(const SubFaceGluing& gluing) {
  GlueSet glues;
  for (const SubFaceGlue& glue : gluing.glues) {
    glues.emplace(glue.first.patch, glue.first.face, glue.second.patch, glue.second.face);
  }
  return glues;
}

FaceSet unmatchedOf(const SubFaceGluing& gluing) {
  FaceSet faces;
  for (const SubFaceId& face : gluing.unmatched) faces.emplace(face.patch, face.face);
  return faces;
}

struct Comparison {
  std::size_t glues = 0, unmatched = 0;
  std::size_t edgesInIntervals = 0, edgesInDoubleDoubles = 0, edgesExact = 0;
  bool sameGlues = false, sameUnmatched = false;
};

Comparison compareReadings(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra) {
  const std::vector<PatchCurve> curves = patchCurves(patches, algebra);
  const std::vector<PatchOverlap> overlaps = patchOverlaps(patches, algebra);
  const std::vector<PatchVertex> vertices = patchVertices(patches, curves, overlaps, algebra);
  const std::vector<PatchSubdivision> subdivisions = patchSubdivisions(patches, curves, vertices, overlaps, algebra);
  constexpr int kDouble = static_cast<int>(PrecisionLevel::DoubleInterval),
                kDoubleDouble = static_cast<int>(PrecisionLevel::DoubleDouble),
                kExact = static_cast<int>(PrecisionLevel::Exact);
  const auto& edgeCounts = algebra.statistics().counts(PredicateKind::EdgeCrossSection).decided;
  const std::size_t doubleBefore = edgeCounts[kDouble], doubleDoubleBefore = edgeCounts[kDoubleDouble],
                    exactBefore = edgeCounts[kExact];
  const SubFaceGluing filtered =
      glueAcrossHorizontalEdges(patches, curves, overlaps, subdivisions, algebra, {}, EdgeReading::Filtered);
  Comparison comparison;
  comparison.edgesInIntervals = edgeCounts[kDouble] - doubleBefore;
  comparison.edgesInDoubleDoubles = edgeCounts[kDoubleDouble] - doubleDoubleBefore;
  comparison.edgesExact = edgeCounts[kExact] - exactBefore;
  const SubFaceGluing exact =
      glueAcrossHorizontalEdges(patches, curves, overlaps, subdivisions, algebra, {}, EdgeReading::Exact);
  comparison.glues = exact.glues.size();
  comparison.unmatched = exact.unmatched.size();
  comparison.sameGlues = gluesOf(filtered) == gluesOf(exact);
  comparison.sameUnmatched = unmatchedOf(filtered) == unmatchedOf(exact);
  return comparison;
}

class BundledSceneHorizontalGluing : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledSceneHorizontalGluing, IntervalReadingGluesAsTheExactOne) {
  BundledScene scene(GetParam());
  const Comparison comparison = compareReadings(scene.geometries, scene.algebra);
  std::cout << GetParam() << ": " << comparison.glues << " glues, " << comparison.unmatched << " unmatched; "
            << comparison.edgesInIntervals << " edges read in double intervals, " << comparison.edgesInDoubleDoubles
            << " in double-double intervals, " << comparison.edgesExact << " exactly\n";
  EXPECT_GT(comparison.glues, 0u);
  EXPECT_GT(comparison.edgesInIntervals, comparison.edgesExact);
  // Axis-aligned walls and coplanar tops leave some orders to double-doubles.
  EXPECT_GT(comparison.edgesInDoubleDoubles, 0u);
  EXPECT_TRUE(comparison.sameGlues);
  EXPECT_TRUE(comparison.sameUnmatched);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledSceneHorizontalGluing,
                         ::testing::Values("cage.cfg", "keyhole.cfg", "keyhole_narrow.cfg", "turn_around.cfg",
                                           "table.cfg", "table_tall.cfg", "overhang.cfg", "room_door.cfg",
                                           "random_polyhedra.cfg", "tetra_floorplan.cfg"));

}  // namespace

RC_GTEST_PROP(HorizontalGluing, IntervalReadingGluesAsTheExactOne, ()) {
  const std::unique_ptr<RandomScene> scene = randomCrowdedScene();
  RC_PRE(scene->hasDistinctHeights());
  const Comparison comparison = compareReadings(scene->allPatchGeometries(), scene->algebra);
  RC_ASSERT(comparison.sameGlues);
  RC_ASSERT(comparison.sameUnmatched);
  RC_TAG(comparison.edgesInIntervals > 0 ? "read in intervals" : "none in intervals");
  RC_TAG(comparison.edgesInDoubleDoubles > 0 ? "read in double-doubles" : "none in double-doubles");
}
