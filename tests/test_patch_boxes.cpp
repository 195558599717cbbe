// Patch boxes against the exact segments: at rational angles inside each arc of a
// patch's range, down to the ends of the arc (where the narrowed enclosures of its
// end angles stop), both segment ends (exact rationals) lie in one of the patch's
// boxes, angle included. A box that misses part of a patch loses candidate pairs and
// so curves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "bundled_scene.h"
#include "exact_geometry.h"
#include "freespace/geometry/patch_box_index.h"
#include "freespace/geometry/patch_geometry.h"
#include "freespace/geometry/perturbed_meshes.h"
#include "freespace/numbers/half_angle.h"
#include "random_scene.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

bool inBox(const PatchBox& box, const std::array<Rational, 2>& point, double theta) {
  return box.low[2] <= theta && theta <= box.high[2] && box.low[0] <= point[0] && point[0] <= box.high[0] &&
         box.low[1] <= point[1] && point[1] <= box.high[1];
}

/// Rational angles inside the arc next to its ends: the inner end of each end
/// angle's enclosure, narrowed in doubles as far as it goes, when it is inside.
std::vector<AlgebraicAngle> nearEnds(const AngleInterval& arc, AngleAlgebra& algebra) {
  std::vector<AlgebraicAngle> angles{algebra.rationalBetween(arc.from, arc.to)};
  for (int end = 0; end < 2; ++end) {
    AlgebraicAngle narrow = end == 0 ? arc.from : arc.to;
    while (narrow.refineInDoubles()) {
    }
    const AlgebraicAngle inner = AlgebraicAngle::rational(narrow.chart(), end == 0 ? narrow.upper() : narrow.lower());
    if (algebra.contains(arc, inner, AngleAlgebra::Boundary::Excluded)) angles.push_back(inner);
  }
  return angles;
}

/// Rational angles spread over the open arc: `count` at equal steps in radians.
std::vector<AlgebraicAngle> acrossArc(const AngleInterval& arc, int count, AngleAlgebra& algebra) {
  const double from = arc.from.radians();
  double to = arc.to.radians();
  if (to < from) to += 2 * M_PI;  // through theta = pi
  std::vector<AlgebraicAngle> angles;
  for (int i = 0; i < count; ++i) {
    const AlgebraicAngle angle = AlgebraicAngle::rational(HalfAngle::fromRadians(from + (to - from) * (i + 0.5) / count));
    if (algebra.contains(arc, angle, AngleAlgebra::Boundary::Excluded)) angles.push_back(angle);
  }
  return angles;
}

/// Checks that the boxes hold both segment ends (exact) at each angle, angle
/// included; counts the angles checked and those left outside.
struct Coverage {
  int checked = 0, outside = 0;

  void check(const std::vector<PatchBox>& boxes, const PatchGeometry& patch, const AlgebraicAngle& angle) {
    const ExactRotation r = rotationOf(angle);
    const double theta = HalfAngle{angle.chart(), angle.lower()}.radians();
    const auto end0 = spiralPoint(spiralOf<Rational>(patch.ends[0]), r.cosine, r.sine);
    const auto end1 = spiralPoint(spiralOf<Rational>(patch.ends[1]), r.cosine, r.sine);
    const bool covered = std::any_of(boxes.begin(), boxes.end(), [&](const PatchBox& box) {
      return inBox(box, end0, theta) && inBox(box, end1, theta);
    });
    checked++;
    outside += !covered;
  }
};

bool anyMeet(const std::vector<PatchBox>& first, const std::vector<PatchBox>& second) {
  return std::any_of(first.begin(), first.end(), [&](const PatchBox& a) {
    return std::any_of(second.begin(), second.end(), [&](const PatchBox& b) {
      for (int axis = 0; axis < 3; ++axis) {
        if (a.high[axis] < b.low[axis] || b.high[axis] < a.low[axis]) return false;
      }
      return true;
    });
  });
}

/// Checks the index's pairs and queries against the patches' boxes compared one by
/// one: a pair when an arc box of each meet and a piece of each meet.
void expectPairsOfMeetingBoxes(const std::vector<PatchGeometry>& geometries) {
  std::vector<std::vector<PatchBox>> arcs, pieces;
  for (const PatchGeometry& patch : geometries) {
    arcs.push_back(patchBoxes(patch));
    pieces.push_back(patchBoxes(patch, PatchBoxIndex::kPieceWidth));
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::uint32_t a = 0; a < arcs.size(); ++a) {
    for (std::uint32_t b = a + 1; b < arcs.size(); ++b) {
      if (anyMeet(arcs[a], arcs[b]) && anyMeet(pieces[a], pieces[b])) expected.emplace_back(a, b);
    }
  }
  EXPECT_GT(expected.size(), geometries.size());
  const PatchBoxIndex index(geometries);
  EXPECT_EQ(index.meetingPairs(), expected);
  const auto expectMeeting = [&](const PatchBox& box) {
    std::vector<std::uint32_t> meeting;
    for (std::uint32_t patch = 0; patch < arcs.size(); ++patch) {
      if (anyMeet(arcs[patch], {box}) && anyMeet(pieces[patch], {box})) meeting.push_back(patch);
    }
    EXPECT_EQ(index.meeting(box), meeting)
        << box.low[0] << " " << box.high[0] << " " << box.low[1] << " " << box.high[1] << " " << box.low[2] << " "
        << box.high[2];
  };
  // Queries: the arc boxes of every third patch; small boxes about points of pieces
  // at one angle (as clearances ask), near theta = +-pi too; boxes reaching past the
  // index's square, or without bounds.
  for (std::size_t query = 0; query < arcs.size(); query += 3) {
    for (const PatchBox& box : arcs[query]) expectMeeting(box);
    const PatchBox& piece = pieces[query].front();
    for (const double theta : {0.5 * (piece.low[2] + piece.high[2]), M_PI - 1e-9, -M_PI + 1e-9}) {
      const double x = 0.5 * (piece.low[0] + piece.high[0]), y = 0.5 * (piece.low[1] + piece.high[1]);
      expectMeeting({{x - 0.01, y - 0.01, theta - 1e-9}, {x + 0.01, y + 0.01, theta + 1e-9}});
    }
  }
  const PatchBoxIndex::Scales& scales = index.scales();
  expectMeeting({{scales.low - scales.side, scales.low - scales.side, -M_PI},
                 {scales.low + 0.5 * scales.side, scales.low + 2 * scales.side, 0}});
  expectMeeting({{scales.low + 2 * scales.side, scales.low, -M_PI}, {scales.low + 3 * scales.side, scales.low, M_PI}});
  const double most = std::numeric_limits<double>::max();
  expectMeeting({{-most, -most, -1}, {most, most, 1}});
}

}  // namespace

class BundledScenePatchBoxes : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledScenePatchBoxes, ContainTheSegmentsUpToTheRangeEnds) {
  BundledScene scene(GetParam());
  Coverage coverage;
  for (const PatchGeometry& patch : scene.geometries) {
    const std::vector<PatchBox> boxes = patchBoxes(patch);
    for (const AngleInterval& arc : patch.patch.range.arcs) {
      for (const AlgebraicAngle& angle : nearEnds(arc, scene.algebra)) coverage.check(boxes, patch, angle);
    }
  }
  EXPECT_GT(coverage.checked, 0);
  EXPECT_EQ(coverage.outside, 0) << "of " << coverage.checked << " angles";
}

// Boxes over narrow pieces of the arcs (as the box index refines with): at angles
// spread over each arc and next to its ends, each piece and the whole set.
TEST_P(BundledScenePatchBoxes, PiecesContainTheSegments) {
  BundledScene scene(GetParam());
  for (const double width : {PatchBoxIndex::kPieceWidth, 0.05}) {
    Coverage coverage;
    for (const PatchGeometry& patch : scene.geometries) {
      const std::vector<PatchBox> pieces = patchBoxes(patch, width);
      for (const PatchBox& piece : pieces) EXPECT_LE(piece.high[2] - piece.low[2], width + 1e-6);
      for (const AngleInterval& arc : patch.patch.range.arcs) {
        for (const AlgebraicAngle& angle : nearEnds(arc, scene.algebra)) coverage.check(pieces, patch, angle);
        for (const AlgebraicAngle& angle : acrossArc(arc, 24, scene.algebra)) coverage.check(pieces, patch, angle);
      }
    }
    EXPECT_GT(coverage.checked, 0);
    EXPECT_EQ(coverage.outside, 0) << "of " << coverage.checked << " angles, pieces " << width << " wide";
  }
}

// The index's pairs against every pair of patches compared box by box: those with
// an arc box each that meet and a piece each that meet, no more, no fewer, once;
// likewise the patches that meet a query box.
TEST_P(BundledScenePatchBoxes, MeetingPairsAreThePairsWhoseBoxesMeet) {
  BundledScene scene(GetParam());
  expectPairsOfMeetingBoxes(scene.geometries);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledScenePatchBoxes, ::testing::Values("maze.cfg", "room_door.cfg", "cage.cfg"));

// Boxes of very different sizes: a bar 4,000 long beside small blocks, so that the
// contacts along the bar's long edges have boxes hundreds of times as long as the
// others (the grid of the pairs takes wider cells then).
TEST(PatchBoxIndex, AnIndexOfNoPatchesMeetsNothing) {
  const PatchBoxIndex index({});
  EXPECT_TRUE(index.meeting({{-1, -1, -1}, {1, 1, 1}}).empty());
  EXPECT_TRUE(index.meetingAt(0, {-1, -1}, {1, 1}).empty());
  EXPECT_TRUE(index.meetingPairs().empty());
}

TEST(PatchBoxIndex, MeetingPairsAmongLongAndSmallBoxes) {
  std::vector<TriangleSoup> parts{boxSoup({10, -2000, 0.45}, {12, 2000, 0.5})};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) parts.push_back(boxSoup({3.0 * i, 3.0 * j, 0.2}, {3.0 * i + 0.5, 3.0 * j + 0.5, 0.7}));
  }
  PerturbedMeshes meshes = perturbMeshes(tetrahedronMesh({0, 0, 0.1}, {1, 0, 0.35}, {0, 1, 0.6}, {0.3, 0.3, 0.9}),
                                         Mesh::fromSoup(joinSoups(parts), "bar and blocks"), PerturbationSettings{});
  RandomScene scene(std::move(meshes.robot), std::move(meshes.world));  // any two meshes with their topology
  ASSERT_TRUE(scene.hasDistinctHeights());
  expectPairsOfMeetingBoxes(scene.allPatchGeometries());
}
