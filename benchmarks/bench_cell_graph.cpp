// The free cell graph (docs/design.md section 7) on the bundled scenes: its size and
// the time it takes against the construction's (target: at most half), and whether
// its edges join the start's and the goal's nodes (they must exactly when both lie in
// one cell).
//
// Usage: bench_cell_graph [PROBLEM.cfg ...]   (default: every benchmarks/problems/*.cfg)
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>

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

void measure(const std::string& cfg) {
  const LoadedProblem loaded = loadProblem(cfg);
  auto start = std::chrono::steady_clock::now();
  const FreeSpace space(loaded.robot, loaded.world);
  const double build = benchmarks::secondsSince(start);
  // The graph with its slices' faces: what every path query walks, built once.
  start = std::chrono::steady_clock::now();
  const CellGraph& graph = space.cellGraph();
  space.sliceFaces();
  const double graphSeconds = benchmarks::secondsSince(start);
  std::cout << "| " << std::filesystem::path(cfg).stem().string() << " | " << space.cellCount() << " | "
            << graph.criticalAngles().size() << " | " << graph.nodes().size() << " | " << graph.edges().size() << " | "
            << build << " | " << graphSeconds << " | " << graphSeconds / build << " | "
            << startAndGoal(space, loaded.problem) << " |" << std::endl;
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
  for (const std::string& problem : problems) measure(problem);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return benchmarks::reportingErrors("bench_cell_graph", [&] { return run(argc, argv); });
}
