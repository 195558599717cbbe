// Locate against the exact collision test on the bundled scenes: builds each scene's
// free space, then locates random configurations (x, y over the environment's box
// grown by the robot's reach, theta uniform) and compares free / blocked with the
// exact collision test on the same perturbed meshes. Prints, per scene, the
// construction's stage times and counts, the disagreements, the free cells met, and
// the time per locate and per collision test.
//
// Usage: bench_locate [--samples N] [PROBLEM.cfg ...]   (default: 100000 samples,
// every benchmarks/problems/*.cfg)
#include <algorithm>
#include <chrono>
#include <iostream>
#include <random>
#include <set>
#include <string>

#include "benchmark_arguments.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/space/free_space.h"

using namespace freespace;

namespace {

void measure(const std::string& cfg, int samples) {
  const LoadedProblem loaded = loadProblem(cfg);
  auto start = std::chrono::steady_clock::now();
  const FreeSpace space(loaded.robot, loaded.world);
  const double buildSeconds = benchmarks::secondsSince(start);
  const ExactCollisionChecker collision(space.meshes().robot, space.meshes().world);
  const Box3 world = space.meshes().world.bounds();
  const double reach = space.meshes().robot.bounds().sizes().head<2>().norm();
  std::mt19937_64 random(20261201);
  std::uniform_real_distribution<double> x(world.min().x() - reach, world.max().x() + reach);
  std::uniform_real_distribution<double> y(world.min().y() - reach, world.max().y() + reach);
  std::uniform_real_distribution<double> theta(-M_PI, M_PI);
  std::vector<Pose2> poses(static_cast<std::size_t>(samples));
  for (Pose2& pose : poses) pose = {x(random), y(random), theta(random)};
  std::vector<Location> locations;
  locations.reserve(poses.size());
  start = std::chrono::steady_clock::now();
  // Drawn in the construction's coordinates, where the exact test runs; located in the input's.
  const double scale = space.meshes().scale;
  for (const Pose2& pose : poses) locations.push_back(space.locate({pose.x / scale, pose.y / scale, pose.theta}));
  const double locateSeconds = benchmarks::secondsSince(start);
  int disagreements = 0, free = 0;
  std::set<std::uint32_t> cellsMet;
  start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const bool collides = collision.inCollision(poses[i]);
    disagreements += locations[i].free == collides;
    if (locations[i].free) {
      ++free;
      cellsMet.insert(locations[i].cell);
    }
  }
  const double collisionSeconds = benchmarks::secondsSince(start);
  std::cout << std::filesystem::path(cfg).stem().string() << ": robot " << space.meshes().robot.triangles().size()
            << " triangles, world " << space.meshes().world.triangles().size() << " triangles; build "
            << buildSeconds << " s (";
  for (const StageTime& stage : space.stageTimes()) std::cout << stage.stage << " " << stage.seconds << " s, ";
  std::cout << space.arrangement().patches.size() << " patches, " << space.shellCount() << " shells, "
            << space.freeShellCount() << " free, " << space.cellCount() << " free cells); " << samples
            << " configurations, " << free << " free, in " << cellsMet.size() << " cells; disagreements with the exact "
            << "collision test: " << disagreements << "; locate " << 1e6 * locateSeconds / samples
            << " us, collision test " << 1e6 * collisionSeconds / samples << " us per configuration" << std::endl;
}


int run(int argc, char** argv) {
  const auto [samples, problems] =
      benchmarks::sampledProblems(argc, argv, 100000, "bench_locate [--samples N] [PROBLEM.cfg ...]");
  for (const std::string& problem : problems) measure(problem, samples);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return benchmarks::reportingErrors("bench_locate", [&] { return run(argc, argv); });
}
