#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "freespace/collision/exact_collision_checker.h"
#include "freespace/collision/fcl_collision_checker.h"
#include "freespace/input_error.h"
#include "scene_input.h"

namespace freespace::cli {

namespace {

struct CheckOptions {
  SceneInput input;
  std::vector<double> at;
  std::string batch;
  bool json = false;
};

std::vector<Pose2> readBatch(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open file");
  std::vector<Pose2> poses;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    std::istringstream fields(line);
    Pose2 pose;
    if (!(fields >> pose.x >> pose.y >> pose.theta) || !(fields >> std::ws).eof() || !std::isfinite(pose.x) ||
        !std::isfinite(pose.y) || !std::isfinite(pose.theta)) {
      throw InputError(path, "line " + std::to_string(number) + ": expected three finite numbers X Y THETA");
    }
    poses.push_back(pose);
  }
  return poses;
}

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
  std::vector<Pose2> poses;
  if (!options.batch.empty()) {
    poses = readBatch(options.batch);
  } else {
    poses.push_back({options.at[0], options.at[1], options.at[2]});
  }
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
  CLI::Option* at = command->add_option("--at", options->at, "configuration X Y THETA (radians)")->expected(3);
  CLI::Option* batch = command->add_option("--batch", options->batch, "file with one 'X Y THETA' per line");
  at->excludes(batch);
  batch->excludes(at);
  command->add_flag("--json", options->json, "print JSON (one object per line)");
  command->callback([options, at, batch]() {
    if (at->count() == 0 && batch->count() == 0) throw CLI::ValidationError("check", "give --at X Y THETA or --batch FILE");
    runCheck(*options);
  });
}

}  // namespace freespace::cli
