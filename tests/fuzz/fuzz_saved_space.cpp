// A saved free space. The input is the payload: the target gives it the file's header
// line, its length and a valid CRC-32, so that the fuzzer reaches the archive's
// decoding and the structure's checks (a payload altered at random otherwise fails
// the checksum first). Loaded with every check (the functions' exact coefficients
// decoded too), or refused with an InputError.
#include "freespace/input_error.h"
#include "freespace/space/free_space.h"
#include "fuzz_input_file.h"
#include "saved_space_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = savedSpaceFileAround(std::string(reinterpret_cast<const char*>(data), size));
  try {
    freespace::FreeSpace::load(
        fuzzInputFile(reinterpret_cast<const std::uint8_t*>(file.data()), file.size(), ".fspace"),
        freespace::FreeSpace::LoadCheck::Everything);
  } catch (const freespace::InputError&) {
  }
  return 0;
}
