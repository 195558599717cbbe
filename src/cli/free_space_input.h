#pragma once

#include <memory>

#include <CLI/CLI.hpp>

#include "freespace/space/free_space.h"
#include "scene_input.h"

namespace freespace::cli {

/// The scene input (or a free space saved by build --save) plus the construction's
/// options (--seed, --perturbation), shared by the commands that need a free space.
/// Stages are announced on stderr when it is a terminal; a stop signal ends the
/// construction (Cancelled, see stop_signals.h).
class FreeSpaceInput {
 public:
  void addOptions(CLI::App& command);
  /// Adds "--space FILE": the meshes (and problem) are loaded as without it, the free
  /// space is read from FILE, which must have been built from those meshes.
  void addSpaceFileOption(CLI::App& command);
  std::unique_ptr<FreeSpace> build(LoadedProblem& loaded) const;
  std::optional<std::string> savedSpaceFile() const { return scene_.savedSpaceFile(); }

 private:
  SceneInput scene_;
  std::string spaceFile_;
  std::uint64_t seed_ = PerturbationSettings{}.seed;
  double perturbation_ = PerturbationSettings{}.relativeSize;
  double memoryLimitGigabytes_ = 0;  // 0: the machine's memory
};

}  // namespace freespace::cli
