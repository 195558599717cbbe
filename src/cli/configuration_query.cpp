#include "configuration_query.h"

#include <iostream>
#include <memory>

#include "configuration_input.h"
#include "free_space_input.h"

namespace freespace::cli {

void addConfigurationQuery(CLI::App& app, const std::string& name, const std::string& description,
                           ConfigurationAnswer answer) {
  struct Options {
    FreeSpaceInput input;
    ConfigurationInput configurations;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(name, description);
  options->input.addOptions(*command);
  options->configurations.addOptions(*command);
  command->add_flag("--json", options->json, "print JSON (one object per line)");
  command->callback([options, answer]() {
    const std::vector<Pose2> poses = options->configurations.poses();
    LoadedProblem loaded;
    const std::unique_ptr<FreeSpace> space = options->input.build(loaded);
    std::cout.precision(17);
    for (const Pose2& pose : poses) answer(*space, pose, options->json);
  });
}

}  // namespace freespace::cli
