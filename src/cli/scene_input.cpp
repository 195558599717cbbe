#include "scene_input.h"

#include <iostream>

#include "freespace/input_error.h"
#include "freespace/io/mesh_reader.h"

namespace freespace::cli {

void SceneInput::addOptions(CLI::App& command) {
  CLI::Option* cfg = command.add_option("--cfg", cfg_, "OMPL.app planar problem (.cfg)");
  CLI::Option* meshes =
      command.add_option("meshes", meshes_, "ROBOT WORLD mesh files (instead of --cfg)")->expected(2);
  cfg->excludes(meshes);
  meshes->excludes(cfg);
}

LoadedProblem SceneInput::load() const {
  std::vector<std::string> warnings;
  LoadedProblem loaded;
  if (!cfg_.empty()) {
    loaded = loadProblem(cfg_, &warnings);
  } else if (meshes_.size() == 2) {
    loaded.robot = loadMesh(meshes_[0], &warnings);
    loaded.world = loadMesh(meshes_[1], &warnings);
    loaded.problem.robot = meshes_[0];
    loaded.problem.world = meshes_[1];
  } else {
    throw CLI::ValidationError("input", "give either --cfg FILE or ROBOT WORLD");
  }
  for (const std::string& warning : warnings) std::cerr << "warning: " << warning << "\n";
  return loaded;
}

}  // namespace freespace::cli
