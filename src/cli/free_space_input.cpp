#include "free_space_input.h"

#include <unistd.h>

#include <array>
#include <charconv>
#include <iostream>
#include <string>

#include "freespace/input_error.h"
#include "number_checks.h"
#include "stop_signals.h"

namespace freespace::cli {

namespace {

// The shortest text that reads back as the same double.
std::string shortest(double value) {
  std::array<char, 32> text{};
  const auto end = std::to_chars(text.data(), text.data() + text.size(), value).ptr;
  return std::string(text.data(), end);
}

/// An InputError naming `file` unless `saved` was built from `loaded`: the same
/// vertices and triangles, each vertex moved by no more than the perturbation.
void checkBuiltFrom(const PerturbedMeshes& saved, const Mesh& loaded, const std::string& which,
                    const std::string& file) {
  const Mesh& built = which == "robot" ? saved.robot : saved.world;
  if (built.vertices().size() != loaded.vertices().size() || built.triangles().size() != loaded.triangles().size()) {
    throw InputError(file, "was built from another " + which + " (" + std::to_string(built.triangles().size()) +
                               " triangles, " + std::to_string(built.vertices().size()) + " vertices; the " + which +
                               " given has " + std::to_string(loaded.triangles().size()) + " and " +
                               std::to_string(loaded.vertices().size()) + ")");
  }
  const double moved = 2 * saved.record.absoluteSize / saved.scale;
  for (std::size_t vertex = 0; vertex < built.vertices().size(); ++vertex) {
    const Point3 original = loaded.vertices()[vertex], position = built.vertices()[vertex] / saved.scale;
    if ((position - original).norm() > moved + 1e-12 * (1 + original.norm())) {
      throw InputError(file, "was built from another " + which + ": its vertex " + std::to_string(vertex) +
                                 " lies elsewhere than the " + which + "'s given");
    }
  }
}

}  // namespace

void FreeSpaceInput::addSpaceFileOption(CLI::App& command) {
  command.add_option("--space", spaceFile_,
                     "free space saved by build --save from the same meshes: read instead of built");
}

void FreeSpaceInput::addOptions(CLI::App& command) {
  scene_.addOptions(command, true);
  command.add_option("--seed", seed_, "seed of the input perturbation (default 1)")->check(wholeNumber());
  command.add_option("--perturbation", perturbation_,
                     "size of the input perturbation relative to the scene (default 1e-8; 0 switches it off)")
      ->check(finiteNonNegative());
  command.add_option("--memory-limit", memoryLimitGigabytes_,
                     "memory the construction may use, in GB (default: the machine's); a scene that needs more by "
                     "an estimate made before building is refused at once")
      ->check(finiteNonNegative());
}

std::unique_ptr<FreeSpace> FreeSpaceInput::build(LoadedProblem& loaded) const {
  if (const std::optional<std::string> saved = scene_.savedSpaceFile()) return FreeSpace::load(*saved);
  loaded = scene_.load();
  if (!spaceFile_.empty()) {
    std::unique_ptr<FreeSpace> space = FreeSpace::load(spaceFile_);
    checkBuiltFrom(space->meshes(), loaded.robot, "robot", spaceFile_);
    checkBuiltFrom(space->meshes(), loaded.world, "world", spaceFile_);
    return space;
  }
  FreeSpaceOptions options;
  options.perturbation.seed = seed_;
  options.perturbation.relativeSize = perturbation_;
  options.perturbation.enabled = perturbation_ > 0;
  options.memoryLimitBytes = memoryLimitGigabytes_ * 1e9;
  options.sourceName = loaded.cfgPath.empty() ? loaded.problem.robot + " and " + loaded.problem.world : loaded.cfgPath;
  if (isatty(STDERR_FILENO)) {
    options.progress = [](const std::string& stage) { std::cerr << "building: " << stage << "...\n"; };
  }
  std::unique_ptr<FreeSpace> space;
  {
    // Ctrl-C (or SIGTERM) stops the construction; main() reports it.
    const StoppableSection section;
    options.cancellation = section.cancellation();
    space = std::make_unique<FreeSpace>(loaded.robot, loaded.world, options);
  }
  const PerturbationRecord& used = space->meshes().record;
  if (used.enabled && used.relativeSize < options.perturbation.relativeSize) {
    std::cerr << "warning: " << options.sourceName << ": perturbation reduced to " << shortest(used.relativeSize)
              << " of the scene size: with " << shortest(options.perturbation.relativeSize)
              << " features of the meshes closer than it crossed (--perturbation " << shortest(used.relativeSize)
              << " reproduces the run)\n";
  }
  return space;
}

}  // namespace freespace::cli
