#pragma once

#include <CLI/CLI.hpp>

namespace freespace::cli {

/// Each command registers its subcommand, options and callback on the application.
/// Callbacks throw freespace::InputError for bad input; main() turns it into a
/// message on stderr and exit status 2.
void addCheckCommand(CLI::App& app);
void addInfoCommand(CLI::App& app);
void addGenerateCommand(CLI::App& app);
void addBuildCommand(CLI::App& app);
void addLocateCommand(CLI::App& app);
void addSliceCommand(CLI::App& app);
void addExportCommand(CLI::App& app);
void addRepairCommand(CLI::App& app);
void addClearanceCommand(CLI::App& app);
void addGraphCommand(CLI::App& app);
void addPlanCommand(CLI::App& app);

}  // namespace freespace::cli
