#include "freespace/geometry/mesh_preparation.h"

#include <limits>

#include "freespace/input_error.h"
#include "soup_checks.h"

namespace freespace {

namespace {

// Whether each vertex is used by the triangles of one component only: components
// that touch at a vertex get vertices of their own from interpretSolid.
bool componentsShareNoVertex(const Mesh& mesh) {
  constexpr std::uint32_t kUnseen = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> componentOf(mesh.vertices().size(), kUnseen);
  for (std::size_t t = 0; t < mesh.triangles().size(); ++t) {
    const std::uint32_t component = mesh.triangleComponents()[t];
    for (std::uint32_t v : mesh.triangles()[t]) {
      if (componentOf[v] != kUnseen && componentOf[v] != component) return false;
      componentOf[v] = component;
    }
  }
  return true;
}

// The mesh of a soup that is already what repair and interpretation make of it
// (closed, edge-manifold, consistently and outward oriented components that meet
// themselves nowhere and share no vertex, nothing to weld or snap within the
// tolerance): the checks every mesh gets, and two sorts more. Otherwise nothing.
std::optional<Mesh> alreadyPrepared(const TriangleSoup& soup, const std::string& sourceName, double tolerance) {
  if (!weldsAndSnapsNothing(soup, tolerance)) return std::nullopt;
  std::vector<std::string> changes;
  try {
    Mesh mesh = Mesh::fromSoup(soup, sourceName, &changes);
    if (changes.empty() && componentsShareNoVertex(mesh)) return mesh;
  } catch (const InputError&) {
    // Not a closed surface as it stands: repaired and interpreted.
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> PreparationReport::changes() const {
  std::vector<std::string> lines;
  if (repair.changedAnything()) lines = repair.describe();
  for (const std::string& line : solid.describe()) lines.push_back(line);
  return lines;
}

Mesh prepareMesh(const TriangleSoup& soup, const std::string& sourceName, const PreparationSettings& settings,
                 PreparationReport* report, std::vector<std::string>* warnings) {
  detail::requireFiniteCoordinates(soup, sourceName);
  detail::requireTriangles(soup, sourceName);
  detail::requireIndicesInRange(soup, sourceName);
  PreparationReport counts;
  counts.repair = unrepairedReport(soup, settings.repair);
  if (std::optional<Mesh> mesh = alreadyPrepared(soup, sourceName, counts.repair.tolerance)) {
    counts.repair.outputVertices = mesh->vertices().size();
    counts.solid.closedComponents = mesh->componentCount();
    if (report) *report = counts;
    return std::move(*mesh);
  }
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
