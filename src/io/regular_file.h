#pragma once

#include <sys/stat.h>

#include <string>

namespace freespace {

/// The InputError for a file that could not be opened or examined, from errno's value.
[[noreturn]] void throwCannotOpen(const std::string& path, int error);

/// Throws the InputError naming `path` unless `info` (its stat) is a regular file: a
/// folder, a FIFO or a device (which could block until someone writes to it, or never
/// end) is refused.
void requireRegularFile(const std::string& path, const struct stat& info);

}  // namespace freespace
