#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "configuration_query.h"

namespace freespace::cli {

void addLocateCommand(CLI::App& app) {
  addConfigurationQuery(
      app, "locate",
      "Locate configurations: free (with the free cell and the node of the cell graph) or blocked, decided exactly",
      [](const FreeSpace& space, const Pose2& pose, bool json) {
        const NodeLocation located = space.locateNode(pose);
        const Location& location = located.location;
        std::int64_t node = -1;  // none
        if (located.node) node = *located.node;
        if (json) {
          nlohmann::json answer = {{"x", pose.x}, {"y", pose.y}, {"theta", pose.theta}, {"free", location.free}};
          if (location.free) answer["cell"] = location.cell;
          if (node >= 0) answer["node"] = node;
          std::cout << answer.dump() << "\n";
          return;
        }
        std::cout << pose.x << " " << pose.y << " " << pose.theta << ": "
                  << (location.free ? "free, cell " + std::to_string(location.cell) : std::string("blocked"));
        if (node >= 0) std::cout << ", node " << node;
        std::cout << "\n";
      });
}

}  // namespace freespace::cli
