// Inputs the fuzz targets (tests/fuzz, scripts/fuzz.sh) once failed on, kept in
// tests/fuzz/regressions/TARGET: each must now be read or refused with exit status 2
// within a time limit, by the command line tool as a user would meet it.
#include <gtest/gtest.h>

#include <filesystem>

#include "command_runner.h"
#include "fuzz/saved_space_file.h"

using freespace::testing::CommandResult;
using freespace::testing::runFreespace;
using freespace::testing::TempDir;

namespace fs = std::filesystem;

namespace {

// The saved-space target's input is a payload (tests/fuzz/fuzz_saved_space.cpp): the
// file it stands for, with the header line, the length and a valid checksum.
std::string savedSpaceOf(const fs::path& payloadFile, const TempDir& dir) {
  return dir.write(payloadFile.filename().string() + ".fspace",
                   savedSpaceFileAround(freespace::testing::readWholeFile(payloadFile.string())));
}

}  // namespace

TEST(FuzzRegressions, EveryFoundInputIsReadOrRefusedInTime) {
  const fs::path root = fs::path(FREESPACE_SOURCE_DIR) / "tests/fuzz/regressions";
  const std::string cube = "'" + std::string(FREESPACE_TEST_DATA) + "/meshes/cube.obj'";
  int inputs = 0;
  const TempDir dir;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const std::string target = entry.path().parent_path().filename().string();
    const std::string file = "'" + entry.path().string() + "'";
    std::string arguments;
    if (target == "fuzz_saved_space") arguments = "locate '" + savedSpaceOf(entry.path(), dir) + "' --at 0 0 0";
    else if (target == "fuzz_cfg") arguments = "info --cfg " + file;
    else if (target == "fuzz_path") arguments = "check " + cube + " " + cube + " --batch " + file;
    else arguments = "info " + file + " " + cube;
    const CommandResult result = runFreespace(arguments, 30);
    EXPECT_TRUE(result.status == 0 || result.status == 2) << arguments << ": status " << result.status << "\n"
                                                          << result.err;
    ++inputs;
  }
  EXPECT_GT(inputs, 0);
}
