// A saved free space. The input is the payload: the target gives it the file's header
// line, its length and a valid CRC-32, so that the fuzzer reaches the archive's
// decoding and the structure's checks (a payload altered at random otherwise fails
// the checksum first). Loaded, or refused with an InputError.
#include <boost/crc.hpp>

#include "freespace/input_error.h"
#include "freespace/space/free_space.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string payload(reinterpret_cast<const char*>(data), size);
  boost::crc_32_type crc;
  crc.process_bytes(payload.data(), payload.size());
  std::string file = "freespace saved free space, format 2\n";
  for (int i = 0; i < 8; ++i) file.push_back(static_cast<char>((std::uint64_t(size) >> (8 * i)) & 0xff));
  for (int i = 0; i < 4; ++i) file.push_back(static_cast<char>((crc.checksum() >> (8 * i)) & 0xff));
  file += payload;
  try {
    freespace::FreeSpace::load(
        fuzzInputFile(reinterpret_cast<const std::uint8_t*>(file.data()), file.size(), ".fspace"));
  } catch (const freespace::InputError&) {
  }
  return 0;
}
