// OMPL's optimizing planners against the certified bounds of maxClearancePath: on each
// solvable problem, the query runs within `--seconds` (default 1); then PRM*, RRT* and
// BIT* (OMPL 1.5.2) each get ten times the query's time with
// MaximizeMinClearanceObjective, the exact test as their validity checker and the
// exact clearance (lower end) as its clearance function, their cost threshold out of
// reach so that they use the whole time. Their paths' least clearance, sampled densely
// (2,000 configurations per motion, the exact clearance's upper end), must never
// exceed the certified upper bound on any path's; how far below c_lo they stay is the
// comparison. (OMPL's motions are checked at its default resolution, so a path may
// clip a corner between samples: its dense least clearance is then negative.)
//
// Usage: bench_ompl_clearance [--seconds S] [PROBLEM.cfg ...]   (S whole seconds,
// default 1; default problems: every benchmarks/problems/*.cfg)
#include <ompl/base/objectives/MaximizeMinClearanceObjective.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "benchmark_arguments.h"
#include "freespace/freespace.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace freespace;

namespace {

Pose2 poseOf(const ob::State* state) {
  const auto* se2 = state->as<ob::SE2StateSpace::StateType>();
  return {se2->getX(), se2->getY(), se2->getYaw()};
}

/// Valid: free by the free space's locate (the exact test's answer); clearance: the
/// exact clearance's lower end.
class ExactValidity : public ob::StateValidityChecker {
 public:
  ExactValidity(const ob::SpaceInformationPtr& information, const FreeSpace& space)
      : ob::StateValidityChecker(information), space_(space) {
    specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::EXACT;
  }
  bool isValid(const ob::State* state) const override { return space_.locate(poseOf(state)).free; }
  double clearance(const ob::State* state) const override { return space_.clearance(poseOf(state)).lower; }

 private:
  const FreeSpace& space_;
};

/// The least of the exact clearance's upper ends at 2,001 configurations of each of
/// the path's motions (as OMPL's SE(2) space interpolates them).
double denseLeastClearance(const FreeSpace& space, const og::PathGeometric& path) {
  double least = HUGE_VAL;
  for (std::size_t k = 0; k + 1 < path.getStateCount(); ++k) {
    const Pose2 from = poseOf(path.getState(k)), to = poseOf(path.getState(k + 1));
    for (int i = 0; i <= 2000; ++i) {
      const Clearance clearance = space.clearance(MotionChecker::interpolate(from, to, i / 2000.0));
      least = std::min(least, clearance.location.free ? clearance.upper : -std::fabs(clearance.lower));
    }
  }
  return least;
}

struct Named {
  const char* name;
  std::function<ob::PlannerPtr(const ob::SpaceInformationPtr&)> make;
};

const std::vector<Named>& planners() {
  static const std::vector<Named> all{
      {"PRM*", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::PRMstar>(si); }},
      {"RRT*", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::RRTstar>(si); }},
      {"BIT*", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::BITstar>(si); }}};
  return all;
}

/// One planner on one problem for `seconds`: its path's dense least clearance, or none.
std::optional<double> plannerClearance(const FreeSpace& space, const LoadedProblem& loaded, const Named& planner,
                                       double seconds) {
  auto stateSpace = std::make_shared<ob::SE2StateSpace>();
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, loaded.problem.volume->min().x());
  bounds.setLow(1, loaded.problem.volume->min().y());
  bounds.setHigh(0, loaded.problem.volume->max().x());
  bounds.setHigh(1, loaded.problem.volume->max().y());
  stateSpace->setBounds(bounds);
  og::SimpleSetup setup(stateSpace);
  const ob::SpaceInformationPtr information = setup.getSpaceInformation();
  setup.setStateValidityChecker(std::make_shared<ExactValidity>(information, space));
  ob::ScopedState<ob::SE2StateSpace> start(stateSpace), goal(stateSpace);
  start->setXY(loaded.problem.start.x, loaded.problem.start.y);
  start->setYaw(loaded.problem.start.theta);
  goal->setXY(loaded.problem.goal.x, loaded.problem.goal.y);
  goal->setYaw(loaded.problem.goal.theta);
  setup.setStartAndGoalStates(start, goal);
  auto objective = std::make_shared<ob::MaximizeMinClearanceObjective>(information);
  objective->setCostThreshold(ob::Cost(HUGE_VAL));  // never satisfied: the whole time is used
  setup.setOptimizationObjective(objective);
  setup.setPlanner(planner.make(information));
  if (setup.solve(seconds) != ob::PlannerStatus::EXACT_SOLUTION) return std::nullopt;
  return denseLeastClearance(space, setup.getSolutionPath());
}

std::string number(double value) {
  std::ostringstream text;
  text << std::setprecision(6) << value;
  return text.str();
}

void compare(const std::string& cfg, double seconds) {
  const LoadedProblem loaded = loadProblem(cfg);
  if (!loaded.problem.volume) throw std::invalid_argument(cfg + ": no volume.min/max: OMPL needs bounds");
  const FreeSpace space(loaded.robot, loaded.world);
  // The graph and its slices' faces first, as `freespace plan` does: they serve every
  // query, and the query's time limit is the query's.
  space.sliceFaces();
  MaxClearancePathOptions options;
  options.volumeLow = std::array<double, 2>{loaded.problem.volume->min().x(), loaded.problem.volume->min().y()};
  options.volumeHigh = std::array<double, 2>{loaded.problem.volume->max().x(), loaded.problem.volume->max().y()};
  options.secondsLimit = seconds;
  const MaxClearancePath path = maxClearancePath(space, loaded.problem.start, loaded.problem.goal, options);
  const std::string name = std::filesystem::path(cfg).stem().string();
  if (path.status != PathStatus::solved) {
    std::cout << "| " << name << " | " << (path.status == PathStatus::infeasible ? "infeasible" : "unfinished")
              << " | - | " << number(path.seconds) << " | - | - | - | - | - |" << std::endl;
    return;
  }
  const double plannerSeconds = 10 * path.seconds;
  for (const Named& planner : planners()) {
    const std::optional<double> least = plannerClearance(space, loaded, planner, plannerSeconds);
    std::cout << "| " << name << " | " << number(path.whole.lower) << " | " << number(path.whole.upper) << " | "
              << number(path.seconds) << " | " << planner.name << " | " << number(plannerSeconds) << " | "
              << (least ? number(*least) : "no path") << " | "
              << (least ? (*least <= path.whole.upper ? "yes" : "NO") : "-") << " | "
              << (least && path.whole.lower > 0 ? number(*least / path.whole.lower) : "-") << " |" << std::endl;
  }
}

int run(int argc, char** argv) {
  const auto [seconds, problems] =
      benchmarks::countedProblems(argc, argv, "--seconds", 1, "bench_ompl_clearance [--seconds S] [PROBLEM.cfg ...]");
  ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
  std::cout << "| problem | c_lo (whole path) | c_hi (any path) | query s | planner | planner s | planner's least "
               "clearance (dense) | at most c_hi | planner / c_lo |\n"
               "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
            << std::endl;
  for (const std::string& problem : problems) compare(problem, seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return benchmarks::reportingErrors("bench_ompl_clearance", [&] { return run(argc, argv); });
}
