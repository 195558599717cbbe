#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "freespace/space/free_space.h"

namespace freespace::cli {

/// Prints the answer about one configuration, as one JSON line or as text.
using ConfigurationAnswer = std::function<void(const FreeSpace& space, const Pose2& pose, bool json)>;

/// Registers a command that builds (or reads) a free space, then answers each
/// configuration given by --at or --batch, one line each (--json: JSON lines).
void addConfigurationQuery(CLI::App& app, const std::string& name, const std::string& description,
                           ConfigurationAnswer answer);

}  // namespace freespace::cli
