#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

// The fuzzer's input as a file (the readers take paths): one per process, rewritten
// for each input, in memory (/dev/shm) where there is such a folder: a file on disk
// truncated and rewritten thousands of times a second is flushed on each close
// (ext4), and the fuzzer spent most of its time waiting for the disk.
inline std::string fuzzInputFile(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  // Removed when the process ends.
  struct RemovedAtExit {
    std::string path;
    ~RemovedAtExit() { ::unlink(path.c_str()); }
  };
  static const std::string folder = ::access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  static const RemovedAtExit file{folder + "/freespace-fuzz-" + std::to_string(::getpid()) + extension};
  const std::string& path = file.path;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                static_cast<std::streamsize>(size));
  return path;
}
