#include "freespace/io/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <system_error>

#include "freespace/input_error.h"

namespace freespace {

std::ifstream openInputFile(const std::string& path, std::ios::openmode mode) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    throw InputError(path, "cannot open file: " + std::generic_category().message(errno));
  }
  if (S_ISDIR(info.st_mode)) throw InputError(path, "cannot open file: it is a directory");
  if (!S_ISREG(info.st_mode)) throw InputError(path, "cannot open file: not a regular file (a pipe or a device)");
  std::ifstream file(path, mode);
  if (!file) throw InputError(path, "cannot open file: " + std::generic_category().message(errno));
  return file;
}

}  // namespace freespace
