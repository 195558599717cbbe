// Clearance (docs/design.md section 7) against the exact collision test on the
// bundled scenes (tests/clearance_oracle.h): no state change nearer than the
// certified clearance, one within it; the certified interval narrower than 1e-12
// relative; the same answer whatever distance the search is told to expect; the same
// cell as locate; and what the clearance must be on a scene simple enough to work it
// out by hand; the same answers from several threads at once as from one.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "bundled_problem.h"
#include "clearance_oracle.h"
#include "random_configurations.h"
#include "temp_dir.h"
#include "freespace/numbers/half_angle.h"
#include "freespace/numbers/interval.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/scenes/scene_generator.h"
#include "freespace/space/free_space.h"
#include "freespace/topology/slice_pieces.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

class BundledClearance : public ::testing::TestWithParam<std::string> {};

/// `count` random configurations around the scene, in the input's units.
std::vector<Pose2> randomPoses(const FreeSpace& space, unsigned seed, int count) {
  RandomConfigurations configurations(space, seed);
  std::vector<Pose2> poses;
  for (int i = 0; i < count; ++i) poses.push_back(configurations.nextInInputUnits());
  return poses;
}

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

// The distance FreeSpace::clearance is told to expect only says where its search
// starts: right, too near (down to nothing), too far or not a number, the answer is
// the one it gives without it.
TEST_P(BundledClearance, ExpectedDistanceChangesNoAnswer) {
  const LoadedProblem problem = loadBundledProblem(GetParam());
  const FreeSpace space(problem.robot, problem.world);
  int compared = 0;
  for (const Pose2& pose : randomPoses(space, 5, 40)) {
    const Clearance plain = space.clearance(pose);
    if (!std::isfinite(plain.lower)) continue;
    const double distance = std::fabs(plain.upper);
    for (const double expected : {distance * 1.01, distance / 3, 1e-300, 0.0, 100 * distance + 1, std::nan("")}) {
      const Clearance hinted = space.clearance(pose, 1e-13, expected);
      EXPECT_EQ(hinted.lower, plain.lower) << "expected " << expected;
      EXPECT_EQ(hinted.upper, plain.upper) << "expected " << expected;
      EXPECT_EQ(hinted.location.free, plain.location.free);
      EXPECT_EQ(hinted.nearest, plain.nearest) << "expected " << expected;
      ++compared;
    }
  }
  EXPECT_GT(compared, 100);
}

// The clearance places a configuration from the side of its nearest piece of boundary
// it lies on, or by a short ray toward it when that piece is not alone near it; locate
// casts a long one along x: the same cell, or both blocked. Also at angles 0 and pi/2,
// critical on the scenes whose walls are parallel to the axes.
TEST_P(BundledClearance, PlacesConfigurationsAsLocateDoes) {
  const LoadedProblem problem = loadBundledProblem(GetParam());
  const FreeSpace space(problem.robot, problem.world);
  std::vector<Pose2> poses = randomPoses(space, 6, 300);
  for (std::size_t k = 200; k < poses.size(); ++k) poses[k].theta = k % 2 == 0 ? 0.0 : M_PI / 2;
  int free = 0;
  for (const Pose2& pose : poses) {
    const Location located = space.locate(pose), placed = space.clearance(pose).location;
    ASSERT_EQ(placed.free, located.free) << pose.x << " " << pose.y << " " << pose.theta;
    if (located.free) {
      EXPECT_EQ(placed.cell, located.cell) << pose.x << " " << pose.y << " " << pose.theta;
    }
    free += located.free;
  }
  EXPECT_GT(free, 0);
  EXPECT_LT(free, 300);
}

/// A query's answers compared between threads.
struct ThreadedAnswer {
  Clearance clearance;
  NodeLocation node;
};

ThreadedAnswer answerOf(const FreeSpace& space, const Pose2& pose) {
  return {space.clearance(pose), space.locateNode(pose)};
}

/// `count` threads asking `space` at once, each in its own order; per configuration,
/// what each thread got.
std::vector<std::vector<ThreadedAnswer>> askedTogether(const FreeSpace& space, const std::vector<Pose2>& poses,
                                                       std::size_t count) {
  std::vector<std::future<std::vector<ThreadedAnswer>>> threads;
  for (std::size_t thread = 0; thread < count; ++thread) {
    threads.push_back(std::async(std::launch::async, [&, thread] {
      std::vector<ThreadedAnswer> answers(poses.size());
      for (std::size_t k = 0; k < poses.size(); ++k) {
        const std::size_t at = (k + thread * poses.size() / count) % poses.size();
        answers[at] = answerOf(space, poses[at]);
      }
      return answers;
    }));
  }
  std::vector<std::vector<ThreadedAnswer>> together;
  for (auto& thread : threads) together.push_back(thread.get());
  return together;
}

void expectSameAnswers(const ThreadedAnswer& other, const ThreadedAnswer& alone, std::size_t k) {
  EXPECT_EQ(other.clearance.lower, alone.clearance.lower) << "configuration " << k;
  EXPECT_EQ(other.clearance.upper, alone.clearance.upper) << "configuration " << k;
  EXPECT_EQ(other.clearance.nearest, alone.clearance.nearest) << "configuration " << k;
  EXPECT_EQ(other.clearance.location.free, alone.clearance.location.free) << "configuration " << k;
  EXPECT_EQ(other.clearance.location.cell, alone.clearance.location.cell) << "configuration " << k;
  EXPECT_EQ(other.node.location.free, alone.node.location.free) << "configuration " << k;
  EXPECT_EQ(other.node.node, alone.node.node) << "configuration " << k;
}

// The witness names its patch: at the configuration's angle, the patch's segment (the
// places where its two features touch, docs/design.md section 3) passes through the
// contact reached, within the rounding of its place.
TEST_P(BundledClearance, TheWitnessLiesOnItsPatch) {
  const LoadedProblem problem = loadBundledProblem(GetParam());
  const FreeSpace space(problem.robot, problem.world);
  const double scale = space.meshes().scale;
  int witnessed = 0;
  for (const Pose2& pose : randomPoses(space, 11, 60)) {
    const Clearance clearance = space.clearance(pose);
    if (!clearance.contact) continue;
    ++witnessed;
    const PatchGeometry& patch = space.arrangement().patches.at(clearance.contactPatch);
    EXPECT_EQ(patch.patch.contact.kind, clearance.contact->kind);
    EXPECT_EQ(patch.patch.contact.robot, clearance.contact->robot);
    EXPECT_EQ(patch.patch.contact.world, clearance.contact->world);
    const RoundingScope rounding;
    slices::SliceIn<Interval> slice;
    HalfAngle::fromRadians(pose.theta).cosSin(slice.cosine, slice.sine);
    std::array<std::array<double, 2>, 2> ends;
    for (int end = 0; end < 2; ++end) {
      const std::array<Interval, 2> point = slice.end(patch, end);
      ends[end] = {point[0].midpoint() / scale, point[1].midpoint() / scale};
    }
    // The distance from the contact to the segment.
    const double alongX = ends[1][0] - ends[0][0], alongY = ends[1][1] - ends[0][1];
    const double dx = clearance.nearest[0] - ends[0][0], dy = clearance.nearest[1] - ends[0][1];
    const double t = std::clamp((dx * alongX + dy * alongY) / (alongX * alongX + alongY * alongY), 0.0, 1.0);
    const double size = 1 + std::fabs(clearance.nearest[0]) + std::fabs(clearance.nearest[1]);
    EXPECT_LT(std::hypot(dx - t * alongX, dy - t * alongY), 1e-9 * size)
        << "at " << pose.x << " " << pose.y << " " << pose.theta << ", patch " << clearance.contactPatch;
  }
  EXPECT_GT(witnessed, 30);
}

// Queries share the free space's functions (and their memos, made on first use) and
// borrow their own predicates: four threads asking at once, each in its own order, get
// what one thread gets asking alone afterwards; so do twelve threads asking the space
// read back from a file first (its exact coefficients decoded on first use; more
// threads than the space keeps idle predicates for without a lock).
TEST_P(BundledClearance, SeveralThreadsGetWhatOneGets) {
  const LoadedProblem problem = loadBundledProblem(GetParam());
  const FreeSpace space(problem.robot, problem.world);
  TempDir dir;
  space.save(dir.file("space.fspace"));
  const std::unique_ptr<FreeSpace> read = FreeSpace::load(dir.file("space.fspace"));
  const std::vector<Pose2> poses = randomPoses(space, 7, 160);
  const std::vector<std::vector<ThreadedAnswer>> together = askedTogether(space, poses, 4);
  const std::vector<std::vector<ThreadedAnswer>> readTogether = askedTogether(*read, poses, 12);
  int free = 0;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const ThreadedAnswer alone = answerOf(space, poses[k]);
    free += alone.node.location.free;
    for (const std::vector<ThreadedAnswer>& answers : together) expectSameAnswers(answers[k], alone, k);
    for (const std::vector<ThreadedAnswer>& answers : readTogether) expectSameAnswers(answers[k], alone, k);
  }
  EXPECT_GT(free, 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BundledClearance,
                         ::testing::Values("keyhole", "keyhole_narrow", "cage", "maze", "overhang", "table",
                                           "table_tall", "turn_around", "room_door", "random_polyhedra",
                                           "tetra_floorplan"));

}  // namespace
