#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace freespace {

/// Writes a file through `write`, into a temporary file next to it that replaces it
/// only once complete (a failure leaves no partial file). Refuses (InputError) to
/// replace an existing file unless `overwrite`; a file that cannot be written is an
/// InputError too.
void writeFile(const std::string& path, bool overwrite, const std::function<void(std::ostream&)>& write);

}  // namespace freespace
