// Query time of the exact collision test against FCL, for a 40-triangle non-convex
// robot in a floor plan of about 2,000 triangles (target for the exact test: under
// 50 microseconds per query). Poses are uniform over the floor plan's bounds and
// all angles, from a fixed seed; the same poses are used for every checker. Each
// benchmark runs on all poses and on the free ones only (argument free_only).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/scenes/scene_generator.h"

using namespace freespace;

namespace {

/// An 11-pointed star prism: 22 side triangles + 2 x 9 cap triangles = 40.
Mesh starRobot() {
  Polygon2 star;
  const int points = 11;
  for (int i = 0; i < points; ++i) {
    const double angle = 2 * M_PI * i / points;
    const double radius = i % 2 == 0 ? 0.75 : 0.375;
    star.emplace_back(std::round(radius * std::cos(angle) * 64) / 64, std::round(radius * std::sin(angle) * 64) / 64);
  }
  return makeCheckedMesh(extrudePolygon(star, 0, 0.5), "star robot");
}

struct BenchmarkScene {
  Mesh robot = starRobot();
  Mesh world;
  std::vector<Pose2> poses;
  std::vector<Pose2> freePoses;  // those of `poses` that the exact test finds free

  BenchmarkScene() {
    FloorPlanLayout layout;
    layout.rooms = 64;
    layout.columns = 8;
    world = makeCheckedMesh(makeFloorPlan(layout, 7).walls, "floor plan");
    std::mt19937_64 random(42);
    const Box3 bounds = world.bounds();
    std::uniform_real_distribution<double> x(bounds.min().x(), bounds.max().x());
    std::uniform_real_distribution<double> y(bounds.min().y(), bounds.max().y());
    std::uniform_real_distribution<double> theta(-M_PI, M_PI);
    for (int i = 0; i < 4096; ++i) poses.push_back({x(random), y(random), theta(random)});
    const ExactCollisionChecker checker(robot, world);
    for (const Pose2& pose : poses) {
      if (!checker.inCollision(pose)) freePoses.push_back(pose);
    }
  }

  /// Benchmark argument 0: all poses; 1: free poses only (no early exit).
  const std::vector<Pose2>& posesFor(const benchmark::State& state) const {
    return state.range(0) == 0 ? poses : freePoses;
  }
};

const BenchmarkScene& scene() {
  static const BenchmarkScene instance;
  return instance;
}

/// Runs `query` (true when the pose collides) over the benchmark's poses.
template <class Query>
void runQueries(benchmark::State& state, Query&& query) {
  const std::vector<Pose2>& poses = scene().posesFor(state);
  std::size_t index = 0, collisions = 0;
  for (auto _ : state) {
    const bool hit = query(poses[index++ % poses.size()]);
    collisions += hit;
    benchmark::DoNotOptimize(hit);
  }
  state.counters["robot_triangles"] = static_cast<double>(scene().robot.triangles().size());
  state.counters["world_triangles"] = static_cast<double>(scene().world.triangles().size());
  state.counters["collision_fraction"] = static_cast<double>(collisions) / static_cast<double>(index);
}

void ExactCollisionQuery(benchmark::State& state) {
  const ExactCollisionChecker checker(scene().robot, scene().world);
  runQueries(state, [&checker](const Pose2& pose) { return checker.inCollision(pose); });
  const auto counts = checker.predicateCounts();
  state.counters["predicates_per_query"] =
      static_cast<double>(counts.evaluated) / static_cast<double>(state.iterations());
  state.counters["exact_fallback_fraction"] =
      counts.evaluated ? static_cast<double>(counts.exact) / static_cast<double>(counts.evaluated) : 0.0;
}

void FclCollisionQuery(benchmark::State& state) {
  const FclCollisionChecker checker(scene().robot, scene().world);
  runQueries(state, [&checker](const Pose2& pose) { return checker.inCollision(pose); });
}

void FclDistanceQuery(benchmark::State& state) {
  const FclCollisionChecker checker(scene().robot, scene().world);
  runQueries(state, [&checker](const Pose2& pose) { return checker.distance(pose) <= 0; });
}

}  // namespace

BENCHMARK(ExactCollisionQuery)->Arg(0)->Arg(1)->ArgName("free_only")->Unit(benchmark::kMicrosecond);
BENCHMARK(FclCollisionQuery)->Arg(0)->Arg(1)->ArgName("free_only")->Unit(benchmark::kMicrosecond);
BENCHMARK(FclDistanceQuery)->Arg(0)->Arg(1)->ArgName("free_only")->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
