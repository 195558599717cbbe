// Patch boxes against the exact segments: at rational angles inside each arc of a
// patch's range, down to the ends of the arc (where the narrowed enclosures of its
// end angles stop), both segment ends (exact rationals) lie in one of the patch's
// boxes, angle included. A box that misses part of a patch loses candidate pairs and
// so curves.
#include <gtest/gtest.h>

#include "bundled_scene.h"
#include "exact_geometry.h"
#include "freespace/geometry/patch_geometry.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

bool inBox(const PatchBox& box, const std::array<Rational, 2>& point, double theta) {
  return box.low[0] <= point[0] && point[0] <= box.high[0] && box.low[1] <= point[1] && point[1] <= box.high[1] &&
         box.low[2] <= theta && theta <= box.high[2];
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

}  // namespace

class BundledScenePatchBoxes : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledScenePatchBoxes, ContainTheSegmentsUpToTheRangeEnds) {
  BundledScene scene(GetParam());
  int checked = 0, outside = 0;
  for (const PatchGeometry& patch : scene.geometries) {
    const std::vector<PatchBox> boxes = patchBoxes(patch);
    for (const AngleInterval& arc : patch.patch.range.arcs) {
      for (const AlgebraicAngle& angle : nearEnds(arc, scene.algebra)) {
        const ExactRotation r = rotationOf(angle);
        const double theta = HalfAngle{angle.chart(), angle.lower()}.radians();
        bool covered = false;
        for (const PatchBox& box : boxes) {
          covered = covered || (inBox(box, spiralPoint(spiralOf<Rational>(patch.ends[0]), r.cosine, r.sine), theta) &&
                                inBox(box, spiralPoint(spiralOf<Rational>(patch.ends[1]), r.cosine, r.sine), theta));
        }
        checked++;
        outside += !covered;
      }
    }
  }
  EXPECT_GT(checked, 0);
  EXPECT_EQ(outside, 0) << "of " << checked << " angles";
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledScenePatchBoxes, ::testing::Values("maze.cfg", "room_door.cfg", "cage.cfg"));
