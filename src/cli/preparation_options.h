#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "freespace/geometry/mesh_preparation.h"

namespace freespace::cli {

/// How meshes read from files are repaired and interpreted: the repair tolerance and
/// --ignore-open.
class PreparationOptions {
 public:
  /// `toleranceNames`: CLI11's comma-separated names of the tolerance option.
  void addOptions(CLI::App& command, const std::string& toleranceNames);
  /// Throws InputError naming the option for a tolerance that is not a finite number.
  PreparationSettings settings() const;

 private:
  std::string toleranceName_;
  std::optional<double> tolerance_;
  bool ignoreOpen_ = false;
};

/// What a preparation changed, for --json output.
nlohmann::json preparationJson(const PreparationReport& report);

}  // namespace freespace::cli
