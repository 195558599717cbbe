#include "freespace/problem/path_file.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "freespace/input_error.h"
#include "freespace/io/output_file.h"

namespace freespace {

namespace {

// The text before any '#' comment.
std::string withoutComment(const std::string& line) { return line.substr(0, line.find('#')); }

// The whitespace-separated fields of a line.
std::vector<std::string> fieldsOf(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t position = 0;
  while ((position = line.find_first_not_of(" \t\r", position)) != std::string::npos) {
    const std::size_t end = line.find_first_of(" \t\r", position);
    fields.push_back(line.substr(position, end - position));
    position = end;
  }
  return fields;
}

// The field as a finite double (from_chars reads the exact decimal value, rounded once).
bool parseFinite(const std::string& field, double& value) {
  const char* end = field.data() + field.size();
  const auto [stop, error] = std::from_chars(field.data(), end, value);
  return error == std::errc() && stop == end && std::isfinite(value);
}

std::string shortest(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

}  // namespace

std::vector<Pose2> readPath(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw InputError(path, "cannot open file: it is a directory");
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open file");
  std::vector<Pose2> poses;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::vector<std::string> fields = fieldsOf(withoutComment(line));
    if (fields.empty()) continue;
    Pose2 pose;
    if (fields.size() != 3 || !parseFinite(fields[0], pose.x) || !parseFinite(fields[1], pose.y) ||
        !parseFinite(fields[2], pose.theta)) {
      throw InputError(path, "line " + std::to_string(number) + ": expected three finite numbers X Y THETA");
    }
    poses.push_back(pose);
  }
  if (in.bad()) throw InputError(path, "read error");
  return poses;
}

void writePath(const std::vector<Pose2>& poses, const std::string& path, bool overwrite) {
  writeFile(path, overwrite, [&poses](std::ostream& out) {
    for (const Pose2& pose : poses) out << shortest(pose.x) << ' ' << shortest(pose.y) << ' ' << shortest(pose.theta) << '\n';
  });
}

}  // namespace freespace
