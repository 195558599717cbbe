#include "scene_input.h"

#include <iostream>

#include "freespace/input_error.h"
#include "freespace/io/mesh_reader.h"

namespace freespace::cli {

void SceneInput::addOptions(CLI::App& command, bool savedSpace) {
  CLI::Option* cfg = command.add_option("--cfg", cfg_, "OMPL.app planar problem (.cfg)");
  CLI::Option* meshes =
      savedSpace ? command.add_option("inputs", meshes_, "SPACE_FILE (saved by build --save) or ROBOT WORLD mesh files")
                       ->expected(1, 2)
                 : command.add_option("meshes", meshes_, "ROBOT WORLD mesh files (instead of --cfg)")->expected(2);
  cfg->excludes(meshes);
  meshes->excludes(cfg);
  preparation_.addOptions(command, "--repair-tolerance");
}

std::optional<std::string> SceneInput::savedSpaceFile() const {
  if (cfg_.empty() && meshes_.size() == 1) return meshes_.front();
  return std::nullopt;
}

LoadedProblem SceneInput::load() const {
  std::vector<std::string> warnings;
  LoadedProblem loaded;
  if (!cfg_.empty()) {
    loaded = loadProblem(cfg_, &warnings, preparation_.settings());
  } else if (meshes_.size() == 2) {
    loaded = loadRobotAndWorld(meshes_[0], meshes_[1], &warnings, preparation_.settings());
  } else {
    throw CLI::ValidationError("input", "give either --cfg FILE or ROBOT WORLD");
  }
  for (const std::string& warning : warnings) std::cerr << "warning: " << warning << "\n";
  return loaded;
}

}  // namespace freespace::cli
