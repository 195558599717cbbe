#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

// The fuzzer's input as a file (the readers take paths): one per process, rewritten
// for each input, in the folder FREESPACE_FUZZ_FILES names (scripts/fuzz.sh makes one
// in memory, /dev/shm, and removes it with whatever a crashed target left), else
// /tmp. On disk, a file truncated and rewritten thousands of times a second is
// flushed on each close (ext4), and the fuzzer spent most of its time waiting.
inline std::string fuzzInputFile(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  // Removed when the process ends normally.
  struct RemovedAtExit {
    std::string path;
    ~RemovedAtExit() { ::unlink(path.c_str()); }
  };
  static const char* const folder = std::getenv("FREESPACE_FUZZ_FILES");
  static const RemovedAtExit file{std::string(folder ? folder : "/tmp") + "/freespace-fuzz-" +
                                  std::to_string(::getpid()) + extension};
  const std::string& path = file.path;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                static_cast<std::streamsize>(size));
  return path;
}
