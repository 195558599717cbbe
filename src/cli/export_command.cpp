#include <iostream>
#include <memory>

#include "commands.h"
#include "free_space_input.h"
#include "freespace/exports/boundary_ply.h"
#include "freespace/io/output_file.h"
#include "number_checks.h"

namespace freespace::cli {

void addExportCommand(CLI::App& app) {
  struct Options {
    FreeSpaceInput input;
    std::string ply;
    double tolerance = 0;
    bool force = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "export", "Export the free cells' boundaries as a PLY mesh in (x, y, reach * theta), coloured by cell");
  options->input.addOptions(*command);
  command->add_option("--ply", options->ply, "output PLY file")->required()->check(nonEmpty());
  command->add_option("--tolerance", options->tolerance,
                      "sampling tolerance in x, y units (default 1% of the environment's size)")
      ->check(finiteNonNegative());
  command->add_flag("--force", options->force, "overwrite an existing output file");
  command->callback([options]() {
    checkOutputPath(options->ply, options->force);  // before the construction, not after it
    LoadedProblem loaded;
    const std::unique_ptr<FreeSpace> space = options->input.build(loaded);
    BoundaryPlyOptions ply;
    ply.tolerance = options->tolerance;
    writeFile(options->ply, options->force, [&](std::ostream& out) { writeBoundaryPly(*space, ply, out); });
    std::cout << options->ply << ": boundaries of " << space->cellCount() << " free cells\n";
  });
}

}  // namespace freespace::cli
