// The first construction stages on the bundled scenes: perturb the meshes, build
// their topology, enumerate VF, FV and EE patches, their segments, curves, overlaps
// and vertices, subdivide every patch into sub-faces and glue sub-faces across
// curves and around spirals. Prints, per scene, the counts, the time of each step, and how the
// predicates were decided (the share decided in double intervals is the robust
// layer's target, at least 95%).
//
// Usage: bench_patches [PROBLEM.cfg ...]   (default: every benchmarks/problems/*.cfg)
#include <chrono>
#include <iomanip>
#include <iostream>

#include "benchmark_arguments.h"
#include "freespace/geometry/patch.h"
#include "freespace/geometry/patch_curve.h"
#include "freespace/geometry/patch_subdivision.h"
#include "freespace/geometry/patch_vertex.h"
#include "freespace/geometry/perturbed_meshes.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/topology/shells.h"

using namespace freespace;

namespace {

void measure(const std::string& cfg) {
  const LoadedProblem loaded = loadProblem(cfg);
  auto start = std::chrono::steady_clock::now();
  const PerturbedMeshes meshes = perturbMeshes(loaded.robot, loaded.world, PerturbationSettings{});
  const double perturbSeconds = benchmarks::secondsSince(start);
  PredicateStatistics statistics;
  start = std::chrono::steady_clock::now();
  const MeshTopology robotTopology(meshes.robot, statistics), worldTopology(meshes.world, statistics);
  const double topologySeconds = benchmarks::secondsSince(start);
  AngleAlgebra algebra(statistics);
  start = std::chrono::steady_clock::now();
  const auto vertexFacet = vertexFacetPatches(meshes.robot, robotTopology, meshes.world, worldTopology, algebra);
  const double vertexFacetSeconds = benchmarks::secondsSince(start);
  start = std::chrono::steady_clock::now();
  const auto edgeEdge = edgeEdgePatches(meshes.robot, robotTopology, meshes.world, worldTopology, algebra);
  const double edgeEdgeSeconds = benchmarks::secondsSince(start);
  std::vector<Patch> patches = vertexFacet;
  patches.insert(patches.end(), edgeEdge.begin(), edgeEdge.end());
  start = std::chrono::steady_clock::now();
  const auto geometries = patchGeometries(patches, meshes.robot, robotTopology, meshes.world, worldTopology, statistics);
  const double segmentSeconds = benchmarks::secondsSince(start);
  start = std::chrono::steady_clock::now();
  const auto pairs = candidatePatchPairs(geometries);
  const double pairSeconds = benchmarks::secondsSince(start);
  start = std::chrono::steady_clock::now();
  const auto curves = patchCurves(geometries, algebra);
  const double curveSeconds = benchmarks::secondsSince(start);
  start = std::chrono::steady_clock::now();
  const auto overlaps = patchOverlaps(geometries, algebra);
  const double overlapSeconds = benchmarks::secondsSince(start);
  start = std::chrono::steady_clock::now();
  const auto vertices = patchVertices(geometries, curves, overlaps, algebra);
  const double vertexSeconds = benchmarks::secondsSince(start);
  start = std::chrono::steady_clock::now();
  std::size_t slabs = 0, subFaces = 0, curveGlues = 0, spiralGlues = 0, horizontalGlues = 0, unmatched = 0;
  std::size_t shellCount = 0, closedShells = 0;
  std::string subdivisionFailure;
  double subdivisionSeconds = 0, gluingSeconds = 0, curveGluingSeconds = 0, spiralGluingSeconds = 0,
         edgeGluingSeconds = 0;
  try {
    const std::vector<PatchSubdivision> subdivisions = patchSubdivisions(geometries, curves, vertices, overlaps, algebra);
    for (const PatchSubdivision& subdivision : subdivisions) {
      slabs += subdivision.slabs.size();
      subFaces += subdivision.faceCount;
    }
    subdivisionSeconds = benchmarks::secondsSince(start);
    start = std::chrono::steady_clock::now();
    const SubFaceGluing acrossCurves = glueAcrossCurves(geometries, curves, subdivisions, algebra);
    curveGluingSeconds = benchmarks::secondsSince(start);
    start = std::chrono::steady_clock::now();
    const SubFaceGluing aroundSpirals = glueAroundSpirals(geometries, subdivisions, algebra);
    spiralGluingSeconds = benchmarks::secondsSince(start);
    start = std::chrono::steady_clock::now();
    const SubFaceGluing acrossEdges = glueAcrossHorizontalEdges(geometries, curves, overlaps, subdivisions, algebra);
    edgeGluingSeconds = benchmarks::secondsSince(start);
    gluingSeconds = curveGluingSeconds + spiralGluingSeconds + edgeGluingSeconds;
    curveGlues = acrossCurves.glues.size();
    spiralGlues = aroundSpirals.glues.size();
    horizontalGlues = acrossEdges.glues.size();
    unmatched = aroundSpirals.unmatched.size() + acrossEdges.unmatched.size();
    const Shells shells(subdivisions, {&acrossCurves, &aroundSpirals, &acrossEdges});
    shellCount = shells.count();
    for (std::uint32_t shell = 0; shell < shells.count(); ++shell) closedShells += shells.closed(shell);
  } catch (const std::logic_error& error) {
    subdivisionFailure = std::string(" FAILED: ") + error.what();
  }
  std::cout << std::filesystem::path(cfg).stem().string() << ": robot " << meshes.robot.triangles().size()
            << " triangles, world " << meshes.world.triangles().size() << " triangles; " << vertexFacet.size()
            << " VF/FV patches, " << edgeEdge.size() << " EE patches; seconds: perturb " << perturbSeconds
            << ", topology " << topologySeconds << ", VF/FV " << vertexFacetSeconds << ", EE " << edgeEdgeSeconds << ", segments " << segmentSeconds << ", candidate pairs "
            << pairSeconds << " (" << pairs.size() << "), curves " << curveSeconds << " (" << curves.size() << "), overlaps " << overlapSeconds << " (" << overlaps.size()
            << "), vertices "
            << vertexSeconds << " (" << vertices.size() << "), subdivision " << subdivisionSeconds << " (" << slabs
            << " slabs, " << subFaces << " sub-faces" << subdivisionFailure << "), gluing " << gluingSeconds << " (curves " << curveGluingSeconds << " s, spirals "
            << spiralGluingSeconds << " s, horizontal edges " << edgeGluingSeconds << " s; "
            << curveGlues << " across curves, " << spiralGlues << " around spirals, " << horizontalGlues
            << " across horizontal edges, " << unmatched << " sub-faces unmatched; " << shellCount << " shells, "
            << closedShells << " closed)"
            << "; decided in double intervals " << std::setprecision(4) << 100 * statistics.doubleIntervalFraction()
            << "%\n"
            << statistics.toText();
}


int run(int argc, char** argv) {
  std::vector<std::string> problems(argv + 1, argv + argc);
  for (const std::string& argument : problems) benchmarks::rejectOption(argument, "bench_patches [PROBLEM.cfg ...]");
  if (problems.empty()) problems = benchmarks::bundledProblems();
  benchmarks::requireFiles(problems);
  for (const std::string& problem : problems) measure(problem);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return benchmarks::reportingErrors("bench_patches", [&] { return run(argc, argv); });
}
