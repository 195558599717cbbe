// The clearance bounds of ClearanceBoxes (docs/design.md section 7) against the exact
// clearance at random configurations inside the boxes: no free configuration has more
// clearance than its box's upper bound (anchors, with the contacts' levers in theta,
// and blocked centres' depths), and a box with a positive lower bound holds only free
// configurations with at least that much; a box that no boundary patch meets
// (unbroken) holds only configurations located as its centre is (blocked, or in its
// centre's cell). Boxes of many sizes: random leaves are halved again and again (in
// theta alone where ClearanceBoxes::axesToSplit says so), so anchors pass from
// parents and neighbours to children; each sample's leaf is found again by leafAt.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "bundled_problem.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/motion_checker.h"
#include "freespace/topology/slice_pieces.h"
#include "space/clearance_boxes.h"
#include "test_meshes.h"

using namespace freespace;
using freespace::testing::loadBundledProblem;
using freespace::testing::scaled;

namespace {

class BundledClearanceBoxes : public ::testing::TestWithParam<std::string> {};

/// Boxes over a problem's volume scaled by `factor` (8 across), random leaves among
/// them halved `rounds` times as ClearanceBoxes::axesToSplit says, and how many of
/// those halvings were in theta alone.
struct HalvedBoxes {
  ClearanceBoxes boxes;
  int thetaOnly = 0;
};

HalvedBoxes halvedBoxes(const FreeSpace& space, const LoadedProblem& loaded, int rounds, std::mt19937_64& random,
                        double factor = 1) {
  const Eigen::AlignedBox2d volume = *loaded.problem.volume;
  HalvedBoxes halved{ClearanceBoxes(space, {volume.min().x() * factor, volume.min().y() * factor},
                                    {volume.max().x() * factor, volume.max().y() * factor},
                                    MotionChecker(space).reach(), 8)};
  ClearanceBoxes& boxes = halved.boxes;
  for (int round = 0; round < rounds; ++round) {
    const std::uint32_t box = std::uniform_int_distribution<std::uint32_t>(0, boxes.size() - 1)(random);
    if (boxes.box(box).split) continue;
    const std::uint8_t axes = boxes.axesToSplit(box);
    halved.thetaOnly += axes == ClearanceBoxes::kThetaAxis;
    boxes.split(box, axes);
  }
  return halved;
}

/// A configuration drawn uniformly from a box.
Pose2 randomPoseIn(const ClearanceBox& leaf, std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double x = leaf.low[0] + (leaf.high[0] - leaf.low[0]) * unit(random);
  const double y = leaf.low[1] + (leaf.high[1] - leaf.low[1]) * unit(random);
  return {x, y, leaf.low[2] + (leaf.high[2] - leaf.low[2]) * unit(random)};
}

/// How many sampled configurations of unbroken boxes had free and blocked centres.
struct UnbrokenSamples {
  int free = 0, blocked = 0;
};

/// Expects a configuration of an unbroken box to lie where the box's centre does:
/// blocked, or free in the centre's cell.
void expectWhereTheCentreIs(const ClearanceBox& leaf, const Location& location, const Pose2& pose,
                            UnbrokenSamples& samples) {
  ++(leaf.centreCell ? samples.free : samples.blocked);
  EXPECT_EQ(location.free, leaf.centreCell.has_value()) << pose.x << " " << pose.y << " " << pose.theta;
  if (location.free && leaf.centreCell) {
    EXPECT_EQ(location.cell, *leaf.centreCell);
  }
}

TEST_P(BundledClearanceBoxes, BoundsHoldTheExactClearanceInside) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  std::mt19937_64 random(20261205);
  auto [boxes, thetaOnly] = halvedBoxes(space, loaded, 600, random);
  // Asked of a cell none lies in, every box free at its centre is tested for a
  // boundary too (ClearanceBox::unbroken).
  boxes.dropOutside(UINT32_MAX);
  int free = 0, certified = 0, freeBesideBlockedCentres = 0;
  UnbrokenSamples unbroken;
  for (int sample = 0; sample < 3000; ++sample) {
    const std::uint32_t box = std::uniform_int_distribution<std::uint32_t>(0, boxes.size() - 1)(random);
    const ClearanceBox& leaf = boxes.box(box);
    if (leaf.split) continue;
    const Pose2 pose = randomPoseIn(leaf, random);
    EXPECT_EQ(boxes.leafAt(pose), box) << pose.x << " " << pose.y << " " << pose.theta;
    const Clearance clearance = space.clearance(pose);
    if (clearance.location.free) {
      ++free;
      if (!leaf.centreCell) ++freeBesideBlockedCentres;
      EXPECT_LE(clearance.lower, leaf.upper) << "box " << box << " at " << pose.x << " " << pose.y << " " << pose.theta;
    }
    // No boundary of the free space meets an unbroken box: every configuration lies
    // where its centre does.
    if (leaf.unbroken) expectWhereTheCentreIs(leaf, clearance.location, pose, unbroken);
    if (leaf.lower > 0) {
      // A positive lower bound certifies the box free (below 0 it bounds nothing: the
      // depth of a blocked configuration is not Lipschitz across angles).
      ++certified;
      EXPECT_TRUE(clearance.location.free) << "box " << box << " at " << pose.x << " " << pose.y << " " << pose.theta;
      EXPECT_GE(clearance.upper, leaf.lower) << "box " << box << " at " << pose.x << " " << pose.y << " " << pose.theta;
    }
  }
  EXPECT_GT(free, 100);
  EXPECT_GT(certified, 10);
  // Bounded by blocked centres too: their depth bounds the slice at their angle.
  EXPECT_GT(freeBesideBlockedCentres, 10);
  // Boxes halved in theta alone (blocked centres deeper than their half diagonal) are
  // among them.
  EXPECT_GT(thetaOnly, 0);
  EXPECT_GT(unbroken.free, 10);
  EXPECT_GT(unbroken.blocked, 10);
}

// A patch anchor's configurations touch, and so does each turned about the robot's
// axis and slid back by its contact point's move: at the fraction t along the segment,
// the robot's point in the contact is minus contactFrom + t contactAlong (docs/design.md
// section 7), which touches the environment at s(t) plus that point turned by the
// anchor's angle; at another angle, the configuration that puts the point there again
// has clearance at most 0 (but for rounding). Ends paired with the wrong contact points,
// or the points' sign or frame wrong, move it off the contact.
TEST_P(BundledClearanceBoxes, PatchAnchorsTouchTurnedAboutTheirContactPoints) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  std::mt19937_64 random(20261206);
  const ClearanceBoxes boxes = halvedBoxes(space, loaded, 100, random).boxes;
  std::uniform_real_distribution<double> unit(0, 1), turn(-0.5, 0.5);
  int checked = 0, moved = 0;
  for (std::uint32_t index = 0; index < boxes.size() && checked < 300; index += 7) {
    for (const ClearanceAnchor& anchor : boxes.box(index).own) {
      if (anchor.along[0] == 0 && anchor.along[1] == 0) continue;
      const double t = unit(random), theta = anchor.at[2], turned = theta + turn(random);
      const double vx = anchor.contactFrom[0] + t * anchor.contactAlong[0];
      const double vy = anchor.contactFrom[1] + t * anchor.contactAlong[1];
      // Where the robot's point (-v, turned by the angle) touches: s(t) - R(theta) v.
      const double touchX = anchor.at[0] + t * anchor.along[0] - (std::cos(theta) * vx - std::sin(theta) * vy);
      const double touchY = anchor.at[1] + t * anchor.along[1] - (std::sin(theta) * vx + std::cos(theta) * vy);
      const Pose2 back{touchX + std::cos(turned) * vx - std::sin(turned) * vy,
                       touchY + std::sin(turned) * vx + std::cos(turned) * vy, turned};
      const Clearance clearance = space.clearance(back);
      EXPECT_LE(clearance.lower, 1e-9 * (1 + std::fabs(back.x) + std::fabs(back.y)))
          << "box " << index << " t " << t << " at " << back.x << " " << back.y << " " << back.theta;
      moved +=
          std::hypot(back.x - anchor.at[0] - t * anchor.along[0], back.y - anchor.at[1] - t * anchor.along[1]) > 1e-3;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(moved, checked / 2);
}

// Each box's centre is located as locate() places it: the halves of a free box whose
// centre's clearance exceeds the move to theirs take its cell without a ray of their
// own (ClearanceBoxes::certifiedLocation), the others are placed by their clearance's.
TEST_P(BundledClearanceBoxes, CentresLieWhereLocateSays) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  std::mt19937_64 random(20261206);
  const ClearanceBoxes boxes = halvedBoxes(space, loaded, 600, random).boxes;
  int free = 0;
  for (std::uint32_t index = 0; index < boxes.size(); ++index) {
    const ClearanceBox& box = boxes.box(index);
    const Pose2 centre = ClearanceBoxes::centre(box);
    const Location location = space.locate(centre);
    ASSERT_EQ(box.centreCell.has_value(), location.free) << "box " << index;
    if (!location.free) continue;
    ++free;
    EXPECT_EQ(*box.centreCell, location.cell) << "box " << index;
  }
  EXPECT_GT(free, 100);
}

// The widest chains by upper bounds from the start's box, by plain relaxation until
// nothing changes (an oracle apart from the searches' Dijkstra): the search that stops
// below a ratio of the bottleneck to the goal's box agrees with it on every box at that
// level or above, and leaves the others below it.
TEST_P(BundledClearanceBoxes, SearchesStoppedBelowTheTargetAgreeWithRelaxationAboveIt) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  std::mt19937_64 random(20261205);
  const ClearanceBoxes boxes = halvedBoxes(space, loaded, 300, random).boxes;
  const std::uint32_t from = boxes.leafAt(loaded.problem.start), to = boxes.leafAt(loaded.problem.goal);
  std::vector<double> relaxed(boxes.size(), -HUGE_VAL);
  relaxed[from] = boxes.box(from).upper;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::uint32_t box = 0; box < boxes.size(); ++box) {
      if (relaxed[box] == -HUGE_VAL || boxes.box(box).split) continue;
      for (std::uint32_t neighbour : boxes.box(box).neighbours) {
        const ClearanceBox& next = boxes.box(neighbour);
        if (next.split || next.dropped) continue;
        const double through = std::min(relaxed[box], next.upper);
        if (through > relaxed[neighbour]) relaxed[neighbour] = through, changed = true;
      }
    }
  }
  ASSERT_GT(relaxed[to], 0);
  const double ratio = 0.98, level = ratio * relaxed[to];
  const std::vector<double> stopped = boxes.widestUpperFrom(from, to, ratio, HUGE_VAL);
  int atLevel = 0, below = 0;
  for (std::uint32_t box = 0; box < boxes.size(); ++box) {
    if (boxes.box(box).split) continue;
    if (relaxed[box] >= level) {
      ++atLevel;
      EXPECT_EQ(stopped[box], relaxed[box]) << "box " << box;
    } else {
      ++below;
      EXPECT_LT(stopped[box], level) << "box " << box;
    }
  }
  EXPECT_GT(atLevel, 10);
  EXPECT_GT(below, 10);
  // The boxes chains wider than a level reach (ClearanceBoxes::reachedAbove): those
  // whose relaxed bottleneck exceeds it.
  for (const double above : {level, relaxed[to], 0.5 * relaxed[to]}) {
    const std::vector<char> reached = boxes.reachedAbove(from, above);
    int inside = 0, outside = 0;
    for (std::uint32_t box = 0; box < boxes.size(); ++box) {
      if (boxes.box(box).split) continue;
      EXPECT_EQ(reached[box] != 0, relaxed[box] > above) << "box " << box << " above " << above;
      ++(reached[box] ? inside : outside);
    }
    EXPECT_GT(inside, 10);
    EXPECT_GT(outside, 10);
  }
}

// A search kept from round to round (ClearanceBoxes::UpperSearch) agrees with a new
// one after every round of halvings and drops: the same bottleneck on every box at
// the level or above, and below it on the others; its chain to the goal's box
// (ClearanceBoxes::chainTo) joins touching boxes with that bottleneck. The boxes halved are among those a
// chain at the level reaches (the searches' trees pass them).
TEST_P(BundledClearanceBoxes, KeptSearchesAgreeWithNewOnes) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  std::mt19937_64 random(20261206);
  ClearanceBoxes boxes = halvedBoxes(space, loaded, 200, random).boxes;
  ClearanceBoxes::UpperSearch kept;
  int compared = 0;
  for (int round = 0; round < 12; ++round) {
    // A lower level every other round: boxes the last search left below its level
    // count then.
    const double ratio = round % 2 == 0 ? 0.98 : 0.6;
    const std::uint32_t from = boxes.leafAt(loaded.problem.start), to = boxes.leafAt(loaded.problem.goal);
    const std::vector<double> fresh = boxes.widestUpperFrom(from, to, ratio, HUGE_VAL);
    const std::vector<double> goneOn = boxes.widestUpperFrom(from, to, ratio, HUGE_VAL, kept);
    ASSERT_EQ(goneOn.size(), fresh.size());
    ASSERT_GT(fresh[to], -HUGE_VAL);
    const double level = ratio * fresh[to];
    // Its chain to the goal's box: touching live boxes from the start's, the least of
    // their upper bounds the bottleneck.
    const ClearanceBoxes::Chain chain = ClearanceBoxes::chainTo(kept, to);
    ASSERT_FALSE(chain.boxes.empty());
    EXPECT_EQ(chain.boxes.front(), from);
    EXPECT_EQ(chain.boxes.back(), to);
    EXPECT_EQ(chain.bottleneck, fresh[to]);
    double least = HUGE_VAL;
    for (std::size_t k = 0; k < chain.boxes.size(); ++k) {
      const ClearanceBox& box = boxes.box(chain.boxes[k]);
      EXPECT_FALSE(box.split || box.dropped) << "round " << round;
      least = std::min(least, box.upper);
      if (k > 0) {
        const std::vector<std::uint32_t>& touching = boxes.box(chain.boxes[k - 1]).neighbours;
        EXPECT_NE(std::find(touching.begin(), touching.end(), chain.boxes[k]), touching.end()) << "round " << round;
      }
    }
    EXPECT_EQ(least, fresh[to]) << "round " << round;
    std::vector<std::uint32_t> reached;
    for (std::uint32_t box = 0; box < boxes.size(); ++box) {
      if (boxes.box(box).split || boxes.box(box).dropped) continue;
      if (fresh[box] >= level) {
        ++compared;
        reached.push_back(box);
        EXPECT_EQ(goneOn[box], fresh[box]) << "round " << round << " box " << box;
      } else {
        EXPECT_LT(goneOn[box], level) << "round " << round << " box " << box;
      }
    }
    // Halve some boxes a chain at the level passes, and drop the lowest.
    std::shuffle(reached.begin(), reached.end(), random);
    for (std::size_t k = 0; k < std::min<std::size_t>(reached.size(), 30); ++k) {
      boxes.split(reached[k], boxes.axesToSplit(reached[k]));
    }
    if (round % 3 == 2) boxes.dropBelow(0.5 * level);
  }
  EXPECT_GT(compared, 1000);
}

// Drops look only at the boxes added since the last call unless the level rose or the
// cell changed: after levels that fall and rise between halvings, and a change of cell,
// no live box lies below the last level or (unbroken) in another cell than the last,
// and a box is dropped only for one or the other (against a scan of every box).
TEST_P(BundledClearanceBoxes, DropsLeaveNoBoxBelowTheLevelNorOutsideTheCell) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  std::mt19937_64 random(20261206);
  ClearanceBoxes boxes = halvedBoxes(space, loaded, 200, random).boxes;
  std::vector<double> uppers;
  for (std::uint32_t box = 0; box < boxes.size(); ++box) uppers.push_back(boxes.box(box).upper);
  std::sort(uppers.begin(), uppers.end());
  const std::uint32_t startCell = space.locate(loaded.problem.start).cell;
  // Levels at the 20th, 5th and 10th percentiles of the first bounds, cells in turn.
  const double levels[] = {uppers[uppers.size() / 5], uppers[uppers.size() / 20], uppers[uppers.size() / 10]};
  const std::uint32_t cells[] = {startCell, startCell + 1, startCell};
  int dropped = 0;
  for (int step = 0; step < 3; ++step) {
    for (int k = 0; k < 100; ++k) {
      const std::uint32_t box = std::uniform_int_distribution<std::uint32_t>(0, boxes.size() - 1)(random);
      if (!boxes.box(box).split && !boxes.box(box).dropped) boxes.split(box, boxes.axesToSplit(box));
    }
    std::vector<char> liveBefore(boxes.size());
    for (std::uint32_t box = 0; box < boxes.size(); ++box) {
      liveBefore[box] = !boxes.box(box).split && !boxes.box(box).dropped;
    }
    boxes.dropBelow(levels[step]);
    boxes.dropOutside(cells[step]);
    for (std::uint32_t box = 0; box < boxes.size(); ++box) {
      const ClearanceBox& candidate = boxes.box(box);
      const bool outside = candidate.unbroken && candidate.centreCell && *candidate.centreCell != cells[step];
      const bool droppable = candidate.upper < levels[step] || outside;
      if (liveBefore[box]) {
        EXPECT_EQ(candidate.dropped, droppable) << "step " << step << " box " << box;
        dropped += candidate.dropped;
      }
    }
  }
  EXPECT_GT(dropped, 10);
}

/// Whether two sets of boxes are the same, box by box: ranges, bounds, centres'
/// cells, anchors, neighbours and halvings.
void expectSameBoxes(const ClearanceBoxes& a, const ClearanceBoxes& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::uint32_t index = 0; index < a.size(); ++index) {
    const ClearanceBox &x = a.box(index), &y = b.box(index);
    EXPECT_EQ(x.low, y.low) << "box " << index;
    EXPECT_EQ(x.high, y.high) << "box " << index;
    EXPECT_EQ(x.lower, y.lower) << "box " << index;
    EXPECT_EQ(x.upper, y.upper) << "box " << index;
    EXPECT_EQ(x.centreLower, y.centreLower) << "box " << index;
    EXPECT_EQ(x.centreCell, y.centreCell) << "box " << index;
    EXPECT_EQ(x.unbroken, y.unbroken) << "box " << index;
    EXPECT_EQ(x.split, y.split) << "box " << index;
    EXPECT_EQ(x.dropped, y.dropped) << "box " << index;
    EXPECT_EQ(x.firstChild, y.firstChild) << "box " << index;
    EXPECT_EQ(x.neighbours, y.neighbours) << "box " << index;
    ASSERT_EQ(x.anchors.size(), y.anchors.size()) << "box " << index;
    for (std::size_t k = 0; k < x.anchors.size(); ++k) {
      EXPECT_EQ(x.anchors[k].at, y.anchors[k].at) << "box " << index;
      EXPECT_EQ(x.anchors[k].upper, y.anchors[k].upper) << "box " << index;
      EXPECT_EQ(x.anchors[k].along, y.anchors[k].along) << "box " << index;
      EXPECT_EQ(x.anchors[k].contactFrom, y.anchors[k].contactFrom) << "box " << index;
    }
  }
}

// Halving many boxes at once (their halves measured and bounded on every core) leaves
// what halving them one after another leaves, neighbours of one another among them,
// some of their neighbours dropped; a halving told to stop leaves the rest whole.
TEST_P(BundledClearanceBoxes, HalvingAtOnceMatchesHalvingInTurn) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  std::mt19937_64 random(20261207), sameRandom(20261207);
  ClearanceBoxes inTurn = halvedBoxes(space, loaded, 100, random).boxes;
  ClearanceBoxes atOnce = halvedBoxes(space, loaded, 100, sameRandom).boxes;
  for (int round = 0; round < 3; ++round) {
    // From the second round, the boxes of the lowest upper bounds dropped (neighbours
    // left out of the halves' bounds).
    if (round > 0) {
      std::vector<double> uppers;
      for (std::uint32_t box = 0; box < inTurn.size(); ++box) {
        if (!inTurn.box(box).split && !inTurn.box(box).dropped) uppers.push_back(inTurn.box(box).upper);
      }
      std::nth_element(uppers.begin(), uppers.begin() + uppers.size() / 5, uppers.end());
      inTurn.dropBelow(uppers[uppers.size() / 5]);
      atOnce.dropBelow(uppers[uppers.size() / 5]);
    }
    // A box and its leaf neighbours, from random boxes, until some 200.
    std::vector<std::uint32_t> chosen;
    std::vector<char> taken(inTurn.size(), 0);
    const auto usable = [&](std::uint32_t box) { return !inTurn.box(box).split && !inTurn.box(box).dropped; };
    while (chosen.size() < 200) {
      const std::uint32_t box = std::uniform_int_distribution<std::uint32_t>(0, inTurn.size() - 1)(random);
      if (!usable(box)) continue;
      std::vector<std::uint32_t> group{box};
      group.insert(group.end(), inTurn.box(box).neighbours.begin(), inTurn.box(box).neighbours.end());
      for (std::uint32_t member : group) {
        if (!taken[member] && usable(member)) chosen.push_back(member), taken[member] = 1;
      }
    }
    for (std::uint32_t box : chosen) inTurn.split(box, inTurn.axesToSplit(box));
    EXPECT_EQ(atOnce.splitEach(chosen, [] { return true; }), chosen.size());
    expectSameBoxes(inTurn, atOnce);
  }
  std::vector<std::uint32_t> leaves;
  for (std::uint32_t box = 0; box < atOnce.size() && leaves.size() < 100; ++box) {
    if (!atOnce.box(box).split) leaves.push_back(box);
  }
  std::atomic<int> asked{0};
  const std::size_t halved = atOnce.splitEach(leaves, [&] { return ++asked <= 40; });
  EXPECT_LE(halved, 40u);
  EXPECT_GE(halved, 1u);
  for (std::size_t k = 0; k < leaves.size(); ++k) EXPECT_EQ(atOnce.box(leaves[k]).split, k < halved) << k;
  // Cancelled in the middle (keepGoing throws): nothing halved, the exception passed on.
  std::vector<std::uint32_t> rest;
  for (std::uint32_t box = 0; box < atOnce.size() && rest.size() < 100; ++box) {
    if (!atOnce.box(box).split) rest.push_back(box);
  }
  const std::size_t before = atOnce.size();
  std::atomic<int> polled{0};
  const auto cancelledAtTwenty = [&] {
    if (++polled > 20) throw Cancelled();
    return true;
  };
  EXPECT_THROW(atOnce.splitEach(rest, cancelledAtTwenty), Cancelled);
  EXPECT_EQ(atOnce.size(), before);
  for (std::uint32_t box : rest) EXPECT_FALSE(atOnce.box(box).split) << box;
}

/// Angles (their tangent's chart and t) strictly inside a slab: just after its start,
/// just before its end and, when both lie in one chart, halfway; none when its ends'
/// enclosures overlap (a whole turn, or too thin to tell).
std::vector<HalfAngle> anglesInside(const PatchSlab& slab) {
  const AlgebraicAngle &from = slab.from, &to = slab.to;
  const bool sameChart = from.chart() == to.chart();
  if (sameChart && from.lower() <= to.upper() && to.lower() <= from.upper()) return {};
  // Chart 0 holds t in [-1, 1], chart 1 in (-1, 1); t grows counterclockwise.
  const auto inChart = [](int chart, double t) { return chart == 0 ? std::fabs(t) <= 1 : std::fabs(t) < 1; };
  std::vector<HalfAngle> angles;
  const double afterFrom = std::nextafter(from.upper(), HUGE_VAL), beforeTo = std::nextafter(to.lower(), -HUGE_VAL);
  if (inChart(from.chart(), afterFrom)) angles.push_back({from.chart(), afterFrom});
  if (inChart(to.chart(), beforeTo)) angles.push_back({to.chart(), beforeTo});
  if (sameChart && from.upper() < to.lower()) angles.push_back({from.chart(), 0.5 * (from.upper() + to.lower())});
  return angles;
}

// Points of the sub-faces that bound a free cell, found exactly at angles inside their
// slabs (just inside each end too), lie in no unbroken box: the test leaves out slabs
// at other angles and the parts of segments beyond those sub-faces' curves, never such
// a sub-face itself. Boxes free at their centre are looked at when another cell is
// asked of them: asked of a cell none lies in (dropOutside), every box is.
TEST_P(BundledClearanceBoxes, FreeCellBoundaryMeetsNoUnbrokenBox) {
  const LoadedProblem loaded = loadBundledProblem(GetParam());
  const FreeSpace space(loaded.robot, loaded.world);
  std::mt19937_64 random(20261206);
  ClearanceBoxes boxes = halvedBoxes(space, loaded, 600, random).boxes;
  constexpr std::uint32_t kNoCell = UINT32_MAX;
  boxes.dropOutside(kNoCell);
  const Arrangement& arrangement = space.arrangement();
  const Eigen::AlignedBox2d volume = *loaded.problem.volume;
  const double scale = space.meshes().scale;
  int checked = 0, slabsTried = 0;
  for (int attempt = 0; attempt < 20000 && slabsTried < 1000; ++attempt) {
    const auto patch = std::uniform_int_distribution<std::uint32_t>(0, arrangement.patches.size() - 1)(random);
    const std::vector<PatchSlab>& slabs = arrangement.subdivisions[patch].slabs;
    if (slabs.empty()) continue;
    const PatchSlab& slab = slabs[std::uniform_int_distribution<std::size_t>(0, slabs.size() - 1)(random)];
    std::vector<std::size_t> freeGaps;
    for (std::size_t gap = 0; gap < slab.faces.size(); ++gap) {
      if (space.cellOfSubFace({patch, slab.faces[gap]})) freeGaps.push_back(gap);
    }
    if (freeGaps.empty()) continue;
    ++slabsTried;
    for (const HalfAngle& angle : anglesInside(slab)) {
      Rational cosine, sine;
      angle.cosSin(cosine, sine);
      const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[patch], cosine, sine);
      for (const std::size_t gap : freeGaps) {
        const auto piece = slices::pieceOf(arrangement, patch, slab, gap, segment, cosine, sine);
        if (!piece) continue;
        const slices::Point point = segment.at(Rational((piece->first + piece->second) / 2));
        const Pose2 pose{point[0].convert_to<double>() / scale, point[1].convert_to<double>() / scale, angle.radians()};
        if (!volume.contains(Eigen::Vector2d(pose.x, pose.y))) continue;
        ++checked;
        EXPECT_FALSE(boxes.box(boxes.leafAt(pose)).unbroken)
            << "patch " << patch << " at " << pose.x << " " << pose.y << " " << pose.theta;
        // And in a box about a thousandth of a radian wide (halved in theta).
        std::uint32_t leaf = boxes.leafAt(pose);
        while (boxes.box(leaf).high[2] - boxes.box(leaf).low[2] > 1e-3) {
          boxes.split(leaf, ClearanceBoxes::kThetaAxis);
          leaf = boxes.leafAt(pose);
        }
        boxes.dropOutside(kNoCell);
        EXPECT_FALSE(boxes.box(leaf).unbroken)
            << "patch " << patch << " at " << pose.x << " " << pose.y << " " << pose.theta << " (thin)";
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

// The keyhole's bar passes its slot turned a quarter turn, 0.125 from either side. A
// box across the slot's middle (the domain is shifted so that no box's edge lies
// there), wide in (x, y) but a thousandth of a radian in theta, is bounded by about
// that (the mix of the two sides' anchors): one side's anchor alone bounds it by 0.125
// plus the width of its part on the other side.
TEST(KeyholeClearanceBoxes, BoxesAcrossASlotAreBoundedByItsClearance) {
  const LoadedProblem keyhole = loadBundledProblem("keyhole");
  const FreeSpace space(keyhole.robot, keyhole.world);
  // The volume shifted by half the width the boxes will have (9.5 / 16 / 8).
  constexpr double kShift = 9.5 / 16 / 16;
  ClearanceBoxes boxes(space, {-4.75 - kShift, -4.75}, {4.75 - kShift, 4.75}, MotionChecker(space).reach());
  const Pose2 middle{0, 0, M_PI / 2};
  const auto leaf = [&] { return boxes.box(boxes.leafAt(middle)); };
  while (leaf().high[0] - leaf().low[0] > 0.12) boxes.split(boxes.leafAt(middle));
  while (leaf().high[2] - leaf().low[2] > 1e-3) boxes.split(boxes.leafAt(middle), ClearanceBoxes::kThetaAxis);
  const ClearanceBox& box = leaf();
  ASSERT_GT(box.high[0] - box.low[0], 0.05);
  ASSERT_GT(std::min(-box.low[0], box.high[0]), 0.03);
  EXPECT_GE(box.upper, space.clearance(middle).upper);
  EXPECT_LT(box.upper, 0.125 * 1.03);
}

// The keyhole scaled down by 1e-5 is built in coordinates scaled back up by a power of
// two (docs/design.md section 5): the boxes' test against the patches' boxes and
// segments works in those, and unbroken boxes still hold only configurations located
// as their centre.
TEST(ScaledClearanceBoxes, UnbrokenBoxesLieWhereTheirCentreDoes) {
  const LoadedProblem keyhole = loadBundledProblem("keyhole");
  constexpr double kFactor = 1e-5;
  const FreeSpace space(scaled(keyhole.robot, kFactor), scaled(keyhole.world, kFactor));
  ASSERT_NE(space.meshes().scale, 1.0);
  std::mt19937_64 random(20261205);
  ClearanceBoxes boxes = halvedBoxes(space, keyhole, 300, random, kFactor).boxes;
  boxes.dropOutside(UINT32_MAX);  // every box free at its centre tested too
  UnbrokenSamples unbroken;
  for (int sample = 0; sample < 3000; ++sample) {
    const ClearanceBox& leaf = boxes.box(std::uniform_int_distribution<std::uint32_t>(0, boxes.size() - 1)(random));
    if (leaf.split || !leaf.unbroken) continue;
    const Pose2 pose = randomPoseIn(leaf, random);
    expectWhereTheCentreIs(leaf, space.locate(pose), pose, unbroken);
  }
  EXPECT_GT(unbroken.free, 10);
  EXPECT_GT(unbroken.blocked, 10);
}

INSTANTIATE_TEST_SUITE_P(Bundled, BundledClearanceBoxes,
                         ::testing::Values("keyhole", "turn_around", "table", "overhang", "random_polyhedra"));

}  // namespace
