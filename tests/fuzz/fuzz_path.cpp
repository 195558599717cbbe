// A .path (batch) file: read, or refused with an InputError.
#include "freespace/input_error.h"
#include "freespace/problem/path_file.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    freespace::readPath(fuzzInputFile(data, size, ".path"));
  } catch (const freespace::InputError&) {
  }
  return 0;
}
