// Output files: written whole or not at all, never replacing a user's file unasked
// (decided atomically, so two writers never both succeed), every write checked
// (a full device is an error), and no temporary file left by a failure or a signal.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "command_runner.h"
#include "freespace/input_error.h"
#include "freespace/io/output_file.h"
#include "temp_dir.h"

using namespace freespace;
using freespace::testing::readWholeFile;
using freespace::testing::TempDir;

namespace {

std::vector<std::string> filesIn(const TempDir& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir.file(""))) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(OutputFile, WritesWholeFilesAndLeavesNothingElse) {
  const TempDir dir;
  const std::string path = dir.file("out.txt");
  writeFile(path, false, [](std::ostream& out) { out << "first\n"; });
  EXPECT_EQ(readWholeFile(path), "first\n");
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"out.txt"});
  struct stat info {};
  ASSERT_EQ(::stat(path.c_str(), &info), 0);
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(info.st_mode & 0777, 0666 & ~mask) << "the mode a created file gets, not a temporary file's 0600";
}

TEST(OutputFile, NeverReplacesAFileUnasked) {
  const TempDir dir;
  const std::string path = dir.write("out.txt", "the user's\n");
  EXPECT_EQ(errorOf([&] { writeFile(path, false, [](std::ostream& out) { out << "new\n"; }); }),
            path + ": already exists (not overwritten)");
  EXPECT_EQ(readWholeFile(path), "the user's\n");
  writeFile(path, true, [](std::ostream& out) { out << "new\n"; });
  EXPECT_EQ(readWholeFile(path), "new\n");
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"out.txt"});
}

TEST(OutputFile, AFailedWriteLeavesTheUsersFileAndNoTemporary) {
  const TempDir dir;
  const std::string path = dir.write("out.txt", "the user's\n");
  EXPECT_THROW(writeFile(path, true,
                         [](std::ostream& out) {
                           out << "half";
                           throw std::runtime_error("failed half way");
                         }),
               std::runtime_error);
  EXPECT_EQ(readWholeFile(path), "the user's\n");
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"out.txt"});
}

TEST(OutputFile, FoldersFullDevicesAndMissingFoldersAreErrorsNamingThePath) {
  const TempDir dir;
  const auto write = [](std::ostream& out) { out << std::string(1 << 20, 'x'); };
  EXPECT_EQ(errorOf([&] { writeFile(dir.file(""), true, write); }), dir.file("") + ": cannot write: is a folder");
  EXPECT_EQ(errorOf([&] { writeFile("/dev/full", true, write); }), "/dev/full: cannot write: No space left on device");
  struct stat info {};
  ASSERT_EQ(::stat("/dev/full", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode)) << "a device is written in place, never replaced";
  const std::string missing = dir.file("no/such/folder/out.txt");
  EXPECT_EQ(errorOf([&] { writeFile(missing, false, write); }), missing + ": cannot write: No such file or directory");
}

TEST(OutputFile, OfTwoWritersOfANewFileExactlyOneSucceeds) {
  for (int round = 0; round < 10; ++round) {
    const TempDir dir;
    const std::string path = dir.file("out.txt");
    std::atomic<int> succeeded{0}, refused{0};
    const auto writer = [&](char mark) {
      try {
        writeFile(path, false, [&](std::ostream& out) {
          std::this_thread::sleep_for(std::chrono::milliseconds(20));  // both past the first check
          out << std::string(1000, mark);
        });
        ++succeeded;
      } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("already exists"), std::string::npos) << error.what();
        ++refused;
      }
    };
    std::thread first(writer, 'a'), second(writer, 'b');
    first.join();
    second.join();
    EXPECT_EQ(succeeded, 1);
    EXPECT_EQ(refused, 1);
    const std::string content = readWholeFile(path);
    EXPECT_TRUE(content == std::string(1000, 'a') || content == std::string(1000, 'b'));
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"out.txt"});
  }
}

TEST(OutputFile, PendingTemporaryFilesAreRemovedOnRequest) {
  const TempDir dir;
  std::vector<std::string> during, afterRemoval;
  EXPECT_THROW(writeFile(dir.file("out.txt"), false,
                         [&](std::ostream& out) {
                           out << "partial";
                           during = filesIn(dir);
                           removePendingOutputs();  // what a signal handler does
                           afterRemoval = filesIn(dir);
                         }),
               InputError);
  ASSERT_EQ(during.size(), 1u);
  EXPECT_EQ(during[0].rfind(".out.txt.", 0), 0u) << during[0];
  EXPECT_TRUE(afterRemoval.empty());
  EXPECT_TRUE(filesIn(dir).empty());
}

TEST(OutputFile, ASignalWhileAFileIsWrittenLeavesNothingBehind) {
  // The export of a 35,216-facet scene writes its PLY (140 MB) for seconds: SIGTERM
  // once the temporary file is there, while it grows.
  const TempDir dir;
  ASSERT_EQ(freespace::testing::runFreespace("generate --out '" + dir.file("scene") + "' --scene tetra_floorplan_1024").status, 0);
  const TempDir scripts;
  const std::string script = scripts.write(
      "stop.sh", std::string("'") + FREESPACE_CLI + "' export --cfg '" + dir.file("scene/tetra_floorplan_1024.cfg") +
                     "' --ply '" + dir.file("out.ply") + "' 2>/dev/null &\npid=$!\nfor i in $(seq 600); do\n  ls -a '" +
                     dir.file("") + "' | grep -q '^[.]out[.]ply[.]' && break\n  sleep 0.05\ndone\nkill -TERM $pid\nwait $pid\n");
  const int raw = std::system(("bash '" + script + "'").c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 143);
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"scene"});
}

TEST(OutputFile, StandardOutputThatCannotBeWrittenIsAnError) {
  const std::string command = std::string("'") + FREESPACE_CLI + "' check --cfg '" + FREESPACE_SOURCE_DIR +
                              "/benchmarks/problems/keyhole.cfg' --at 0 0 0 >/dev/full 2>/dev/null";
  const int raw = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 2);
}
