#include "freespace/io/output_file.h"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "freespace/input_error.h"

namespace freespace {

void writeFile(const std::string& path, bool overwrite, const std::function<void(std::ostream&)>& write) {
  std::error_code error;
  if (!overwrite && std::filesystem::exists(path, error)) throw InputError(path, "already exists (not overwritten)");
  const std::string partial = path + ".partial";
  try {
    std::ofstream out(partial, std::ios::binary);
    if (!out) throw InputError(path, "cannot write: " + std::generic_category().message(errno));
    write(out);
    out.close();
    if (!out) throw InputError(path, "cannot write: output error");
    std::filesystem::rename(partial, path, error);
    if (error) throw InputError(path, "cannot write: " + error.message());
  } catch (...) {
    std::filesystem::remove(partial, error);
    throw;
  }
}

}  // namespace freespace
