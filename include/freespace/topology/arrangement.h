#pragma once

#include <functional>
#include <string>
#include <vector>

#include "freespace/geometry/patch_curve.h"
#include "freespace/geometry/patch_geometry.h"
#include "freespace/geometry/patch_subdivision.h"
#include "freespace/geometry/patch_vertex.h"
#include "freespace/topology/shells.h"
#include "freespace/topology/sub_face_gluing.h"

namespace freespace {

/// The arrangement of the patches (DESIGN.md section 6, steps 3 to 5): their curves,
/// overlaps and vertices, each patch subdivided into sub-faces, the sub-faces glued
/// across curves, spirals and horizontal edges, and the shells they form.
struct Arrangement {
  std::vector<PatchGeometry> patches;
  std::vector<PatchCurve> curves;
  std::vector<PatchOverlap> overlaps;
  std::vector<PatchVertex> vertices;
  std::vector<PatchSubdivision> subdivisions;
  SubFaceGluing acrossCurves;
  SubFaceGluing aroundSpirals;
  SubFaceGluing acrossHorizontalEdges;
  Shells shells;
};

/// Builds it stage by stage, announcing each to `progress` (when set).
Arrangement buildArrangement(std::vector<PatchGeometry> patches, AngleAlgebra& algebra,
                             const Cancellation& cancellation = {},
                             const std::function<void(const std::string& stage)>& progress = {});

}  // namespace freespace
