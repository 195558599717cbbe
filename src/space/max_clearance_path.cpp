#include "freespace/space/max_clearance_path.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "clearance_boxes.h"
#include "freespace/geometry/stage_clock.h"
#include "freespace/input_error.h"
#include "freespace/numbers/angle_reduction.h"
#include "freespace/space/motion_checker.h"
#include "passage.h"
#include "raised_passage.h"
#include "route_path.h"

namespace freespace {

namespace {

using Clock = std::chrono::steady_clock;

/// The share of a query's time one raising of a path may take.
constexpr double kRaisingShare = 0.4;
/// How much of a chain's bottleneck its path keeps when shortened before raising, and
/// how much wider than the last chain raised a chain must be to be raised in turn.
constexpr double kChainShortening = 0.99;
constexpr double kRaiseAgain = 1.01;

/// When a raising that starts now must end.
Clock::time_point raisingDeadline(Clock::time_point deadline, const MaxClearancePathOptions& options) {
  return std::min(deadline, Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                               std::chrono::duration<double>(kRaisingShare * options.secondsLimit)));
}

std::string poseText(const Pose2& pose) {
  std::ostringstream text;
  text.precision(17);
  text << "(" << pose.x << ", " << pose.y << ", " << pose.theta << ")";
  return text.str();
}

/// The clearance of a start or goal; an InputError naming it when it is not finite,
/// outside the volume, or not free.
Clearance checkedEnd(const FreeSpace& space, const Pose2& pose, const std::string& name,
                     const MaxClearancePathOptions& options) {
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) {
    throw InputError(name, "x, y and theta must be finite numbers, not " + poseText(pose));
  }
  if (options.volumeLow && !Domain{*options.volumeLow, *options.volumeHigh}.holds(pose)) {
    throw InputError(name, poseText(pose) + " lies outside the volume");
  }
  const Clearance clearance = space.clearance(pose, MotionChecker::kClearanceWidth);
  if (!clearance.location.free) {
    std::ostringstream text;
    text << "the robot at " << poseText(pose) << " touches or overlaps the environment (clearance " << clearance.upper
         << ")";
    throw InputError(name, text.str());
  }
  return clearance;
}

/// Where paths may go: the volume, within the bounded cell's box; in the unbounded
/// cell without a volume, the environment's box with room for the robot around it.
Domain domainOf(const FreeSpace& space, std::uint32_t cell, const MaxClearancePathOptions& options) {
  Domain domain{{-HUGE_VAL, -HUGE_VAL}, {HUGE_VAL, HUGE_VAL}};
  if (options.volumeLow) domain = {*options.volumeLow, *options.volumeHigh};
  const std::optional<PatchBox> cellBox = space.cellBoxes()[cell];
  if (cellBox) {
    for (int axis = 0; axis < 2; ++axis) {
      domain.low[axis] = std::max(domain.low[axis], cellBox->low[axis]);
      domain.high[axis] = std::min(domain.high[axis], cellBox->high[axis]);
    }
  } else if (!options.volumeLow) {
    const double scale = space.meshes().scale;
    const double room = 2 * space.meshes().robot.horizontalReach() / scale;
    for (const Point3& vertex : space.meshes().world.vertices()) {
      for (int axis = 0; axis < 2; ++axis) {
        domain.low[axis] = std::min(domain.low[axis], vertex[axis] / scale - room);
        domain.high[axis] = std::max(domain.high[axis], vertex[axis] / scale + room);
      }
    }
  }
  return domain;
}

/// A first (or, reversed, last) motion: straight away from the nearest contact, as
/// far as the clearance grows at doubling steps, kept when certified to keep 99.8% of
/// the clearance it starts with (the level alone: parts grow with the clearance, so
/// a few dozen clearances certify it, where a bound within 0.2% all along would take
/// thousands).
struct Climb {
  Pose2 to;
  double clearance;  // certified along the motion (the start's when it has none)
};

Climb climbFrom(const FreeSpace& space, const MotionChecker& checker, const Pose2& from, const Clearance& clearance,
                const Domain& domain) {
  const Climb none{from, clearance.lower};
  if (!std::isfinite(clearance.lower) || (clearance.direction[0] == 0 && clearance.direction[1] == 0)) return none;
  double best = 0, bestClearance = clearance.lower;
  for (double step = clearance.lower / 2; step < 1e3 * clearance.lower; step *= 2) {
    const Pose2 at{from.x - step * clearance.direction[0], from.y - step * clearance.direction[1], from.theta};
    if (!domain.holds(at)) break;
    const Clearance there = space.clearance(at, MotionChecker::kClearanceWidth);
    if (!there.location.free || there.lower <= bestClearance) break;
    best = step;
    bestClearance = there.lower;
  }
  if (best == 0) return none;
  const Pose2 to{from.x - best * clearance.direction[0], from.y - best * clearance.direction[1], from.theta};
  const double kept = 0.998 * clearance.lower;
  if (!checker.keepsClearance(from, to, kept, 4096)) return none;
  return {to, kept};
}

/// The waypoints through a chain of boxes from `from` (in its first box) to `to` (in
/// its last), through the middles of the common parts of consecutive boxes: each
/// motion inside one box, with the box's lower bound as its certified clearance.
Passage chainPath(const ClearanceBoxes& boxes, const ClearanceBoxes::Chain& chain, const Pose2& from, const Pose2& to) {
  Passage passage{{from}, {}, chain.bottleneck};
  for (std::size_t k = 0; k < chain.boxes.size(); ++k) {
    passage.waypoints.push_back(k + 1 < chain.boxes.size() ? boxes.meeting(chain.boxes[k], chain.boxes[k + 1]) : to);
    passage.motionClearance.push_back(boxes.box(chain.boxes[k]).lower);
  }
  return passage;
}

/// Leaves out the route's waypoints outside `domain`, the motion that replaces each run
/// of them not certified yet; false when an end lies outside.
bool keepToDomain(const Domain& domain, RoutedPath& route) {
  if (!domain.holds(route.waypoints.front()) || !domain.holds(route.waypoints.back())) return false;
  RoutedPath kept{{route.waypoints.front()}, {}};
  bool skipped = false;
  for (std::size_t k = 1; k < route.waypoints.size(); ++k) {
    if (!domain.holds(route.waypoints[k])) {
      skipped = true;
      continue;
    }
    kept.certified.push_back(skipped ? std::nullopt : route.certified[k - 1]);
    kept.waypoints.push_back(route.waypoints[k]);
    skipped = false;
  }
  route = std::move(kept);
  return true;
}

/// The path along the cell graph's route (routePath), each motion certified free by
/// the motion checker (unless routing certified it already) with the clearance bound
/// that took (halving a motion that passes near a contact until its bound is near the
/// true least clearance could take billions of parts); none when one is not, or not
/// before `deadline`. The route keeps to the cell, not to the volume: a run of its
/// waypoints outside `domain` (the walk through a face's triangles can pass the far
/// corner of the box around an unbounded face) is replaced by the motion between the
/// waypoints on either side, which lie in it (so does the motion: the domain is a
/// rectangle).
std::optional<Passage> certifiedRoutePath(const FreeSpace& space, const MotionChecker& checker, const Pose2& from,
                                          const Pose2& to, const Domain& domain, Clock::time_point deadline,
                                          QueryRate& rate, const MaxClearancePathOptions& options) {
  std::optional<RoutedPath> routed = routePath(space, from, to, deadline, options.cancellation);
  if (!routed || !keepToDomain(domain, *routed)) return std::nullopt;
  Passage passage{std::move(routed->waypoints), {}, HUGE_VAL};
  for (std::size_t k = 0; k + 1 < passage.waypoints.size(); ++k) {
    options.cancellation.check();
    if (Clock::now() > deadline) return std::nullopt;
    double clearance;
    if (routed->certified[k]) {
      clearance = *routed->certified[k];
    } else {
      // As many clearances as the time left allows at the rate measured so far (a
      // motion passing very near a contact takes many).
      const double secondsLeft = std::chrono::duration<double>(deadline - Clock::now()).count();
      const MotionCheck check = rate.check(checker, passage.waypoints[k], passage.waypoints[k + 1], 1, secondsLeft);
      if (!check.free) return std::nullopt;
      clearance = check.minClearance;
    }
    passage.motionClearance.push_back(clearance);
    passage.lower = std::min(passage.lower, clearance);
  }
  return passage;
}

/// Replaces runs of waypoints between `first` and `last` by single motions certified
/// to keep at least `level`, the longest found by doubling jumps from each waypoint.
void shorten(const MotionChecker& checker, std::size_t first, std::size_t last, double level,
             std::vector<Pose2>& waypoints, std::vector<double>& motionClearance) {
  std::vector<Pose2> shorter(waypoints.begin(), waypoints.begin() + first + 1);
  std::vector<double> clearances(motionClearance.begin(), motionClearance.begin() + first);
  for (std::size_t at = first; at < last;) {
    std::size_t reach = at + 1;
    double reachClearance = motionClearance[at];
    for (std::size_t jump = 2; at + jump / 2 < last; jump *= 2) {
      const std::size_t to = std::min(last, at + jump);
      if (!checker.keepsClearance(waypoints[at], waypoints[to], level, 64)) break;
      reach = to;
      reachClearance = level;
    }
    shorter.push_back(waypoints[reach]);
    clearances.push_back(reachClearance);
    at = reach;
  }
  shorter.insert(shorter.end(), waypoints.begin() + last + 1, waypoints.end());
  clearances.insert(clearances.end(), motionClearance.begin() + last, motionClearance.end());
  waypoints = std::move(shorter);
  motionClearance = std::move(clearances);
}

/// The path through a chain of boxes (chainPath), shortened to keep 99% of the chain's
/// bottleneck (a few dozen motions instead of one per box), then raised
/// (raisedPassage): the chain's boxes are many times smaller than its passages, and
/// their lower bounds lose about a box's size near the bottleneck, where a path pushed
/// to the passages' middles keeps nearly all of it.
std::optional<Passage> raisedChainPath(const FreeSpace& space, const MotionChecker& checker,
                                       const ClearanceBoxes& boxes, const ClearanceBoxes::Chain& chain,
                                       const Pose2& from, const Pose2& to, const Domain& domain,
                                       Clock::time_point deadline, QueryRate& rate, const Cancellation& cancellation) {
  Passage passage = chainPath(boxes, chain, from, to);
  passage.lower = kChainShortening * chain.bottleneck;
  shorten(checker, 0, passage.waypoints.size() - 1, passage.lower, passage.waypoints, passage.motionClearance);
  return raisedPassage(space, checker, passage, domain, deadline, rate, cancellation);
}

/// A round's bounds: c_hi, the target c_lo must reach, and their ratio.
struct RoundLevels {
  double target, upper, ratio;
};

/// How far from the widest chain by upper bounds the boxes that limit c_hi are looked
/// for: in a passage of even width, the chain's limiting boxes have neighbours as
/// narrow, through which the next round's chain would pass (docs/design.md section 7).
constexpr int kLimitingHops = 2;

/// The boxes of the widest chain by upper bounds (`upperChain`) not certain at the
/// ratio (lower bound below the target) whose bound lies within the ratio's slack of
/// c_hi (those that limit it and those that would next: halving all that tie with them
/// along other chains took 40% longer on tetra_floorplan), and such boxes within
/// kLimitingHops of them that chains at the target's level reach (`fromStart`).
std::vector<std::uint32_t> limitingBoxes(const ClearanceBoxes& boxes, const ClearanceBoxes::Chain& upperChain,
                                         const std::vector<double>& fromStart, const RoundLevels& levels) {
  std::vector<char> seen(boxes.size(), 0);
  const auto limits = [&](std::uint32_t index) {
    const ClearanceBox& box = boxes.box(index);
    return !seen[index] && !box.split && !box.dropped && box.lower < levels.target &&
           box.upper * levels.ratio <= levels.upper;
  };
  std::vector<std::uint32_t> limiting, reached;
  const auto reach = [&](std::uint32_t box, std::vector<std::uint32_t>& into) {
    seen[box] = 1;
    into.push_back(box);
  };
  for (std::uint32_t box : upperChain.boxes) {
    if (limits(box)) reach(box, reached);
  }
  for (int hop = 0; !reached.empty(); ++hop) {
    limiting.insert(limiting.end(), reached.begin(), reached.end());
    if (hop == kLimitingHops) break;
    std::vector<std::uint32_t> next;
    for (std::uint32_t box : reached) {
      for (std::uint32_t neighbour : boxes.box(box).neighbours) {
        if (fromStart[neighbour] >= levels.target && limits(neighbour)) reach(neighbour, next);
      }
    }
    reached = std::move(next);
  }
  return limiting;
}

/// The boxes a round halves, distinct and in order: those that limit c_hi
/// (limitingBoxes); those whose centre lies outside `cell` (blocked, or another
/// cell's) that some chain at the target's level passes (reached from the start at it,
/// `fromStart`: at a level at most c_hi, the boxes chains at it reach from the start
/// are those they reach from the goal; their upper bound is about their size, and
/// chains of them along walls or around the cell's outside may be all that carries
/// c_hi), but not those at the edge of one end's basin alone (see below); and the
/// worse half of the widest chain by lower bounds; and when nothing above is left, the
/// uncertain boxes of the widest chain by upper bounds (docs/design.md section 7).
///
/// An end's basin is where chains from it wider than c_hi by more than the ratio's
/// slack reach (the start's: `fromStart` above that; the goal's: `goalBasin`). A box
/// next to one basin but not the other and wider than c_hi does not limit any chain
/// at c_hi: those chains narrow past it, between the basins. The walls around a wide
/// room are such boxes, and halving them every round took keyhole_wide past two
/// million boxes without converging; they are left whole (a choice of what to halve
/// first: the bounds stay certified whatever is halved). A box next to both basins
/// may join them, one next to neither lies between them, and one no wider than c_hi
/// may limit a chain: those are halved.
std::vector<std::uint32_t> boxesToHalve(const ClearanceBoxes& boxes, const ClearanceBoxes::Chain& upperChain,
                                        const std::vector<double>& fromStart, const std::vector<char>& goalBasin,
                                        const ClearanceBoxes::Chain& lowerChain, const RoundLevels& levels,
                                        std::uint32_t cell) {
  std::vector<std::uint32_t> uncertain = limitingBoxes(boxes, upperChain, fromStart, levels);
  const double wide = levels.upper / levels.ratio;
  const auto inStartBasin = [&](std::uint32_t box) { return fromStart[box] > wide; };
  const auto inGoalBasin = [&](std::uint32_t box) { return goalBasin[box] != 0; };
  for (std::uint32_t box = 0; box < boxes.size(); ++box) {
    // (The search's values first: most boxes are not reached at the target.)
    if (fromStart[box] < levels.target) continue;
    const ClearanceBox& candidate = boxes.box(box);
    if (candidate.split || candidate.dropped || candidate.lower >= levels.target || candidate.centreCell == cell) {
      continue;
    }
    const std::vector<std::uint32_t>& next = candidate.neighbours;
    const bool nextToStartBasin = std::any_of(next.begin(), next.end(), inStartBasin);
    const bool nextToGoalBasin = std::any_of(next.begin(), next.end(), inGoalBasin);
    if (nextToStartBasin == nextToGoalBasin || candidate.upper <= levels.upper) uncertain.push_back(box);
  }
  const bool upperSettled = uncertain.empty();
  for (std::uint32_t box : lowerChain.boxes) {
    if (boxes.box(box).lower <= 0.5 * (lowerChain.bottleneck + levels.target)) uncertain.push_back(box);
  }
  if (lowerChain.boxes.empty() || upperSettled) {
    // No chain of boxes whose centres lie in the cell joins the ends at the target's
    // upper bounds: the widest chain by upper bounds passes boxes too coarse to say
    // (those outside the cell are halved above; a box outside it never has a lower
    // bound at the target: it would have been dropped). Or nothing above limits c_hi
    // any more: the widest path lies along that chain, whose uncertain boxes the
    // chain by lower bounds may not reach for many rounds (it passes narrower routes
    // first, each halved a few boxes a round; RandomPolygons converged in 3.2 s
    // instead of 0.6-0.7).
    for (std::uint32_t box : upperChain.boxes) {
      if (boxes.box(box).lower < levels.target) uncertain.push_back(box);
    }
  }
  std::sort(uncertain.begin(), uncertain.end());
  uncertain.erase(std::unique(uncertain.begin(), uncertain.end()), uncertain.end());
  return uncertain;
}

void measure(MaxClearancePath& path) {
  for (std::size_t k = 0; k + 1 < path.waypoints.size(); ++k) {
    const Pose2 &from = path.waypoints[k], &to = path.waypoints[k + 1];
    path.length += std::hypot(to.x - from.x, to.y - from.y);
    path.turn += std::fabs(MotionChecker::shorterTurn(from.theta, to.theta));
  }
}

}  // namespace

MaxClearancePath maxClearancePath(const FreeSpace& space, const Pose2& start, const Pose2& goal,
                                  const MaxClearancePathOptions& options) {
  const Clock::time_point began = Clock::now();
  const Clearance startClearance = checkedEnd(space, start, options.startName, options);
  const Clearance goalClearance = checkedEnd(space, goal, options.goalName, options);
  MaxClearancePath path;
  path.startCell = startClearance.location.cell;
  path.goalCell = goalClearance.location.cell;
  path.startClearance = startClearance.lower;
  path.goalClearance = goalClearance.lower;
  if (path.startCell != path.goalCell) {
    path.status = PathStatus::infeasible;
    path.proof = "the start lies in free cell " + std::to_string(path.startCell) + " and the goal in free cell " +
                 std::to_string(path.goalCell);
    path.seconds = secondsSince(began);
    return path;
  }
  const MotionChecker checker(space);
  const Domain domain = domainOf(space, path.startCell, options);
  const Climb leave = climbFrom(space, checker, start, startClearance, domain);
  const Climb arrive = climbFrom(space, checker, goal, goalClearance, domain);
  const Pose2 passageStart{leave.to.x, leave.to.y, reducedAngle(leave.to.theta)};
  const Pose2 passageEnd{arrive.to.x, arrive.to.y, reducedAngle(arrive.to.theta)};
  const double passageStartUpper = space.clearance(passageStart, MotionChecker::kClearanceWidth).upper;
  const double passageEndUpper = space.clearance(passageEnd, MotionChecker::kClearanceWidth).upper;

  // The first path: along the cell graph's route (`best`: the best path certified so far).
  const Clock::time_point deadline =
      began + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.secondsLimit));
  QueryRate rate;
  std::optional<Passage> best =
      certifiedRoutePath(space, checker, passageStart, passageEnd, domain, deadline, rate, options);
  if (best) {
    path.secondsToFirstPath = secondsSince(began);
    if (!best->motionClearance.empty()) {
      tightenBounds(space, checker, *best, 0.02, deadline, rate, options.cancellation);
      // The route keeps to the middle of the faces' triangles, not of the passages:
      // pushed to their middle, its least clearance rises (within a share of the time).
      std::optional<Passage> raised =
          raisedPassage(space, checker, *best, domain, raisingDeadline(deadline, options), rate, options.cancellation);
      if (raised && raised->lower > best->lower) best = std::move(raised);
    }
  }
  double bestLower = best ? best->lower : -HUGE_VAL;

  // Halve the boxes that keep the bounds apart (not yet certain at the ratio asked,
  // chosen as said below), until a chain's lower bounds (or the best path's
  // clearance) reach that ratio of the upper bound.
  ClearanceBoxes boxes(space, domain.low, domain.high, checker.reach());
  ClearanceBoxes::Chain lowerChain;
  // Each round's search goes on from the last round's (ClearanceBoxes::UpperSearch).
  ClearanceBoxes::UpperSearch startSearch;
  ClearanceBoxes::ChainRoom lowerRoom;
  double raisedChain = 0;  // the bottleneck of the last chain raised
  for (;;) {
    options.cancellation.check();
    // Paths through boxes below the clearance of a path already found are worse.
    if (bestLower > 0) boxes.dropBelow(bestLower);
    boxes.dropOutside(path.startCell);
    const std::uint32_t from = boxes.leafAt(passageStart), to = boxes.leafAt(passageEnd);
    // Only chains at the target's level matter below: the search stops under it.
    const double cap = std::min(passageStartUpper, passageEndUpper);
    const std::vector<double>& fromStart = boxes.widestUpperFrom(from, to, options.clearanceRatio, cap, startSearch);
    if (fromStart[to] == -HUGE_VAL) {
      path.status = PathStatus::infeasible;
      path.proof = "no path of free cell " + std::to_string(path.startCell) + " stays inside the volume";
      break;
    }
    path.passage.upper = std::min({fromStart[to], passageStartUpper, passageEndUpper});
    const double target = options.clearanceRatio * path.passage.upper;
    lowerChain = boxes.widestChain(from, to, ClearanceBoxes::Bound::Lower, target, path.startCell, lowerRoom);
    if (lowerChain.bottleneck > 0 && path.secondsToFirstPath == 0) path.secondsToFirstPath = secondsSince(began);
    // A chain wider than the best path is raised (its bounds lose about a box's size
    // where the path's motions lose little): the path may then carry c_lo.
    if (lowerChain.bottleneck > bestLower && lowerChain.bottleneck > kRaiseAgain * raisedChain) {
      raisedChain = lowerChain.bottleneck;
      std::optional<Passage> raised =
          raisedChainPath(space, checker, boxes, lowerChain, passageStart, passageEnd, domain,
                          raisingDeadline(deadline, options), rate, options.cancellation);
      if (raised && raised->lower > bestLower) {
        best = std::move(raised);
        bestLower = best->lower;
      }
    }
    path.converged = std::max(lowerChain.bottleneck, bestLower) >= target;
    if (path.converged || secondsSince(began) > options.secondsLimit || boxes.size() > options.boxLimit) break;
    const std::vector<std::uint32_t> uncertain =
        boxesToHalve(boxes, ClearanceBoxes::chainTo(startSearch, to), fromStart,
                     boxes.reachedAbove(to, path.passage.upper / options.clearanceRatio), lowerChain,
                     {target, path.passage.upper, options.clearanceRatio}, path.startCell);
    if (uncertain.empty()) break;
    // The limit and cancellation are looked at between halvings too: a round can halve
    // thousands.
    boxes.splitEach(uncertain, [&] {
      options.cancellation.check();
      return secondsSince(began) <= options.secondsLimit;
    });
    ++path.refinements;
  }
  path.boxes = boxes.size();
  if (path.status == PathStatus::infeasible) {
    path.seconds = secondsSince(began);
    return path;
  }
  if (!path.converged) {
    lowerChain = boxes.widestChain(boxes.leafAt(passageStart), boxes.leafAt(passageEnd), ClearanceBoxes::Bound::Lower);
  }
  // The better of the best path raised and the chain's.
  std::optional<Passage> passage = best;
  if (lowerChain.bottleneck > 0 && lowerChain.bottleneck > bestLower) {
    passage = chainPath(boxes, lowerChain, passageStart, passageEnd);
  }
  if (!passage) {
    path.seconds = secondsSince(began);
    return path;
  }
  if (path.secondsToFirstPath == 0) path.secondsToFirstPath = secondsSince(began);
  path.status = PathStatus::solved;
  path.passage.lower = passage->lower;

  // start, leaving, the passage, arriving, goal.
  path.waypoints = {start};
  if (leave.to.x != start.x || leave.to.y != start.y) {
    path.waypoints.push_back(passageStart);
    path.motionClearance.push_back(leave.clearance);
  }
  const std::size_t first = path.waypoints.size() - 1;
  path.waypoints.insert(path.waypoints.end(), passage->waypoints.begin() + 1, passage->waypoints.end());
  path.motionClearance.insert(path.motionClearance.end(), passage->motionClearance.begin(),
                              passage->motionClearance.end());
  const std::size_t last = path.waypoints.size() - 1;
  if (arrive.to.x != goal.x || arrive.to.y != goal.y) {
    path.waypoints.push_back(goal);
    path.motionClearance.push_back(arrive.clearance);
  }
  shorten(checker, first, last, path.passage.lower, path.waypoints, path.motionClearance);

  path.whole.lower = *std::min_element(path.motionClearance.begin(), path.motionClearance.end());
  const ClearanceBoxes::Chain wholeChain =
      boxes.widestChain(boxes.leafAt(start), boxes.leafAt(goal), ClearanceBoxes::Bound::Upper);
  // Boxes below the passage's lower bound were dropped: a path through them has a
  // smaller bottleneck than that bound anyway.
  path.whole.upper =
      std::min({startClearance.upper, goalClearance.upper, std::max(wholeChain.bottleneck, path.passage.lower)});
  measure(path);
  path.seconds = secondsSince(began);
  return path;
}

}  // namespace freespace
