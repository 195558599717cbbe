#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

// The fuzzer's input as a file (the readers take paths): one per process, rewritten
// for each input.
inline std::string fuzzInputFile(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  const std::string path = "/tmp/freespace-fuzz-" + std::to_string(::getpid()) + extension;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                static_cast<std::streamsize>(size));
  return path;
}
