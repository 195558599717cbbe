// A mesh file of one format (FUZZ_EXTENSION): it is read, or refused with an
// InputError; anything else (a crash, a hang, runaway memory, another exception) is
// a finding.
#include "freespace/input_error.h"
#include "freespace/io/mesh_reader.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    freespace::importMesh(fuzzInputFile(data, size, FUZZ_EXTENSION));
  } catch (const freespace::InputError&) {
  }
  return 0;
}
