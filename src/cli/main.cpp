#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>

#include "commands.h"
#include "freespace/geometry/cancellation.h"
#include "freespace/input_error.h"
#include "stop_signals.h"

namespace {

// Output on stdout that could not be written (a full disk, a closed pipe) is an error,
// not a success.
int checkedStandardOutput(int status) {
  std::cout.flush();
  if (std::fflush(stdout) == 0 && std::cout.good()) return status;
  std::cerr << "error: standard output: cannot write: " << std::strerror(errno) << "\n";
  return status == 0 ? 2 : status;
}

int run(int argc, char** argv) {
  CLI::App app{"freespace: exact free space of a polyhedron moving on a floor"};
  app.require_subcommand(1);
  freespace::cli::addCheckCommand(app);
  freespace::cli::addInfoCommand(app);
  freespace::cli::addGenerateCommand(app);
  freespace::cli::addBuildCommand(app);
  freespace::cli::addLocateCommand(app);
  freespace::cli::addClearanceCommand(app);
  freespace::cli::addGraphCommand(app);
  freespace::cli::addPlanCommand(app);
  freespace::cli::addSliceCommand(app);
  freespace::cli::addExportCommand(app);
  freespace::cli::addRepairCommand(app);
  if (argc > 1 && argv[1][0] != '-') {
    try {
      app.get_subcommand(argv[1]);
    } catch (const CLI::OptionNotFound&) {
      std::cerr << "error: unknown command '" << argv[1] << "'; run with --help for the commands\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // Help and version succeed; any bad option or value is bad input (the parser's
    // own codes would say which kind).
    return app.exit(error) == 0 ? 0 : 2;
  } catch (const freespace::Cancelled&) {
    std::cerr << "cancelled\n";
    const int signal = freespace::cli::stopSignal();
    return 128 + (signal != 0 ? signal : SIGINT);
  } catch (const freespace::InputError& error) {
    std::cerr << "error: " << error.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory: this input needs more memory than the machine gives the program\n";
    return 1;
  } catch (const std::exception& error) {
    // Not the user's doing: a defect of the program, said as one.
    std::cerr << "error: internal error (please report it with the input): " << error.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  freespace::cli::installStopHandlers();
  return checkedStandardOutput(run(argc, argv));
}
