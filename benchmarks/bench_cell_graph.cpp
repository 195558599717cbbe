// The free cell graph (docs/design.md section 7) on the bundled scenes: its size and
// the time it takes against the construction's (target: at most half; the medians of
// five fresh spaces), and whether its edges join the start's and the goal's nodes
// (they must exactly when both lie in one cell).
//
// Usage: bench_cell_graph [PROBLEM.cfg ...]   (default: every benchmarks/problems/*.cfg)
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "benchmark_arguments.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/free_space.h"

using namespace freespace;

namespace {

/// "yes" or "no" when the graph joins the start's and the goal's nodes or not, then
/// whether they share a cell; "blocked" when one of them is.
std::string startAndGoal(const FreeSpace& space, const PlanarProblem& problem) {
  const std::optional<std::uint32_t> start = space.nodeOf(problem.start), goal = space.nodeOf(problem.goal);
  if (!start || !goal) return "blocked";
  const bool sameCell = space.locate(problem.start).cell == space.locate(problem.goal).cell;
  return std::string(space.cellGraph().route(*start, *goal) ? "yes" : "no") + " (" +
         (sameCell ? "one cell" : "two cells") + ")";
}

/// The middle of the values (the upper one of an even count).
double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

/// The problem's construction and graph, each timed in `runs` fresh spaces (the
/// median of each is printed: on a small scene one run moves by half).
void measure(const std::string& cfg, int runs) {
  const LoadedProblem loaded = loadProblem(cfg);
  std::vector<double> builds, graphs;
  std::unique_ptr<FreeSpace> space;
  for (int run = 0; run < runs; ++run) {
    space.reset();  // not in the time, nor two spaces at once
    auto start = std::chrono::steady_clock::now();
    space = std::make_unique<FreeSpace>(loaded.robot, loaded.world);
    builds.push_back(benchmarks::secondsSince(start));
    // The graph with its slices' faces: what every path query walks, built once.
    start = std::chrono::steady_clock::now();
    space->cellGraph();
    space->sliceFaces();
    graphs.push_back(benchmarks::secondsSince(start));
  }
  const CellGraph& graph = space->cellGraph();
  const double build = median(builds), graphSeconds = median(graphs);
  std::cout << "| " << std::filesystem::path(cfg).stem().string() << " | " << space->cellCount() << " | "
            << graph.criticalAngles().size() << " | " << graph.nodes().size() << " | " << graph.edges().size() << " | "
            << build << " | " << graphSeconds << " | " << graphSeconds / build << " | "
            << startAndGoal(*space, loaded.problem) << " |" << std::endl;
}

int run(int argc, char** argv) {
  std::vector<std::string> problems;
  for (int i = 1; i < argc; ++i) {
    benchmarks::rejectOption(argv[i], "bench_cell_graph [PROBLEM.cfg ...]");
    problems.push_back(argv[i]);
  }
  if (problems.empty()) problems = benchmarks::bundledProblems();
  benchmarks::requireFiles(problems);
  std::cout << "| problem | free cells | critical angles | nodes | edges | build s | graph s | graph / build | "
               "start and goal joined |\n"
               "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
            << std::endl;
  constexpr int kRuns = 5;
  for (const std::string& problem : problems) measure(problem, kRuns);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return benchmarks::reportingErrors("bench_cell_graph", [&] { return run(argc, argv); });
}
