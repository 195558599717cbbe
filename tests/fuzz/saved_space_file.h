#pragma once

// A saved free space's file around a payload: the header line, then the payload, its
// length and a valid checksum (XXH3, 64 bits; the layout src/space/free_space_file.cpp
// writes, format 9), for the saved-space fuzz target and the tests that alter payloads.

#include <xxhash.h>

#include <cstdint>
#include <string>

inline std::string savedSpaceFileAround(const std::string& payload) {
  const std::uint64_t sum = XXH3_64bits(payload.data(), payload.size());
  std::string file = "freespace saved free space, format 9\n" + payload;
  for (int i = 0; i < 8; ++i) file.push_back(static_cast<char>((std::uint64_t(payload.size()) >> (8 * i)) & 0xff));
  for (int i = 0; i < 8; ++i) file.push_back(static_cast<char>((sum >> (8 * i)) & 0xff));
  return file;
}
