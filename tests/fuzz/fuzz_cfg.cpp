// An OMPL.app .cfg file: read, or refused with an InputError.
#include "freespace/input_error.h"
#include "freespace/problem/planar_problem.h"
#include "fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    std::vector<std::string> warnings;
    freespace::readProblem(fuzzInputFile(data, size, ".cfg"), &warnings);
  } catch (const freespace::InputError&) {
  }
  return 0;
}
