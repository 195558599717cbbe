#pragma once

#include <fstream>
#include <string>

namespace freespace {

/// Opens a user's file for reading. Only a regular file is opened: a folder, a FIFO
/// or a device (which could block until someone writes to it, or never end) and a
/// file that cannot be opened are an InputError naming the path and the reason.
std::ifstream openInputFile(const std::string& path, std::ios::openmode mode = std::ios::in);

}  // namespace freespace
