#include "freespace/geometry/mesh_preparation.h"

namespace freespace {

std::vector<std::string> PreparationReport::changes() const {
  std::vector<std::string> lines;
  if (repair.changedAnything()) lines = repair.describe();
  for (const std::string& line : solid.describe()) lines.push_back(line);
  return lines;
}

Mesh prepareMesh(const TriangleSoup& soup, const std::string& sourceName, const PreparationSettings& settings,
                 PreparationReport* report, std::vector<std::string>* warnings) {
  PreparationReport counts;
  std::vector<std::uint32_t> pieces;
  const TriangleSoup repaired = repairSoup(soup, sourceName, settings.repair, &counts.repair, &pieces);
  SolidSettings solidSettings = settings.solid;
  solidSettings.tolerance = counts.repair.tolerance;
  const TriangleSoup solid = interpretSolid(repaired, pieces, sourceName, solidSettings, &counts.solid, warnings);
  if (warnings) {
    for (const std::string& change : counts.changes()) warnings->push_back(sourceName + ": " + change);
  }
  if (report) *report = counts;
  return Mesh::fromSoup(solid, sourceName, warnings, VertexWelding::asIndexed, SelfIntersectionCheck::alreadyDone);
}

}  // namespace freespace
