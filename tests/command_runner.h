#pragma once

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include "temp_dir.h"

namespace freespace::testing {

struct CommandResult {
  int status = -1;
  std::string out;
  std::string err;
};

inline std::string readWholeFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The text in single quotes, as one shell word (for paths without quotes).
inline std::string quoted(const std::string& text) { return "'" + text + "'"; }

/// Runs the freespace command line tool with `arguments` (already shell quoted);
/// with `timeLimit` seconds, a run that takes longer is killed (status 124).
inline CommandResult runFreespace(const std::string& arguments, int timeLimit = 0) {
  TempDir dir;
  const std::string limit = timeLimit > 0 ? "timeout " + std::to_string(timeLimit) + " " : "";
  const std::string command = limit + "'" + FREESPACE_CLI + "' " + arguments + " >'" + dir.file("out") + "' 2>'" +
                              dir.file("err") + "' </dev/null";
  const int raw = std::system(command.c_str());
  CommandResult result;
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  result.out = readWholeFile(dir.file("out"));
  result.err = readWholeFile(dir.file("err"));
  return result;
}

}  // namespace freespace::testing
