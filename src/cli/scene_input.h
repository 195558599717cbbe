#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "freespace/problem/planar_problem.h"
#include "preparation_options.h"

namespace freespace::cli {

/// The "(--cfg FILE | ROBOT WORLD)" input shared by the commands.
class SceneInput {
 public:
  /// With `savedSpace`, one file (a saved free space) may stand for ROBOT WORLD.
  void addOptions(CLI::App& command, bool savedSpace = false);

  /// The saved free space named instead of ROBOT WORLD, if one is.
  std::optional<std::string> savedSpaceFile() const;

  /// Loads the meshes (and the problem, with --cfg; the robot is then re-centred as
  /// in OMPL.app), repaired and interpreted as solids (--tolerance, --ignore-open).
  /// Warnings and every change made to a mesh go to stderr. Throws InputError.
  LoadedProblem load() const;

 private:
  std::string cfg_;
  std::vector<std::string> meshes_;
  PreparationOptions preparation_;
};

}  // namespace freespace::cli
