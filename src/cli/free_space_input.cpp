#include "free_space_input.h"

#include <unistd.h>

#include <array>
#include <charconv>
#include <iostream>
#include <string>

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

}  // namespace

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
