// Reading and preparing a mesh; the reading alone (mesh_reader.cpp) depends on no
// geometry, so the readers can be built and fuzzed on their own.
#include "freespace/io/mesh_reader.h"

#include "freespace/geometry/mesh_preparation.h"

namespace freespace {

Mesh loadMesh(const std::string& path, std::vector<std::string>* warnings, const PreparationSettings& settings,
              PreparationReport* report) {
  return prepareMesh(readTriangleSoup(path), path, settings, report, warnings);
}

}  // namespace freespace
