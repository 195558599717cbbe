#include "freespace/topology/arrangement.h"

namespace freespace {

Arrangement buildArrangement(std::vector<PatchGeometry> patches, AngleAlgebra& algebra,
                             const Cancellation& cancellation,
                             const std::function<void(const std::string& stage)>& progress) {
  const auto announce = [&](const char* stage) {
    cancellation.check();
    if (progress) progress(stage);
  };
  Arrangement a;
  a.patches = std::move(patches);
  announce("curves");
  a.curves = patchCurves(a.patches, algebra, cancellation);
  announce("overlaps");
  a.overlaps = patchOverlaps(a.patches, algebra);
  announce("vertices");
  a.vertices = patchVertices(a.patches, a.curves, a.overlaps, algebra, cancellation);
  announce("subdivision");
  a.subdivisions = patchSubdivisions(a.patches, a.curves, a.vertices, a.overlaps, algebra, cancellation);
  announce("gluing");
  a.acrossCurves = glueAcrossCurves(a.patches, a.curves, a.subdivisions, algebra, cancellation);
  a.aroundSpirals = glueAroundSpirals(a.patches, a.subdivisions, algebra, cancellation);
  a.acrossHorizontalEdges =
      glueAcrossHorizontalEdges(a.patches, a.curves, a.overlaps, a.subdivisions, algebra, cancellation);
  a.shells = Shells(a.subdivisions, {&a.acrossCurves, &a.aroundSpirals, &a.acrossHorizontalEdges});
  return a;
}

}  // namespace freespace
