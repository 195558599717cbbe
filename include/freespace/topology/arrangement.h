#pragma once

#include <memory>
#include <vector>

#include "freespace/geometry/patch_box_index.h"
#include "freespace/geometry/patch_curve.h"
#include "freespace/geometry/patch_geometry.h"
#include "freespace/geometry/patch_subdivision.h"
#include "freespace/geometry/patch_vertex.h"
#include "freespace/geometry/stage_clock.h"
#include "freespace/topology/shells.h"
#include "freespace/topology/sub_face_gluing.h"

namespace freespace {

/// The arrangement of the patches (docs/design.md section 6, steps 3 to 5): their curves,
/// overlaps and vertices, each patch subdivided into sub-faces, the sub-faces glued
/// across curves, spirals and horizontal edges, and the shells they form.
struct Arrangement {
  std::vector<PatchGeometry> patches;
  /// The patches' boxes on grids: built once, for the candidate pairs of curves
  /// and overlaps and for the rays cast at fixed angles (SliceRays).
  std::shared_ptr<const PatchBoxIndex> boxIndex;
  std::vector<PatchCurve> curves;
  std::vector<PatchOverlap> overlaps;
  std::vector<PatchVertex> vertices;
  std::vector<PatchSubdivision> subdivisions;
  SubFaceGluing acrossCurves;
  SubFaceGluing aroundSpirals;
  SubFaceGluing acrossHorizontalEdges;
  Shells shells;
};

/// Builds it stage by stage (curves, overlaps, vertices, subdivision, the three
/// gluings, shells), each run and timed by `clock`.
Arrangement buildArrangement(std::vector<PatchGeometry> patches, AngleAlgebra& algebra, StageClock& clock);

/// The same without progress, cancellation or stage times.
Arrangement buildArrangement(std::vector<PatchGeometry> patches, AngleAlgebra& algebra);

}  // namespace freespace
