#include <array>
#include <iostream>
#include <memory>

#include "commands.h"
#include "free_space_input.h"
#include "freespace/exports/slice_svg.h"
#include "freespace/io/output_file.h"
#include "number_checks.h"

namespace freespace::cli {

void addSliceCommand(CLI::App& app) {
  struct Options {
    FreeSpaceInput input;
    double theta = 0;
    std::string svg;
    std::vector<double> robotAt;
    int resolution = 240;
    bool force = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "slice", "Draw the free space's slice at one angle as SVG: blocked, free cells, boundaries, the robot");
  options->input.addOptions(*command);
  command->add_option("--theta", options->theta, "the slice's angle (radians)")->required()->check(finiteNumber());
  command->add_option("--svg", options->svg, "output SVG file")->required()->check(nonEmpty());
  command->add_option("--robot-at", options->robotAt, "draw the robot's outline at X Y")
      ->expected(2)
      ->check(finiteNumber());
  command->add_option("--resolution", options->resolution, "pixels across the wider side (default 240)")
      ->check(CLI::Range(8, 4000));
  command->add_flag("--force", options->force, "overwrite an existing output file");
  command->callback([options]() {
    checkOutputPath(options->svg, options->force);  // before the construction, not after it
    LoadedProblem loaded;
    const std::unique_ptr<FreeSpace> space = options->input.build(loaded);
    SliceSvgOptions slice;
    slice.theta = options->theta;
    slice.resolution = options->resolution;
    if (options->robotAt.size() == 2) slice.robotAt = std::array<double, 2>{options->robotAt[0], options->robotAt[1]};
    writeFile(options->svg, options->force, [&](std::ostream& out) { writeSliceSvg(*space, slice, out); });
    std::cout << options->svg << ": slice at theta " << options->theta << ", " << space->cellCount()
              << " free cells\n";
  });
}

}  // namespace freespace::cli
