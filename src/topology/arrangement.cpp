#include "freespace/topology/arrangement.h"

namespace freespace {

Arrangement buildArrangement(std::vector<PatchGeometry> patches, AngleAlgebra& algebra, StageClock& clock) {
  const Cancellation& cancellation = clock.cancellation();
  Arrangement a;
  a.patches = std::move(patches);
  // The pairs of patches whose boxes meet: the only ones that can cross or overlap.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> candidates;
  a.curves = clock.run("curves", [&] {
    a.boxIndex = std::make_shared<const PatchBoxIndex>(a.patches, cancellation);
    candidates = a.boxIndex->meetingPairs(cancellation);
    return patchCurves(a.patches, candidates, algebra, cancellation);
  });
  a.overlaps = clock.run("overlaps", [&] { return patchOverlaps(a.patches, candidates, algebra, cancellation); });
  a.vertices =
      clock.run("vertices", [&] { return patchVertices(a.patches, a.curves, a.overlaps, algebra, cancellation); });
  a.subdivisions = clock.run("subdivision", [&] {
    return patchSubdivisions(a.patches, a.curves, a.vertices, a.overlaps, algebra, cancellation);
  });
  a.acrossCurves = clock.run(
      "gluing_curves", [&] { return glueAcrossCurves(a.patches, a.curves, a.subdivisions, algebra, cancellation); });
  a.aroundSpirals =
      clock.run("gluing_spirals", [&] { return glueAroundSpirals(a.patches, a.subdivisions, algebra, cancellation); });
  a.acrossHorizontalEdges = clock.run("gluing_horizontal", [&] {
    return glueAcrossHorizontalEdges(a.patches, a.curves, a.overlaps, a.subdivisions, algebra, cancellation);
  });
  a.shells = clock.run("shells", [&] {
    return Shells(a.subdivisions, {&a.acrossCurves, &a.aroundSpirals, &a.acrossHorizontalEdges});
  });
  return a;
}

Arrangement buildArrangement(std::vector<PatchGeometry> patches, AngleAlgebra& algebra) {
  StageClock clock;
  return buildArrangement(std::move(patches), algebra, clock);
}

}  // namespace freespace
