#include "configuration_input.h"

#include <algorithm>
#include <cmath>

#include "freespace/problem/path_file.h"

namespace freespace::cli {

void ConfigurationInput::addOptions(CLI::App& command) {
  CLI::Option* at = command.add_option("--at", at_, "configuration X Y THETA (radians)")->expected(3);
  CLI::Option* batch = command.add_option("--batch", batch_, "file with one 'X Y THETA' per line (an OMPL.app .path file)");
  at->excludes(batch);
  batch->excludes(at);
}

std::vector<Pose2> ConfigurationInput::poses() const {
  if (!batch_.empty()) return readPath(batch_);
  if (at_.size() != 3) throw CLI::ValidationError("configurations", "give --at X Y THETA or --batch FILE");
  if (!std::all_of(at_.begin(), at_.end(), [](double value) { return std::isfinite(value); })) {
    throw CLI::ValidationError("--at", "expected three finite numbers X Y THETA");
  }
  return {{at_[0], at_[1], at_[2]}};
}

}  // namespace freespace::cli
