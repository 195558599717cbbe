#include "preparation_options.h"

#include "number_checks.h"

namespace freespace::cli {

void PreparationOptions::addOptions(CLI::App& command, const std::string& toleranceNames) {
  command
      .add_option(toleranceNames, tolerance_,
                  "Weld points closer than this and insert vertices into edges they lie on within it (model "
                  "units; 0: only identical points; default: 1e-6 of each mesh's bounding box diagonal)")
      ->check(finiteNonNegative());
  command.add_flag("--ignore-open", ignoreOpen_,
                   "Drop triangles that enclose nothing (open sheets, zero-thickness walls, cracks) with a warning "
                   "instead of refusing the mesh");
}

PreparationSettings PreparationOptions::settings() const {
  PreparationSettings settings;
  settings.repair.absoluteTolerance = tolerance_;
  settings.solid.ignoreOpen = ignoreOpen_;
  return settings;
}

nlohmann::json preparationJson(const PreparationReport& report) {
  const RepairReport& repair = report.repair;
  const SolidReport& solid = report.solid;
  nlohmann::json json = {
      {"tolerance", repair.tolerance},
      {"tolerance_relative_to_diagonal", repair.toleranceIsRelative ? nlohmann::json(repair.relativeTolerance)
                                                                     : nlohmann::json(nullptr)},
      {"points_welded", repair.pointsWelded},
      {"largest_weld_distance", repair.largestWeldDistance},
      {"coordinates_snapped", repair.coordinatesSnapped},
      {"vertices_snapped", repair.verticesSnapped},
      {"triangles_split", repair.trianglesSplit},
      {"zero_area_dropped", repair.zeroAreaDropped},
      {"duplicates_dropped", repair.duplicatesDropped},
      {"reversed_duplicates_dropped", repair.reversedDuplicatesDropped},
      {"closed_components_kept", solid.closedComponents},
      {"soup_triangles", solid.soupTriangles},
      {"soup_pieces", solid.soupPieces},
      {"crossing_pairs", solid.meetingPairs},
      {"triangles_refined", solid.refinedTriangles},
      {"enclosed_regions", solid.enclosedRegions},
      {"solids", solid.solids},
      {"boundary_triangles", solid.boundaryTriangles},
      {"cap_triangles", solid.capTriangles},
      {"edges_separated", solid.separatedEdges},
      {"internal_triangles_dropped", solid.internalTriangles},
      {"open_triangles_dropped", solid.open.sourceTriangles},
      {"out_of_reach_open_triangles_dropped", solid.outOfReach.sourceTriangles},
  };
  const auto boxJson = [](const Box3& box) {
    return nlohmann::json{{"min", {box.min().x(), box.min().y(), box.min().z()}},
                          {"max", {box.max().x(), box.max().y(), box.max().z()}}};
  };
  if (solid.open.pieces > 0) json["open_bounds"] = boxJson(solid.open.bounds);
  if (solid.outOfReach.pieces > 0) json["out_of_reach_open_bounds"] = boxJson(solid.outOfReach.bounds);
  return json;
}

}  // namespace freespace::cli
