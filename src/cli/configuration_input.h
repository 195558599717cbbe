#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "freespace/problem/planar_problem.h"

namespace freespace::cli {

/// The "--at X Y THETA | --batch FILE" input shared by the commands that answer
/// for configurations.
class ConfigurationInput {
 public:
  void addOptions(CLI::App& command);
  /// Throws CLI::ValidationError when neither is given, InputError for a bad file.
  std::vector<Pose2> poses() const;

 private:
  std::vector<double> at_;
  std::string batch_;
};

}  // namespace freespace::cli
