#pragma once

#include <stdexcept>
#include <string>

namespace freespace {

/// Bad input from a user's file: the message always starts with the file name,
/// then names the defect ("maze.obj: edge (12, 40) is shared by 3 triangles").
/// Command line tools report it and exit with status 2.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& problem)
      : std::runtime_error(file + ": " + problem), file_(file), problem_(problem) {}

  const std::string& file() const { return file_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  std::string problem_;
};

}  // namespace freespace
