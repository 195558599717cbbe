#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "configuration_query.h"

namespace freespace::cli {

void addLocateCommand(CLI::App& app) {
  addConfigurationQuery(
      app, "locate", "Locate configurations: free (and the free cell) or blocked, decided exactly",
      [](const FreeSpace& space, const Pose2& pose, bool json) {
        const Location location = space.locate(pose);
        if (json) {
          nlohmann::json answer = {{"x", pose.x}, {"y", pose.y}, {"theta", pose.theta}, {"free", location.free}};
          if (location.free) answer["cell"] = location.cell;
          std::cout << answer.dump() << "\n";
        } else {
          std::cout << pose.x << " " << pose.y << " " << pose.theta << ": "
                    << (location.free ? "free, cell " + std::to_string(location.cell) : std::string("blocked")) << "\n";
        }
      });
}

}  // namespace freespace::cli
