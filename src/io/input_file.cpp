#include "freespace/io/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <system_error>

#include "freespace/input_error.h"
#include "regular_file.h"

namespace freespace {

void throwCannotOpen(const std::string& path, int error) {
  throw InputError(path, "cannot open file: " + std::generic_category().message(error));
}

void requireRegularFile(const std::string& path, const struct stat& info) {
  if (S_ISDIR(info.st_mode)) throw InputError(path, "cannot open file: it is a directory");
  if (!S_ISREG(info.st_mode)) throw InputError(path, "cannot open file: not a regular file (a pipe or a device)");
}

std::ifstream openInputFile(const std::string& path, std::ios::openmode mode) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throwCannotOpen(path, errno);
  requireRegularFile(path, info);
  std::ifstream file(path, mode);
  if (!file) throwCannotOpen(path, errno);
  return file;
}

}  // namespace freespace
