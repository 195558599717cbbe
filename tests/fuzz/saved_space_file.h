#pragma once

// A saved free space's file around a payload: the header line, the payload's length
// and a valid CRC-32 (the layout src/space/free_space_file.cpp writes, format 7), for
// the saved-space fuzz target and the test that replays its findings.

#include <boost/crc.hpp>

#include <cstdint>
#include <string>

inline std::string savedSpaceFileAround(const std::string& payload) {
  boost::crc_32_type crc;
  crc.process_bytes(payload.data(), payload.size());
  std::string file = "freespace saved free space, format 7\n";
  for (int i = 0; i < 8; ++i) file.push_back(static_cast<char>((std::uint64_t(payload.size()) >> (8 * i)) & 0xff));
  for (int i = 0; i < 4; ++i) file.push_back(static_cast<char>((crc.checksum() >> (8 * i)) & 0xff));
  return file + payload;
}
