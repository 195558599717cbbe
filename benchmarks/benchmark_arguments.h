#pragma once

// Argument errors of the benchmark commands: a bad option, a missing problem file or
// any failure while running names the problem on stderr and exits with status 1,
// before the long runs start where it can be checked then.

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "freespace/geometry/stage_clock.h"

namespace freespace::benchmarks {

using freespace::secondsSince;

/// Runs `body` (which returns the exit status), reporting any exception as
/// "program: error: what" with status 1.
template <class Body>
int reportingErrors(const char* program, const Body& body) {
  try {
    return body();
  } catch (const std::exception& error) {
    std::cerr << program << ": error: " << error.what() << "\n";
    return 1;
  }
}

/// An argument that looks like an option but is none of the accepted ones.
inline void rejectOption(const std::string& argument, const std::string& usage) {
  if (argument.rfind("-", 0) == 0) throw std::invalid_argument("unknown option " + argument + "\nusage: " + usage);
}

/// The value of a count option: a whole number, or an error naming the option.
inline unsigned wholeNumber(const std::string& option, const std::string& value) {
  const bool digits = !value.empty() && value.size() <= 9 && value.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) throw std::invalid_argument(option + " needs a whole number below 10^9, not '" + value + "'");
  return static_cast<unsigned>(std::stoul(value));
}

/// Problem files that do not exist, named before anything runs.
inline void requireFiles(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    if (!std::filesystem::is_regular_file(path)) throw std::invalid_argument(path + ": no such problem file");
  }
}

/// Every problem bundled in benchmarks/problems, by name.
inline std::vector<std::string> bundledProblems() {
  std::vector<std::string> problems;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems")) {
    if (entry.path().extension() == ".cfg") problems.push_back(entry.path().string());
  }
  std::sort(problems.begin(), problems.end());
  return problems;
}

/// The arguments of a benchmark run over problems: one whole-number option (`--samples
/// N`, `--seconds S`; else its default) and problem files (else every bundled
/// problem), checked.
struct CountedProblems {
  int count;
  std::vector<std::string> problems;
};

inline CountedProblems countedProblems(int argc, char** argv, const std::string& option, int defaultCount,
                                       const std::string& usage) {
  CountedProblems run{defaultCount, {}};
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == option && i + 1 < argc) {
      run.count = static_cast<int>(wholeNumber(argument, argv[++i]));
    } else {
      rejectOption(argument, usage);
      run.problems.push_back(argument);
    }
  }
  if (run.problems.empty()) run.problems = bundledProblems();
  requireFiles(run.problems);
  return run;
}

/// countedProblems with `--samples N`.
inline CountedProblems sampledProblems(int argc, char** argv, int defaultSamples, const std::string& usage) {
  return countedProblems(argc, argv, "--samples", defaultSamples, usage);
}

}  // namespace freespace::benchmarks
