#include <chrono>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "free_space_input.h"
#include "freespace/exports/path_svg.h"
#include "freespace/geometry/stage_clock.h"
#include "freespace/input_error.h"
#include "freespace/io/output_file.h"
#include "freespace/problem/path_file.h"
#include "freespace/space/max_clearance_path.h"
#include "number_checks.h"
#include "stop_signals.h"

namespace freespace::cli {

namespace {

using Clock = std::chrono::steady_clock;

struct PlanOptions {
  FreeSpaceInput input;
  std::vector<double> start, goal;
  double ratio = MaxClearancePathOptions{}.clearanceRatio;
  double secondsLimit = MaxClearancePathOptions{}.secondsLimit;
  bool json = false, force = false;
  std::string pathOut, svg;
};

const char* statusName(PathStatus status) {
  switch (status) {
    case PathStatus::solved:
      return "solved";
    case PathStatus::infeasible:
      return "infeasible";
    default:
      return "unfinished";
  }
}

/// JSON has no infinity: an unbounded clearance is null.
nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

nlohmann::json planJson(const MaxClearancePath& path, const nlohmann::json& seconds) {
  nlohmann::json waypoints = nlohmann::json::array();
  for (const Pose2& pose : path.waypoints) waypoints.push_back({pose.x, pose.y, pose.theta});
  nlohmann::json motions = nlohmann::json::array();
  for (double clearance : path.motionClearance) motions.push_back(number(clearance));
  nlohmann::json answer = {{"status", statusName(path.status)},
                           {"start_cell", path.startCell},
                           {"goal_cell", path.goalCell},
                           {"start_clearance", number(path.startClearance)},
                           {"goal_clearance", number(path.goalClearance)},
                           {"seconds", seconds}};
  if (path.status == PathStatus::infeasible) {
    answer["proof"] = path.proof;
    return answer;
  }
  answer.update({{"clearance_lower", number(path.passage.lower)},
                 {"clearance_upper", number(path.passage.upper)},
                 {"whole_clearance_lower", number(path.whole.lower)},
                 {"whole_clearance_upper", number(path.whole.upper)},
                 {"converged", path.converged},
                 {"length", path.length},
                 {"turn", path.turn},
                 {"waypoints", waypoints},
                 {"motion_clearance", motions},
                 {"boxes", path.boxes}});
  return answer;
}

void printPlan(const nlohmann::json& plan) {
  std::cout << plan["status"].get<std::string>();
  if (plan.contains("proof")) {
    std::cout << ": " << plan["proof"].get<std::string>() << "\n";
  } else if (plan["status"] == "solved") {
    std::cout << ": clearance " << plan["clearance_lower"] << " certified on the path, at most "
              << plan["clearance_upper"] << " on any path" << (plan["converged"] ? "" : " (bounds not converged)")
              << "; " << plan["waypoints"].size() << " waypoints, length " << plan["length"] << ", turn "
              << plan["turn"] << " rad\n";
    std::cout << "start clearance " << plan["start_clearance"] << ", goal clearance " << plan["goal_clearance"]
              << "; whole path: clearance " << plan["whole_clearance_lower"] << ", at most "
              << plan["whole_clearance_upper"] << " on any path\n";
  } else {
    std::cout << ": no path certified within the time limit\n";
  }
  const nlohmann::json& seconds = plan["seconds"];
  std::cout << "seconds: construction " << seconds["construction"] << ", graph " << seconds["graph"] << ", query "
            << seconds["query"] << " (first path " << seconds["first_path"] << ")\n";
}

Pose2 endFrom(const std::vector<double>& given, const Pose2& fromProblem) {
  return given.empty() ? fromProblem : Pose2{given[0], given[1], given[2]};
}

void runPlan(const PlanOptions& options) {
  const Clock::time_point began = Clock::now();
  LoadedProblem loaded;
  const std::unique_ptr<FreeSpace> space = options.input.build(loaded);
  const double construction = secondsSince(began);
  const bool fromCfg = !loaded.cfgPath.empty();
  if (!fromCfg && (options.start.empty() || options.goal.empty())) {
    throw InputError("plan", "--start and --goal are needed without --cfg");
  }
  MaxClearancePathOptions query;
  query.clearanceRatio = options.ratio;
  query.secondsLimit = options.secondsLimit;
  query.startName = options.start.empty() ? loaded.cfgPath + ": start" : "--start";
  query.goalName = options.goal.empty() ? loaded.cfgPath + ": goal" : "--goal";
  if (fromCfg && loaded.problem.volume) {
    query.volumeLow = std::array<double, 2>{loaded.problem.volume->min().x(), loaded.problem.volume->min().y()};
    query.volumeHigh = std::array<double, 2>{loaded.problem.volume->max().x(), loaded.problem.volume->max().y()};
  }
  const Pose2 start = endFrom(options.start, loaded.problem.start), goal = endFrom(options.goal, loaded.problem.goal);
  MaxClearancePath path;
  double graph = 0;
  {
    const StoppableSection section;
    query.cancellation = section.cancellation();
    // The graph and its slices' faces first (the query's first path follows them), so
    // that their time is their own.
    const Clock::time_point graphBegan = Clock::now();
    space->sliceFaces();
    graph = secondsSince(graphBegan);
    path = maxClearancePath(*space, start, goal, query);
  }
  const nlohmann::json plan = planJson(path, {{"construction", construction},
                                              {"graph", graph},
                                              {"query", path.seconds},
                                              {"first_path", path.secondsToFirstPath}});
  if (!options.pathOut.empty() && path.status == PathStatus::solved) {
    writePath(path.waypoints, options.pathOut, options.force);
  }
  if (!options.svg.empty()) {
    writeFile(options.svg, options.force, [&](std::ostream& out) { writePathSvg(*space, start, goal, path, out); });
  }
  if (options.json) {
    std::cout << plan.dump(2) << "\n";
  } else {
    printPlan(plan);
  }
}

}  // namespace

void addPlanCommand(CLI::App& app) {
  auto options = std::make_shared<PlanOptions>();
  CLI::App* command = app.add_subcommand(
      "plan",
      "Maximum clearance path from the start to the goal: 'solved' with a path whose clearance is certified within "
      "--ratio of the best any path can have, or 'infeasible' with its proof (start and goal in different free "
      "cells); exit status 0 for both");
  options->input.addOptions(*command);
  options->input.addSpaceFileOption(*command);
  command->add_option("--start", options->start, "start X Y THETA (default: the --cfg's)")
      ->expected(3)
      ->check(finiteNumber());
  command->add_option("--goal", options->goal, "goal X Y THETA (default: the --cfg's)")
      ->expected(3)
      ->check(finiteNumber());
  command
      ->add_option("--ratio", options->ratio,
                   "the path's certified clearance must reach this fraction of the bound on any path's "
                   "(default 0.98)")
      ->check(CLI::Range(0.5, 0.9999));
  command
      ->add_option("--seconds-limit", options->secondsLimit,
                   "stop refining the bounds after this many seconds (default 60)")
      ->check(finiteNonNegative());
  command->add_option("--path-out", options->pathOut, "write the path as an OMPL.app .path file");
  command->add_option("--svg", options->svg,
                      "draw the path as SVG: the environment's footprint, the robot along the path coloured by "
                      "clearance, start and goal");
  command->add_flag("--force", options->force, "overwrite an existing --path-out or --svg file");
  command->add_flag("--json", options->json, "print JSON");
  command->callback([options]() { runPlan(*options); });
}

}  // namespace freespace::cli
