#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "configuration_input.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "scene_input.h"

namespace freespace::cli {

namespace {

struct CheckOptions {
  SceneInput input;
  ConfigurationInput configurations;
  bool json = false;
};

void printAnswer(const Pose2& pose, bool exactCollision, bool fclCollision, double fclDistance, bool json) {
  if (json) {
    const nlohmann::json answer = {{"x", pose.x},
                                   {"y", pose.y},
                                   {"theta", pose.theta},
                                   {"exact_free", !exactCollision},
                                   {"fcl_free", !fclCollision},
                                   {"fcl_distance", fclDistance}};
    std::cout << answer.dump() << "\n";
    return;
  }
  std::cout << pose.x << " " << pose.y << " " << pose.theta << ": exact " << (exactCollision ? "collision" : "free")
            << ", fcl " << (fclCollision ? "collision" : "free") << ", fcl distance " << fclDistance << "\n";
}

void runCheck(const CheckOptions& options) {
  const std::vector<Pose2> poses = options.configurations.poses();
  const LoadedProblem loaded = options.input.load();
  const ExactCollisionChecker exact(loaded.robot, loaded.world);
  const FclCollisionChecker fcl(loaded.robot, loaded.world);
  std::cout.precision(17);
  for (const Pose2& pose : poses) {
    printAnswer(pose, exact.inCollision(pose), fcl.inCollision(pose), fcl.distance(pose), options.json);
  }
}

}  // namespace

void addCheckCommand(CLI::App& app) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* command = app.add_subcommand(
      "check", "Is the robot at a configuration free? Answers by the exact test and by FCL, with FCL's distance");
  options->input.addOptions(*command);
  options->configurations.addOptions(*command);
  command->add_flag("--json", options->json, "print JSON (one object per line)");
  command->callback([options]() { runCheck(*options); });
}

}  // namespace freespace::cli
