// Loading meshes: what repair and solid interpretation (prepareMesh) cost over the
// checks a mesh always had (Mesh::fromSoup), on a closed manifold floor plan (the
// target: under 5% extra), and on the generator's soups imitating modelling tools'
// files (the target: a 100,000-triangle soup under 2 s). The soups are built in
// memory (float noise included), so file reading is not timed.
#include <benchmark/benchmark.h>

#include "freespace/geometry/mesh_preparation.h"
#include "freespace/scenes/scene_generator.h"

using namespace freespace;

namespace {

TriangleSoup closedFloorPlan(unsigned rooms) {
  FloorPlanLayout layout;
  layout.rooms = rooms;
  layout.columns = 16;
  const Mesh mesh = makeCheckedMesh(makeFloorPlan(layout, 7).walls, "floor plan");
  return {mesh.vertices(), mesh.triangles()};
}

TriangleSoup soupMaze(unsigned thousands) {
  const Scene scene = makeScene("soup_maze_" + std::to_string(thousands));
  return *scene.worldSoup;
}

void recordTriangles(benchmark::State& state, const TriangleSoup& soup) {
  state.counters["triangles"] = static_cast<double>(soup.triangles.size());
}

void BM_ClosedFloorPlanChecksOnly(benchmark::State& state) {
  const TriangleSoup soup = closedFloorPlan(static_cast<unsigned>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(Mesh::fromSoup(soup, "floor plan"));
  recordTriangles(state, soup);
}

void BM_ClosedFloorPlanPrepared(benchmark::State& state) {
  const TriangleSoup soup = closedFloorPlan(static_cast<unsigned>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(prepareMesh(soup, "floor plan"));
  recordTriangles(state, soup);
}

void BM_SoupMazePrepared(benchmark::State& state) {
  const TriangleSoup soup = soupMaze(static_cast<unsigned>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(prepareMesh(soup, "soup maze"));
  recordTriangles(state, soup);
}

}  // namespace

BENCHMARK(BM_ClosedFloorPlanChecksOnly)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ClosedFloorPlanPrepared)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SoupMazePrepared)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
