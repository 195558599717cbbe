#pragma once

#include <string>
#include <vector>

#include "freespace/geometry/mesh.h"
#include "freespace/geometry/solid_interpretation.h"
#include "freespace/geometry/soup_repair.h"

namespace freespace {

/// How a soup read from a file becomes a mesh.
struct PreparationSettings {
  RepairSettings repair;
  SolidSettings solid;
};

struct PreparationReport {
  RepairReport repair;
  SolidReport solid;

  /// What was changed, a line each (empty when nothing was).
  std::vector<std::string> changes() const;
};

/// The mesh a soup shows (docs/design.md section 9): repairSoup, then
/// interpretSolid, then Mesh::fromSoup (VertexWelding::asIndexed). Every change is
/// appended to `warnings` as "sourceName: change"; errors are InputError naming
/// `sourceName`.
Mesh prepareMesh(const TriangleSoup& soup, const std::string& sourceName, const PreparationSettings& settings = {},
                 PreparationReport* report = nullptr, std::vector<std::string>* warnings = nullptr);

}  // namespace freespace
