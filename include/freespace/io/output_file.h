#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace freespace {

/// Writes a file through `write`. A regular file (or a new one) is written into a
/// temporary file of a unique name in the same folder, every write checked, that
/// takes the path only once complete: a failure, or a signal the caller handles with
/// removePendingOutputs, leaves nothing behind and the file the user had untouched.
/// An existing file is replaced only if `overwrite`; otherwise "already exists" is
/// decided atomically with the rename (two writers never both succeed). A device or
/// pipe (/dev/stdout, a FIFO) is written in place. Every failure is an InputError
/// naming the path and the reason (a folder, no space left, no permission, ...).
void writeFile(const std::string& path, bool overwrite, const std::function<void(std::ostream&)>& write);

/// The checks writeFile makes before it writes, for a caller to fail before long
/// work: throws the InputError writeFile would for a folder, or for an existing
/// regular file when not `overwrite`. Returns whether the path is (or will be) a
/// regular file, false for a device or a pipe.
bool checkOutputPath(const std::string& path, bool overwrite);

/// Removes the temporary files of writes in progress; async-signal-safe, for a
/// program's handlers of the signals that end it (SIGINT, SIGTERM, ...).
void removePendingOutputs() noexcept;

}  // namespace freespace
