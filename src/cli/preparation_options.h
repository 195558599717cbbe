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
  /// `toleranceNames`: CLI11's comma-separated names of the tolerance option (a
  /// finite number, at least 0).
  void addOptions(CLI::App& command, const std::string& toleranceNames);
  PreparationSettings settings() const;

 private:
  std::optional<double> tolerance_;
  bool ignoreOpen_ = false;
};

/// What a preparation changed, for --json output.
nlohmann::json preparationJson(const PreparationReport& report);

}  // namespace freespace::cli
