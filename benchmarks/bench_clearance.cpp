// Clearance against the exact collision test on the bundled scenes (the oracle of
// tests/clearance_oracle.h: each configuration keeps its state on 64 directions up to
// |clearance| (1 - 1e-6) and changes it within |clearance| (1 + 1e-6)), with the time
// per clearance query and the widest certified interval.
//
// Usage: bench_clearance [--samples N] [PROBLEM.cfg ...]   (default: 10000 samples,
// every benchmarks/problems/*.cfg)
#include <filesystem>
#include <iostream>
#include <string>

#include "benchmark_arguments.h"
#include "clearance_oracle.h"
#include "freespace/problem/planar_problem.h"

using namespace freespace;

namespace {

void measure(const std::string& cfg, int samples) {
  const LoadedProblem loaded = loadProblem(cfg);
  const FreeSpace space(loaded.robot, loaded.world);
  const testing::ClearanceCheck check = testing::clearanceAgainstCollision(space, samples, 20261204);
  std::cout << "| " << std::filesystem::path(cfg).stem().string() << " | " << check.samples << " | " << check.free
            << " | " << check.keepsStateTooClose << " | " << check.noChangeWithin << " | " << check.widestRelative
            << " | " << 1e6 * check.clearanceSeconds / check.samples << " |" << std::endl;
}

int run(int argc, char** argv) {
  const auto [samples, problems] =
      benchmarks::sampledProblems(argc, argv, 10000, "bench_clearance [--samples N] [PROBLEM.cfg ...]");
  std::cout << "| problem | configurations | free | state changed nearer than the clearance | no change within "
               "it | widest interval (relative) | us per clearance |\n| --- | --- | --- | --- | --- | --- | --- |"
            << std::endl;
  for (const std::string& problem : problems) measure(problem, samples);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return benchmarks::reportingErrors("bench_clearance", [&] { return run(argc, argv); });
}
