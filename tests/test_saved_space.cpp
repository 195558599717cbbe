// Saving and loading a built free space: the loaded one answers every locate as the
// built one (and so as the exact collision test, checked elsewhere), without
// rebuilding; files that are not saved free spaces, of another format version,
// truncated, altered, or already present are clear errors naming the file.
#include <gtest/gtest.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <fstream>
#include <random>
#include <sstream>

#include "freespace/input_error.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/free_space.h"
#include "space/saved_space.h"
#include "fuzz/saved_space_file.h"
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

/// Where the payload starts: after the header line.
std::size_t payloadStartOf(const std::string& bytes) { return bytes.find('\n') + 1; }

/// The payload of a saved file's bytes: after the header line, before its size and checksum.
std::string payloadOf(const std::string& bytes) {
  return bytes.substr(payloadStartOf(bytes), bytes.size() - 16 - payloadStartOf(bytes));
}

/// The bytes of builtSpace() saved in `dir`.
std::string savedBytes(const TempDir& dir) {
  const std::string file = dir.file("space.fspace");
  builtSpace().save(file);
  return contents(file);
}

/// Writes `value` as 8 little-endian bytes at `at`.
void putUint64(std::string& bytes, std::size_t at, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xff);
}

/// A saved file's payload decoded.
saved::Space spaceOf(const std::string& bytes) {
  saved::Space space;
  std::istringstream in(payloadOf(bytes));
  boost::archive::binary_iarchive archive(in);
  archive >> space;
  return space;
}

/// The payload of a saved file's `bytes` decoded, altered by `alter`, and written
/// again into a file with a valid checksum; returns the file's path.
std::string fileWithSpaceAltered(const TempDir& dir, const std::string& bytes,
                                 const std::function<void(saved::Space&)>& alter) {
  saved::Space space = spaceOf(bytes);
  alter(space);
  std::ostringstream out;
  {
    boost::archive::binary_oarchive archive(out);
    archive << space;
  }
  const std::string file = dir.file("altered_space.fspace");
  write(file, savedSpaceFileAround(out.str()));
  return file;
}

/// Where in `payload` the text `text` is written: its 8-byte length, then its bytes.
std::size_t whereTextIs(const std::string& payload, const std::string& text) {
  std::string written(8, '\0');
  putUint64(written, 0, text.size());
  return payload.find(written + text);
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
    if (i % 20 == 0) {  // and the clearance, from the same pieces of the same slices
      const Clearance fromBuilt = built.clearance(pose), fromLoaded = loaded->clearance(pose);
      different += fromBuilt.lower != fromLoaded.lower || fromBuilt.upper != fromLoaded.upper;
    }
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
  version.replace(bytes.find('\n') - 1, 1, "8");
  write(other, version);
  EXPECT_NE(loadError(other).find("format 8; this build reads format 9"), std::string::npos);
  write(other, bytes.substr(0, bytes.size() / 2));
  EXPECT_NE(loadError(other).find("damaged"), std::string::npos);
  std::string altered = bytes;
  altered[altered.size() / 2] = static_cast<char>(altered[altered.size() / 2] ^ 0x5a);
  write(other, altered);
  EXPECT_NE(loadError(other).find("checksum"), std::string::npos);
  EXPECT_EQ(loadError(dir.file("missing.fspace")), "cannot open file: No such file or directory");
}

TEST(SavedSpace, AlteredPayloadsWithAValidChecksumLoadOrFailCleanly) {
  const FreeSpace& built = builtSpace();
  TempDir dir;
  const std::string file = dir.file("space.fspace");
  built.save(file);
  const std::string bytes = contents(file);
  const std::size_t payloadStart = payloadStartOf(bytes);
  std::mt19937 random(17);
  std::uniform_int_distribution<std::size_t> position(payloadStart, bytes.size() - 17);
  int loaded = 0, rejected = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::string altered = bytes;
    for (int flip = 0; flip < 4; ++flip) altered[position(random)] ^= static_cast<char>(1 + trial % 255);
    const std::string other = dir.file("altered.fspace");
    write(other, savedSpaceFileAround(payloadOf(altered)));
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

// A text's length altered to 16 GiB (the functions' exact coefficients; the checksum
// made valid again) is damage found before any memory is set aside for it: a clear
// error at once, not a loader that fills the machine's memory.
TEST(SavedSpace, AHugeTextLengthIsAClearErrorWithoutAllocating) {
  TempDir dir;
  const std::string bytes = savedBytes(dir);
  std::string payload = payloadOf(bytes);
  const std::size_t at = whereTextIs(payload, spaceOf(bytes).functions.exact);
  ASSERT_NE(at, std::string::npos) << "the functions' coefficients not found in the payload";
  putUint64(payload, at, std::uint64_t(1) << 34);
  const std::string other = dir.file("huge.fspace");
  write(other, savedSpaceFileAround(payload));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(loadError(other), "damaged: a text longer than the rest of the file");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "rejected in " << seconds << " s\n";
}

// An angle's exact interval made an unreduced fraction (its lower end's numerator and
// denominator both even) is refused as damage before GMP takes it.
TEST(SavedSpace, AnUnreducedFractionIsRefused) {
  TempDir dir;
  const std::string file = fileWithSpaceAltered(dir, savedBytes(dir), [](saved::Space& space) {
    std::string& bytes = space.angles.exactIntervals;
    ASSERT_GE(bytes.size(), 11u) << "no exact interval in the table";
    // A sign byte, the numerator's 4-byte length and bytes, the denominator's.
    const std::size_t numerator = static_cast<unsigned char>(bytes[1]);  // lengths below 256
    const std::size_t denominator = static_cast<unsigned char>(bytes[5 + numerator]);
    bytes[4 + numerator] = 2;
    bytes[8 + numerator + denominator] = 4;
  });
  EXPECT_EQ(loadError(file), "inconsistent saved free space at a number");
}

// Every 8-byte value in the payload that could be a length (1 to 100,000) raised by
// 2^26, the checksum made valid again: each file loads or is refused at once with one
// of the loader's own plain messages, never the archive's or the standard library's
// texts, and without setting aside memory for the claimed length.
TEST(SavedSpace, AlteredLengthsAreRefusedWithPlainMessages) {
  TempDir dir;
  const std::string bytes = savedBytes(dir);
  const std::size_t payloadStart = payloadStartOf(bytes);
  const std::string other = dir.file("altered.fspace");
  int altered = 0;
  for (std::size_t at = payloadStart; at + 8 <= bytes.size() - 16 && altered < 300; ++at) {
    std::uint64_t value = 0;
    for (int i = 0; i < 8; ++i)
      value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
    if (value == 0 || value > 100000) continue;
    std::string changed = bytes;
    putUint64(changed, at, value + (std::uint64_t(1) << 26));
    write(other, savedSpaceFileAround(payloadOf(changed)));
    ++altered;
    try {
      FreeSpace::load(other);
    } catch (const InputError& error) {
      const std::string problem = error.problem();
      const bool plain =
          problem.rfind("damaged: ", 0) == 0 || problem.rfind("inconsistent saved free space at ", 0) == 0;
      EXPECT_TRUE(plain) << "at byte " << at << ": " << problem;
      for (const char* libraryText : {"std::", "::_M_", "stream error", "bad_alloc", "basic_string"}) {
        EXPECT_EQ(problem.find(libraryText), std::string::npos) << "at byte " << at << ": " << problem;
      }
    }
  }
  EXPECT_GE(altered, 100);
}

namespace {

/// The loader's complaint about the saved `bytes` with their graph altered.
std::string errorWithGraphAltered(const TempDir& dir, const std::string& bytes,
                                  const std::function<void(saved::Graph&)>& alter) {
  return loadError(fileWithSpaceAltered(dir, bytes, [&](saved::Space& space) { alter(space.graph); }));
}

}  // namespace

// A graph whose parts do not fit the rest is refused naming the part.
TEST(SavedSpace, ADamagedGraphIsRefusedNamingThePart) {
  TempDir dir;
  const std::string bytes = savedBytes(dir);
  const std::vector<std::pair<std::function<void(saved::Graph&)>, std::string>> cases{
      {[](saved::Graph& graph) { graph.nodes[0] = 1000; }, "a node of the graph"},
      {[](saved::Graph& graph) { graph.nodes[2] = 1u << 30; }, "a node of the graph"},
      {[](saved::Graph& graph) {
         graph.edges.insert(graph.edges.end(), {0, 999, 0});
       },
       "an edge of the graph"},
      {[](saved::Graph& graph) { graph.runCounts.pop_back(); }, "the graph's pieces"},
      {[](saved::Graph& graph) {
         graph.runs.insert(graph.runs.end(), {0, 0});
       },
       "the graph's runs"},
      {[](saved::Graph& graph) { graph.nodes.pop_back(); }, "the graph's nodes"},
      {[](saved::Graph& graph) { std::swap(graph.criticalAngles[0], graph.criticalAngles[1]); },
       "the graph's critical angles"},
  };
  for (const auto& [alter, part] : cases) {
    const std::string error = errorWithGraphAltered(dir, bytes, alter);
    EXPECT_NE(error.find("inconsistent saved free space at " + part), std::string::npos) << error;
  }
}

// Lists of a part that do not fit together (an item's entry missing from one list)
// are refused naming the part, before any item is built from them.
TEST(SavedSpace, ListsOfAPartThatDoNotFitAreRefusedNamingThePart) {
  TempDir dir;
  const std::string bytes = savedBytes(dir);
  const std::vector<std::pair<std::function<void(saved::Space&)>, std::string>> cases{
      {[](saved::Space& space) { space.functions.keyed.pop_back(); }, "the functions"},
      {[](saved::Space& space) { space.functions.enclosures.pop_back(); }, "the functions"},
      {[](saved::Space& space) { space.functions.exactEnds.back() += 1; }, "the functions"},
      {[](saved::Space& space) { space.angles.charts.pop_back(); }, "the angles"},
      {[](saved::Space& space) { space.angles.charts.back() = 2; }, "an angle"},
      {[](saved::Space& space) { space.angles.functions.back() = 1 << 30; }, "an angle's function"},
      {[](saved::Space& space) { space.patches.linePoints.pop_back(); }, "the patches"},
      {[](saved::Space& space) { space.patches.ranges.arcCounts.back() += 1; }, "an angle set's arcs"},
      {[](saved::Space& space) { space.patches.ranges.fullCircle.back() = 7; }, "an angle set"},
      {[](saved::Space& space) { space.curves.ends.pop_back(); }, "the curves"},
      {[](saved::Space& space) { space.subdivisions.faces.pop_back(); }, "the subdivisions"},
      {[](saved::Space& space) { space.subdivisions.slabAngles.back() = 1u << 30; }, "an angle's index"},
  };
  for (const auto& [alter, part] : cases) {
    const std::string error = loadError(fileWithSpaceAltered(dir, bytes, alter));
    EXPECT_EQ(error, "inconsistent saved free space at " + part);
  }
}

// Values that the structure would trip over later (an infinite enclosure a rational
// is made from, a root outside its chart, a root's place that sizes a table, a
// vertex's crossing that indexes its three patches, an undefined node box, a stage's
// time or one time too many) are refused at loading.
TEST(SavedSpace, ValuesUsedLaterAreCheckedAtLoading) {
  TempDir dir;
  const std::string bytes = savedBytes(dir);
  const auto firstRoot = [](const saved::Space& space) {
    const auto& functions = space.angles.functions;
    const auto root = std::find_if(functions.begin(), functions.end(), [](std::int32_t f) { return f >= 0; });
    EXPECT_NE(root, functions.end()) << "no root in the table";
    return static_cast<std::size_t>(root - functions.begin());
  };
  const std::vector<std::pair<std::function<void(saved::Space&)>, std::string>> cases{
      {[&](saved::Space& space) { space.angles.enclosures[2 * firstRoot(space)] = -HUGE_VAL; }, "an angle"},
      {[&](saved::Space& space) { space.angles.indices[firstRoot(space)] = 1 << 30; }, "an angle"},
      {[](saved::Space& space) {
         ASSERT_FALSE(space.vertices.crossings.empty());
         space.vertices.crossings.front() = 7;
       },
       "a vertex"},
      {[](saved::Space& space) { space.graph.nodeGeometry[2] = NAN; }, "a node's box"},
      {[](saved::Space& space) { space.stageSeconds.front() = NAN; }, "the stages' times"},
      {[](saved::Space& space) { space.stageSeconds.push_back(1); }, "the stages' times"},
      {[&](saved::Space& space) { space.angles.enclosures[2 * firstRoot(space) + 1] = 2; }, "an angle"},
  };
  for (const auto& [alter, part] : cases) {
    EXPECT_EQ(loadError(fileWithSpaceAltered(dir, bytes, alter)), "inconsistent saved free space at " + part);
  }
}

// A list's length that the bytes left could hold as bytes but not as its numbers
// (the last list, the graph's unbounded runs, claiming four times its numbers) is
// refused before the list is made.
TEST(SavedSpace, AListLongerThanItsNumbersIsRefused) {
  TempDir dir;
  const std::string bytes = savedBytes(dir);
  std::string payload = payloadOf(bytes);
  const std::size_t numbers = spaceOf(bytes).graph.unboundedRuns.size();
  ASSERT_GT(numbers, 0u);
  const std::size_t countAt = payload.size() - 4 * numbers - 8;
  ASSERT_EQ(static_cast<unsigned char>(payload[countAt]), numbers & 0xff);
  putUint64(payload, countAt, 4 * numbers);
  const std::string file = dir.file("longer.fspace");
  write(file, savedSpaceFileAround(payload));
  EXPECT_EQ(loadError(file), "damaged: a list longer than the rest of the file");
}

// A function's exact coefficients are decoded when first needed: a coefficient
// altered behind a valid checksum (its most significant byte changed, so that it
// leaves its stored double enclosure) loads with the structure checked, and is refused
// naming the file when they are decoded (here all of them, LoadCheck::Everything).
TEST(SavedSpace, AnAlteredExactCoefficientIsRefusedWhenDecoded) {
  TempDir dir;
  const std::string bytes = savedBytes(dir);
  const std::string intact = dir.file("intact.fspace");
  write(intact, bytes);
  EXPECT_NO_THROW(FreeSpace::load(intact, FreeSpace::LoadCheck::Everything));
  bool altered = false;
  const std::string file = fileWithSpaceAltered(dir, bytes, [&](saved::Space& space) {
    const saved::Functions& functions = space.functions;
    for (std::size_t i = 0; i < functions.exactEnds.size(); ++i) {
      // A function's first coefficient: a sign byte, the numerator's 4-byte length, its bytes.
      const std::size_t begin = i == 0 ? 0 : functions.exactEnds[i - 1];
      if (functions.exactEnds[i] - begin < 6 || functions.exact[begin + 1] == 0) continue;
      char& mostSignificant = space.functions.exact[begin + 5];
      mostSignificant ^= static_cast<char>(mostSignificant == 0x40 ? 0x20 : 0x40);
      altered = true;
      return;
    }
  });
  ASSERT_TRUE(altered) << "no function with a nonzero coefficient";
  EXPECT_NO_THROW(FreeSpace::load(file));
  try {
    FreeSpace::load(file, FreeSpace::LoadCheck::Everything);
    ADD_FAILURE() << "the altered coefficient was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file);
    EXPECT_EQ(error.problem(), "inconsistent saved free space at a function's exact coefficients");
  }
}

// A sub-division's face count beyond the faces its slabs hold is refused before the
// shells set memory aside for it (a fuzzer's input claimed hundreds of millions).
TEST(SavedSpace, AFaceCountBeyondTheSlabsIsRefused) {
  TempDir dir;
  const std::string file = fileWithSpaceAltered(
      dir, savedBytes(dir), [](saved::Space& space) { space.subdivisions.faceCounts.front() = 1u << 28; });
  EXPECT_EQ(loadError(file), "inconsistent saved free space at a subdivision's face count");
}
