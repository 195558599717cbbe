#include <iostream>

#include "commands.h"
#include "freespace/geometry/cancellation.h"
#include "freespace/input_error.h"

int main(int argc, char** argv) {
  CLI::App app{"freespace: exact free space of a polyhedron moving on a floor"};
  app.require_subcommand(1);
  freespace::cli::addCheckCommand(app);
  freespace::cli::addInfoCommand(app);
  freespace::cli::addGenerateCommand(app);
  freespace::cli::addBuildCommand(app);
  freespace::cli::addLocateCommand(app);
  freespace::cli::addSliceCommand(app);
  freespace::cli::addExportCommand(app);
  freespace::cli::addRepairCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const freespace::Cancelled&) {
    std::cerr << "cancelled\n";
    return 130;
  } catch (const freespace::InputError& error) {
    std::cerr << "error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
