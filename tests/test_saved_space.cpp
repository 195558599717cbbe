// Saving and loading a built free space: the loaded one answers every locate as the
// built one (and so as the exact collision test, checked elsewhere), without
// rebuilding; files that are not saved free spaces, of another format version,
// truncated, altered, or already present are clear errors naming the file.
#include <gtest/gtest.h>

#include <boost/crc.hpp>
#include <chrono>
#include <fstream>
#include <random>
#include <sstream>

#include "freespace/input_error.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/free_space.h"
#include "temp_dir.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream all;
  all << in.rdbuf();
  return all.str();
}

void write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

/// The problem's free space, built once for the tests of this file.
const FreeSpace& builtSpace() {
  static const std::unique_ptr<FreeSpace> space = [] {
    const LoadedProblem problem =
        loadProblem(std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole_narrow.cfg");
    return std::make_unique<FreeSpace>(problem.robot, problem.world);
  }();
  return *space;
}

std::string loadError(const std::string& path) {
  try {
    FreeSpace::load(path);
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    return error.problem();
  }
  ADD_FAILURE() << "loaded " << path;
  return {};
}

}  // namespace

TEST(SavedSpace, LoadedSpaceLocatesAsTheBuiltOne) {
  const FreeSpace& built = builtSpace();
  TempDir dir;
  const std::string file = dir.file("keyhole_narrow.fspace");
  built.save(file);
  const auto start = std::chrono::steady_clock::now();
  const std::unique_ptr<FreeSpace> loaded = FreeSpace::load(file);
  const double loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(loaded->cellCount(), built.cellCount());
  EXPECT_EQ(loaded->shellCount(), built.shellCount());
  EXPECT_EQ(loaded->freeShellCount(), built.freeShellCount());
  const Box3 world = built.meshes().world.bounds();
  std::mt19937 random(3);
  std::uniform_real_distribution<double> x(world.min().x() - 1, world.max().x() + 1);
  std::uniform_real_distribution<double> y(world.min().y() - 1, world.max().y() + 1);
  std::uniform_real_distribution<double> theta(-M_PI, M_PI);
  int different = 0, free = 0;
  for (int i = 0; i < 2000; ++i) {
    const Pose2 pose{x(random), y(random), theta(random)};
    const Location a = built.locate(pose), b = loaded->locate(pose);
    free += a.free;
    different += a.free != b.free || (a.free && a.cell != b.cell);
  }
  EXPECT_EQ(different, 0);
  EXPECT_GT(free, 0);
  std::cout << "saved " << contents(file).size() << " bytes; loaded in " << loadSeconds << " s\n";
}

TEST(SavedSpace, BadFilesAreClearErrors) {
  const FreeSpace& built = builtSpace();
  TempDir dir;
  const std::string file = dir.file("space.fspace");
  built.save(file);
  const std::string bytes = contents(file);
  // An existing file is never replaced.
  try {
    built.save(file);
    ADD_FAILURE() << "overwrote " << file;
  } catch (const InputError& error) {
    EXPECT_EQ(error.problem(), "already exists (not overwritten)");
  }
  EXPECT_EQ(contents(file), bytes);
  const std::string other = dir.file("other.fspace");
  write(other, "v 0 0 0\n");
  EXPECT_NE(loadError(other).find("not a saved free space"), std::string::npos);
  std::string version = bytes;
  version.replace(bytes.find('\n') - 1, 1, "9");
  write(other, version);
  EXPECT_NE(loadError(other).find("format 9; this build reads format 1"), std::string::npos);
  write(other, bytes.substr(0, bytes.size() / 2));
  EXPECT_NE(loadError(other).find("damaged"), std::string::npos);
  std::string altered = bytes;
  altered[altered.size() / 2] = static_cast<char>(altered[altered.size() / 2] ^ 0x5a);
  write(other, altered);
  EXPECT_NE(loadError(other).find("checksum"), std::string::npos);
  EXPECT_EQ(loadError(dir.file("missing.fspace")), "cannot open file");
}

TEST(SavedSpace, AlteredPayloadsWithAValidChecksumLoadOrFailCleanly) {
  const FreeSpace& built = builtSpace();
  TempDir dir;
  const std::string file = dir.file("space.fspace");
  built.save(file);
  const std::string bytes = contents(file);
  const std::size_t payloadStart = bytes.find('\n') + 1 + 12;  // header line, size, CRC-32
  std::mt19937 random(17);
  std::uniform_int_distribution<std::size_t> position(payloadStart, bytes.size() - 1);
  int loaded = 0, rejected = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::string altered = bytes;
    for (int flip = 0; flip < 4; ++flip) altered[position(random)] ^= static_cast<char>(1 + trial % 255);
    // A valid CRC-32 for the altered payload, little-endian after the size.
    boost::crc_32_type crc;
    crc.process_bytes(altered.data() + payloadStart, altered.size() - payloadStart);
    for (int i = 0; i < 4; ++i) altered[payloadStart - 4 + i] = static_cast<char>((crc.checksum() >> (8 * i)) & 0xff);
    const std::string other = dir.file("altered.fspace");
    write(other, altered);
    try {
      FreeSpace::load(other);
      ++loaded;
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), other);
      ++rejected;
    }
  }
  EXPECT_EQ(loaded + rejected, 40);
  std::cout << loaded << " altered files loaded, " << rejected << " rejected\n";
}
