#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace freespace {

/// Writes a text file through `write`. Refuses (InputError) to replace an existing
/// file unless `overwrite`; a file that cannot be written is an InputError too.
void writeTextFile(const std::string& path, bool overwrite, const std::function<void(std::ostream&)>& write);

}  // namespace freespace
