#include "freespace/topology/arrangement.h"

namespace freespace {

Arrangement buildArrangement(std::vector<PatchGeometry> patches, AngleAlgebra& algebra) {
  Arrangement arrangement;
  arrangement.patches = std::move(patches);
  const std::vector<PatchGeometry>& geometries = arrangement.patches;
  arrangement.curves = patchCurves(geometries, algebra);
  arrangement.overlaps = patchOverlaps(geometries, algebra);
  arrangement.vertices = patchVertices(geometries, arrangement.curves, arrangement.overlaps, algebra);
  arrangement.subdivisions =
      patchSubdivisions(geometries, arrangement.curves, arrangement.vertices, arrangement.overlaps, algebra);
  arrangement.acrossCurves = glueAcrossCurves(geometries, arrangement.curves, arrangement.subdivisions, algebra);
  arrangement.aroundSpirals = glueAroundSpirals(geometries, arrangement.subdivisions, algebra);
  arrangement.acrossHorizontalEdges = glueAcrossHorizontalEdges(geometries, arrangement.curves, arrangement.overlaps,
                                                                arrangement.subdivisions, algebra);
  arrangement.shells = Shells(arrangement.subdivisions, {&arrangement.acrossCurves, &arrangement.aroundSpirals,
                                                         &arrangement.acrossHorizontalEdges});
  return arrangement;
}

}  // namespace freespace
