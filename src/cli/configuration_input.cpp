#include "configuration_input.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "freespace/input_error.h"

namespace freespace::cli {

namespace {

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

}  // namespace

void ConfigurationInput::addOptions(CLI::App& command) {
  CLI::Option* at = command.add_option("--at", at_, "configuration X Y THETA (radians)")->expected(3);
  CLI::Option* batch = command.add_option("--batch", batch_, "file with one 'X Y THETA' per line");
  at->excludes(batch);
  batch->excludes(at);
}

std::vector<Pose2> ConfigurationInput::poses() const {
  if (!batch_.empty()) return readBatch(batch_);
  if (at_.size() != 3) throw CLI::ValidationError("configurations", "give --at X Y THETA or --batch FILE");
  if (!std::all_of(at_.begin(), at_.end(), [](double value) { return std::isfinite(value); })) {
    throw CLI::ValidationError("--at", "expected three finite numbers X Y THETA");
  }
  return {{at_[0], at_[1], at_[2]}};
}

}  // namespace freespace::cli
