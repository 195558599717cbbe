#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "configuration_input.h"
#include "free_space_input.h"

namespace freespace::cli {

void addLocateCommand(CLI::App& app) {
  struct Options {
    FreeSpaceInput input;
    ConfigurationInput configurations;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command =
      app.add_subcommand("locate", "Locate configurations: free (and the free cell) or blocked, decided exactly");
  options->input.addOptions(*command);
  options->configurations.addOptions(*command);
  command->add_flag("--json", options->json, "print JSON (one object per line)");
  command->callback([options]() {
    const std::vector<Pose2> poses = options->configurations.poses();
    LoadedProblem loaded;
    const std::unique_ptr<FreeSpace> space = options->input.build(loaded);
    std::cout.precision(17);
    for (const Pose2& pose : poses) {
      const Location location = space->locate(pose);
      if (options->json) {
        nlohmann::json answer = {{"x", pose.x}, {"y", pose.y}, {"theta", pose.theta}, {"free", location.free}};
        if (location.free) answer["cell"] = location.cell;
        std::cout << answer.dump() << "\n";
      } else {
        std::cout << pose.x << " " << pose.y << " " << pose.theta << ": "
                  << (location.free ? "free, cell " + std::to_string(location.cell) : std::string("blocked")) << "\n";
      }
    }
  });
}

}  // namespace freespace::cli
