// The hostile inputs and faults once found against the command line tool, each kept
// as a regression test with its exit status and message. Where each case lives:
//
// Mesh import that crashed, hung or ran out of memory (truncated ASCII and binary
// PLY and OFF, a PLY cut inside its header, an OFF header claiming 1e9 vertices,
// COLLADA nested 10,000 deep or instancing itself, junk in a COLLADA index list):
//   MeshFileChecks.* (every prefix, every byte edit, counts beyond the file, hostile
//   COLLADA) and FuzzRegressions.EveryFoundInputIsReadOrRefusedInTime.
// Valid meshes refused or malformed accepted: MeshReader.ReadsOffFacesOfAnySize,
//   MeshFileChecks.FacesWithFewerThanThreeVerticesAreRefused, and a COLLADA
//   coordinate the import library would misread: MeshFileChecks.HostileColladaIsRefusedNamingTheDefect.
// Angles of 1e15 and beyond: AngleReduction.* (check and locate against the exact test).
// Output to a full device, signals, concurrent writers, "already exists": OutputFile.*,
//   CliFreeSpace.InterruptStopsABuildWithStatus130 / TerminationStopsABuildWithStatus143.
// Exit codes and option values: Cli.BadOptionValuesExitWithStatusTwoNamingTheOption;
//   coordinates beyond single precision: MeshFileChecks.CoordinatesBeyondSinglePrecisionAreReportedAsRead;
//   library texts (std::bad_alloc, vector::_M_...): SavedSpace.AlteredLengthsAreRefusedWithPlainMessages;
//   a NUL byte in a .cfg: Problem.BadValuesAndSyntaxAreErrors.
// Tiny and huge scenes: HostileInput.TinyAndHugeCoordinatesGiveTheSameCells,
//   MeshReader.ReadsATinyModelAsTheSameSolid, and below.
// A 2-million-triangle environment (heights that collided after perturbation, then
//   memory beyond the machine's): PerturbedMeshes.EveryVertexHeightIsDistinctEvenWhenOffsetsCollide,
//   FreeSpaceConstruction.PatchCandidatesBoundThePatchesAndAreWeighedAgainstTheMemoryLimit, and below.
// FIFOs and devices as input: Cli.PipesAndDevicesAsInputAreRefusedNotWaitedOn.
// A directory as batch file, a trailing comment on a batch line: below.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>

#include "command_runner.h"
#include "freespace/io/mesh_writer.h"
#include "freespace/problem/planar_problem.h"

using namespace freespace;
using namespace freespace::testing;

namespace {

const std::string kKeyhole = std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole.cfg";

}  // namespace

TEST(HostileCases, ADirectoryAsBatchFileIsAnErrorNamingIt) {
  TempDir dir;
  std::filesystem::create_directory(dir.file("batch"));
  const CommandResult result = runFreespace("locate --cfg " + quoted(kKeyhole) + " --batch " + quoted(dir.file("batch")));
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err, "error: " + dir.file("batch") + ": cannot open file: it is a directory\n");
  EXPECT_EQ(result.out, "");
}

TEST(HostileCases, ATrailingCommentOnABatchLineIsAComment) {
  TempDir dir;
  const std::string batch = dir.write("batch.path", "0 -2.25 0 # the start\n# a line of its own\n0 0 0\n");
  const CommandResult result = runFreespace("locate --cfg " + quoted(kKeyhole) + " --batch " + quoted(batch));
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(std::regex_match(result.out, std::regex("0 -2.25 0: free, cell 1, node [0-9]+\n0 0 0: blocked\n")))
      << result.out;
}

// The keyhole at 2^-100 (about 1e-30) from files: located as at its own size (a build
// that took 14.5 s and a division by an interval holding zero at 1e-38, before scenes
// were scaled), under a time limit.
TEST(HostileCases, ATinySceneIsLocatedAsAtItsOwnSize) {
  const LoadedProblem keyhole = loadProblem(kKeyhole);
  TempDir dir;
  const double factor = std::ldexp(1.0, -100);
  for (const auto& [mesh, name] : {std::pair{&keyhole.robot, "robot.stl"}, std::pair{&keyhole.world, "world.stl"}}) {
    TriangleSoup soup{{}, mesh->triangles()};
    for (const Point3& vertex : mesh->vertices()) soup.vertices.push_back(vertex * factor);
    writeSoup(soup, dir.file(name));
  }
  char start[64];
  std::snprintf(start, sizeof start, "0 %.17g 0", -2.25 * factor);
  const std::string batch = dir.write("batch.path", std::string(start) + "\n0 0 0\n");
  const CommandResult result = runFreespace(
      "locate " + quoted(dir.file("robot.stl")) + " " + quoted(dir.file("world.stl")) + " --batch " + quoted(batch), 60);
  EXPECT_EQ(result.status, 0) << result.err;
  const std::string expected = std::regex_replace(start, std::regex("[.+-]"), "\\$&");
  EXPECT_TRUE(std::regex_match(result.out, std::regex(expected + ": free, cell 1, node [0-9]+\n0 0 0: blocked\n")))
      << result.out << result.err;
}

// A scene whose construction needs more memory than allowed is refused before any
// patch is built, with the estimate (2 million triangles: at least 26 GB, after
// loading, on a machine of 25 GB; here the keyhole under a limit of 1 MB).
TEST(HostileCases, AConstructionBeyondTheMemoryLimitIsRefusedWithAnEstimate) {
  const CommandResult result = runFreespace("build --cfg " + quoted(kKeyhole) + " --memory-limit 0.001");
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err.rfind("error: " + kKeyhole + ": the construction needs at least ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find("more than the memory limit of 0.001 GB"), std::string::npos) << result.err;
}
