#pragma once

// A bundled problem (benchmarks/problems) by its name, without the .cfg.

#include <string>

#include "freespace/problem/planar_problem.h"

namespace freespace::testing {

inline LoadedProblem loadBundledProblem(const std::string& name) {
  return loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/" + name + ".cfg");
}

}  // namespace freespace::testing
