// Reading mesh files: every format, node transforms, the VTK reader, and the
// malformed files of tests/data/meshes with the message each must produce.
//
// Malformed files (tests/data/meshes/bad_*) are listed in kMalformedFiles, each with
// a substring of its InputError problem (the full message is "<path>: <problem>");
// the repairable ones (repairable_*) load as the solids they show.
//
// A path that does not exist gives "cannot open file".

#include "freespace/io/mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "freespace/input_error.h"
#include "temp_dir.h"

namespace freespace {
namespace {

namespace fs = std::filesystem;

const std::string kMeshes = std::string(FREESPACE_TEST_DATA) + "/meshes/";

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

// The problem loadMesh reports for `path`, or "" when it loads.
std::string loadProblem(const std::string& path) {
  try {
    loadMesh(path);
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(std::string(error.what()), path + ": " + error.problem());
    return error.problem();
  }
  return "";
}

void expectBounds(const Mesh& mesh, const Point3& min, const Point3& max) {
  EXPECT_EQ(mesh.bounds().min(), min) << mesh.bounds().min().transpose();
  EXPECT_EQ(mesh.bounds().max(), max) << mesh.bounds().max().transpose();
}

// ---------------------------------------------------------------------------
// Well-formed files

TEST(MeshReader, ReadsObjQuadsAsTriangles) {
  const TriangleSoup soup = readTriangleSoup(kMeshes + "cube.obj");
  EXPECT_EQ(soup.triangles.size(), 12u);
  const Mesh mesh = loadMesh(kMeshes + "cube.obj");
  EXPECT_EQ(mesh.vertices().size(), 8u);
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_EQ(mesh.componentCount(), 1u);
  EXPECT_EQ(mesh.volume(), 1.0);
  expectBounds(mesh, Point3(0, 0, 0), Point3(1, 1, 1));
}

TEST(MeshReader, ReadsTwoObjectsAsTwoComponents) {
  const Mesh mesh = loadMesh(kMeshes + "two_cubes.obj");
  EXPECT_EQ(mesh.componentCount(), 2u);
  EXPECT_EQ(mesh.vertices().size(), 16u);
  EXPECT_EQ(mesh.triangles().size(), 24u);
  EXPECT_EQ(mesh.volume(), 2.0);
  expectBounds(mesh, Point3(0, 0, 0), Point3(4, 1, 1));
}

TEST(MeshReader, FlipsAnInsideOutFileWithAWarning) {
  const std::string path = kMeshes + "inside_out_cube.obj";
  std::vector<std::string> warnings;
  const Mesh mesh = loadMesh(path, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], path + ": 12 triangles of closed components turned to face outward like their neighbours");
  EXPECT_EQ(mesh.volume(), 1.0);
}

TEST(MeshReader, ReadsAsciiStl) {
  const Mesh mesh = loadMesh(kMeshes + "box_ascii.stl");
  EXPECT_EQ(mesh.vertices().size(), 8u);
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_EQ(mesh.volume(), 8.0);
  expectBounds(mesh, Point3(-1, -1, -1), Point3(1, 1, 1));
}

void appendBinary(std::string& bytes, const void* data, std::size_t size) {
  bytes.append(static_cast<const char*>(data), size);
}

// Binary STL (little-endian): 80-byte header, triangle count, then per triangle a
// normal, three vertices (floats) and a 2-byte attribute.
std::string binaryStl(const TriangleSoup& soup) {
  std::string bytes(80, ' ');
  bytes.replace(0, 25, "binary STL of a test box.");
  const auto count = static_cast<std::uint32_t>(soup.triangles.size());
  appendBinary(bytes, &count, sizeof count);
  for (const TriangleIndices& triangle : soup.triangles) {
    const float normal[3] = {0, 0, 0};
    appendBinary(bytes, normal, sizeof normal);
    for (std::uint32_t index : triangle) {
      const float corner[3] = {static_cast<float>(soup.vertices[index].x()),
                               static_cast<float>(soup.vertices[index].y()),
                               static_cast<float>(soup.vertices[index].z())};
      appendBinary(bytes, corner, sizeof corner);
    }
    const std::uint16_t attribute = 0;
    appendBinary(bytes, &attribute, sizeof attribute);
  }
  return bytes;
}

TEST(MeshReader, ReadsBinaryStl) {
  const Mesh box = loadMesh(kMeshes + "cube.obj");
  TriangleSoup soup{box.vertices(), box.triangles()};
  for (Point3& vertex : soup.vertices) vertex = vertex.cwiseProduct(Point3(2, 3, 5));
  const testing::TempDir directory;
  const Mesh mesh = loadMesh(directory.write("box.stl", binaryStl(soup)));
  EXPECT_EQ(mesh.vertices().size(), 8u);
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_EQ(mesh.volume(), 30.0);
  expectBounds(mesh, Point3(0, 0, 0), Point3(2, 3, 5));
}

TEST(MeshReader, ReadsPlyQuads) {
  const Mesh mesh = loadMesh(kMeshes + "box.ply");
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_EQ(mesh.volume(), 6.0);
  expectBounds(mesh, Point3(0, 0, 0), Point3(1, 2, 3));
}

TEST(MeshReader, ReadsOffQuads) {
  const Mesh mesh = loadMesh(kMeshes + "box.off");
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_EQ(mesh.volume(), 2.0);
  expectBounds(mesh, Point3(0, 0, 0), Point3(4, 1, 0.5));
}

// A prism over a non-convex 12-gon (a comb of area 8), its caps single faces: the import
// library's own OFF reader drops faces of more than 9 vertices. (Its triangulation of
// the caps puts vertices on edges, the aligned tooth corners: the repair splits those.)
TEST(MeshReader, ReadsOffFacesOfAnySize) {
  const std::vector<std::pair<int, int>> comb = {{0, 0}, {5, 0}, {5, 2}, {4, 2}, {4, 1}, {3, 1},
                                                 {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const int n = static_cast<int>(comb.size());
  std::string text = "OFF\n" + std::to_string(2 * n) + " " + std::to_string(n + 2) + " 0\n";
  for (int z = 0; z < 2; ++z) {
    for (const auto& [x, y] : comb) text += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  }
  std::string bottom = std::to_string(n), top = std::to_string(n);
  for (int i = 0; i < n; ++i) {
    bottom += " " + std::to_string(n - 1 - i);
    top += " " + std::to_string(n + i);
  }
  text += bottom + "\n" + top + "\n";
  for (int i = 0; i < n; ++i) {
    const int next = (i + 1) % n;
    text += "4 " + std::to_string(i) + " " + std::to_string(next) + " " + std::to_string(n + next) + " " +
            std::to_string(n + i) + "\n";
  }
  const testing::TempDir directory;
  std::vector<std::string> warnings;
  const Mesh mesh = loadMesh(directory.write("comb.off", text), &warnings);
  EXPECT_EQ(mesh.volume(), 8.0);
  // Dropped caps would be closed again by the repair, with this warning.
  for (const std::string& warning : warnings) EXPECT_EQ(warning.find("openings"), std::string::npos) << warning;
  expectBounds(mesh, Point3(0, 0, 0), Point3(5, 2, 1));
}

// The import library's JoinIdenticalVertices merges distinct points of a model a few
// millionths across (the bundled keyhole's environment at 2^-20 lost 3 of its 32
// points): the triangles are read without it.
TEST(MeshReader, ReadsATinyModelAsTheSameSolid) {
  const std::string path = std::string(FREESPACE_SOURCE_DIR) + "/benchmarks/problems/keyhole_world.obj";
  const Mesh ordinary = loadMesh(path);
  std::ifstream in(path);
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) == 0) {
      std::istringstream words(line.substr(2));
      double x, y, z;
      words >> x >> y >> z;
      char written[128];
      std::snprintf(written, sizeof written, "v %.17g %.17g %.17g", std::ldexp(x, -20), std::ldexp(y, -20),
                    std::ldexp(z, -20));
      line = written;
    }
    text += line + "\n";
  }
  const testing::TempDir directory;
  const Mesh tiny = loadMesh(directory.write("tiny.obj", text));
  EXPECT_EQ(tiny.vertices().size(), ordinary.vertices().size());
  EXPECT_EQ(tiny.triangles().size(), ordinary.triangles().size());
  EXPECT_EQ(tiny.volume(), std::ldexp(ordinary.volume(), -60));
}

TEST(MeshReader, AppliesNestedColladaNodeTransformsFromTheRoot) {
  // translate (10, 20, 30) applied after the inner node's scale by 2.
  const Mesh mesh = loadMesh(kMeshes + "cube_nested_transform.dae");
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_EQ(mesh.volume(), 8.0);
  expectBounds(mesh, Point3(10, 20, 30), Point3(12, 22, 32));
}

TEST(MeshReader, TurnsZUpColladaFilesYUpLikeOmplApp) {
  // Box [0,1]x[0,2]x[0,3] in the file; assimp maps (x, y, z) to (x, z, -y).
  const Mesh mesh = loadMesh(kMeshes + "box_z_up.dae");
  EXPECT_EQ(mesh.volume(), 6.0);
  expectBounds(mesh, Point3(0, 0, -2), Point3(1, 3, 0));
}

TEST(MeshReader, ExtensionsAreCaseInsensitive) {
  std::ifstream original(kMeshes + "cube.obj");
  const std::string content{std::istreambuf_iterator<char>(original), std::istreambuf_iterator<char>()};
  const testing::TempDir directory;
  EXPECT_EQ(loadMesh(directory.write("CUBE.OBJ", content)).volume(), 1.0);
}

// ---------------------------------------------------------------------------
// Legacy VTK

TEST(VtkReader, KeepsPointNumberingAndTriangulatesPolygonsAsFans) {
  const TriangleSoup soup = readTriangleSoup(kMeshes + "cube_quads.vtk");
  ASSERT_EQ(soup.vertices.size(), 8u);
  EXPECT_EQ(soup.vertices[6], Point3(1, 1, 1));
  ASSERT_EQ(soup.triangles.size(), 12u);  // VERTICES and LINES give none
  EXPECT_EQ(soup.triangles[0], (TriangleIndices{0, 3, 2}));
  EXPECT_EQ(soup.triangles[1], (TriangleIndices{0, 2, 1}));
  const Mesh mesh = loadMesh(kMeshes + "cube_quads.vtk");
  EXPECT_EQ(mesh.vertices(), soup.vertices);
  EXPECT_EQ(mesh.volume(), 1.0);
}

TEST(VtkReader, ReadsTheVersion5OffsetsLayoutAndSkipsMetadata) {
  const Mesh mesh = loadMesh(kMeshes + "cube_v51.vtk");
  EXPECT_EQ(mesh.vertices().size(), 8u);
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_EQ(mesh.volume(), 1.0);
  expectBounds(mesh, Point3(10, 0, 0), Point3(11, 1, 1));
}

TEST(VtkReader, SplitsTriangleStripsKeepingTheirOrientation) {
  const TriangleSoup soup = readTriangleSoup(kMeshes + "tetra_strip.vtk");
  const std::vector<TriangleIndices> expected = {{0, 1, 2}, {2, 1, 3}, {2, 3, 0}, {0, 3, 1}};
  EXPECT_EQ(soup.triangles, expected);
  std::vector<std::string> warnings;
  EXPECT_DOUBLE_EQ(loadMesh(kMeshes + "tetra_strip.vtk", &warnings).volume(), 1.0 / 6);
  EXPECT_EQ(warnings.size(), 1u);  // the strip's first triangle faces inward
}

const std::string kTetrahedronPolygons =
    "POLYGONS 4 16\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";

TEST(VtkReader, ReadsFullDoublePrecisionAndWindowsLineEnds) {
  const std::string text =
      "# vtk DataFile Version 2.0\r\ntetrahedron\r\nascii\r\nDATASET POLYDATA\r\n"
      "POINTS 4 double\r\n0.1 0.2 0.3\r\n1.0000000000000002 0 0\r\n0 1e-300 1\r\n"
      "-0 0 1e300\r\n" "POLYGONS 4 16\r\n3 0 2 1\r\n3 0 1 3\r\n3 1 2 3\r\n3 2 0 3\r\n";
  const testing::TempDir directory;
  const TriangleSoup soup = readTriangleSoup(directory.write("precise.vtk", text));
  ASSERT_EQ(soup.vertices.size(), 4u);
  EXPECT_EQ(soup.vertices[0], Point3(0.1, 0.2, 0.3));
  EXPECT_EQ(soup.vertices[1].x(), 1.0000000000000002);
  EXPECT_EQ(soup.vertices[2].y(), 1e-300);
  EXPECT_EQ(soup.vertices[3].z(), 1e300);
  EXPECT_EQ(soup.triangles.size(), 4u);
}

TEST(VtkReader, SkipsFieldDataBeforeThePoints) {
  const std::string text =
      "# vtk DataFile Version 3.0\nwith field data\nASCII\nDATASET POLYDATA\n"
      "FIELD FieldData 2\ntime 1 1 double\n3.5\nlabels 2 2 int\n1 2\n3 4\n"
      "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n" +
      kTetrahedronPolygons + "CELL_DATA 4\nSCALARS id int\nLOOKUP_TABLE default\n0 1 2 3\n";
  const testing::TempDir directory;
  EXPECT_DOUBLE_EQ(loadMesh(directory.write("field.vtk", text)).volume(), 1.0 / 6);
}

TEST(VtkReader, ReportsMalformedSectionsWithTheirLine) {
  const std::string header = "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET POLYDATA\n";
  const std::string points = "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n";
  const testing::TempDir directory;
  const auto problem = [&](const std::string& body) {
    return loadProblem(directory.write("bad.vtk", header + body));
  };
  EXPECT_EQ(problem("POINTS 4 float\n0 0 0 1 0 zero 0 1 0 0 0 1\n"),
            "line 6: expected a number, found 'zero'");
  EXPECT_EQ(problem("POINTS 4\n0 0 0 1 0 0 0 1 0 0 0 1\n"), "line 6: unknown data type '0'");
  EXPECT_EQ(problem(kTetrahedronPolygons + points), "line 5: POLYGONS before POINTS (point indices need them)");
  EXPECT_EQ(problem(points + "POLYGONS 1 3\n2 0 1\n"),
            "line 8: polygons need at least 3 points, found one with 2");
  EXPECT_EQ(problem(points + "POLYGONS 2 8\n3 0 1 2\n"),
            "line 7: expected 2 polygons, file ended after 1");
  EXPECT_EQ(problem(points + "POLYGONS 1 4\n3 0 1 -2\n"),
            "line 8: expected a point index, found '-2'");
  EXPECT_EQ(problem(points + "SPHERES 1\n"),
            "line 7: unexpected 'SPHERES' (expected POINTS, POLYGONS, TRIANGLE_STRIPS, VERTICES, "
            "LINES, FIELD, METADATA, POINT_DATA or CELL_DATA)");
  EXPECT_EQ(problem(points + "POLYGONS 2 8\nOFFSETS int\n0 3\nCONNECTIVITY int\n0 1 2\n"),
            "line 7: the last offset must be the connectivity size 8");
  EXPECT_EQ(problem(points + "POLYGONS 2 3\nOFFSETS int\n0 3\nCONNECTIVITY int\n0 1 7\n"),
            "line 11: point index 7 out of range (4 points)");
  EXPECT_EQ(loadProblem(directory.write("short.vtk", "# vtk DataFile Version 3.0\ntitle\n")),
            "line 2: file ended before line 3, which must say ASCII or BINARY");
}

// ---------------------------------------------------------------------------
// Malformed files

struct MalformedFile {
  const char* name;
  const char* problem;  // a substring of the InputError's problem
};

// The table at the top of this file.
const MalformedFile kMalformedFiles[] = {
    {"bad_truncated.obj", "OBJ line 13: a face with 2 vertices (at least 3 needed)"},
    {"bad_nonmanifold.obj", "1 triangle encloses nothing"},
    {"bad_zero_area.obj", "2 triangles enclose nothing"},
    {"bad_flat.obj", "4 triangles enclose nothing"},
    {"bad_nan.obj", "a vertex at (0, 0, nan) as read: coordinates must be finite"},
    {"bad_no_triangles.obj", "contains no triangles"},
    {"bad_index.obj", "cannot read mesh: OBJ: vertex index out of range"},
    {"bad_empty.obj", "file is empty"},
    {"bad_garbage.stl", "cannot read mesh:"},
    {"bad_garbage.ply", "PLY header line 1: expected 'ply'"},
    {"bad_format.xyz", "unsupported mesh format '.xyz' (expected obj, stl, ply, off, dae or vtk)"},
    {"bad_truncated.vtk", "line 5: expected 24 point coordinates, file ended after 13"},
    {"bad_nan.vtk", "vertex 3 has a non-finite coordinate (nan)"},
    {"bad_index.vtk", "line 20: point index 9 out of range (8 points)"},
    {"bad_polygon_size.vtk", "line 14: POLYGONS announces 31 numbers, but its 6 polygons hold 30"},
    {"bad_binary.vtk", "binary VTK is not supported"},
    {"bad_dataset.vtk", "line 4: not a POLYDATA dataset (found UNSTRUCTURED_GRID)"},
    {"bad_header.vtk", "not a legacy VTK file"},
    {"bad_truncated.off", "OFF file is truncated: it promises 8 vertices and 6 faces in 86 bytes"},
    {"bad_nan.off", "a vertex at (4, nan, 0) as read: coordinates must be finite"},
    {"bad_truncated.ply", "PLY file is truncated"},
    {"bad_truncated.dae", "COLLADA file is not well-formed XML at byte 842: Start-end tags mismatch"},
};

class MalformedMeshFile : public ::testing::TestWithParam<MalformedFile> {};

// Files the old checks refused that repair and interpretation now read as the unit
// cube (or the 2 x 2 x 2 box) they show, each reporting what it changed.
TEST(MeshReader, RepairableFilesLoadAsTheSolidsTheyShow) {
  const struct {
    const char* name;
    double volume;
    const char* change;
  } files[] = {
      {"repairable_missing_face.obj", 1, "triangles added to close planar openings"},
      {"repairable_orientation.obj", 1, "2 triangles of closed components turned to face outward"},
      {"repairable_duplicate.obj", 1, "1 duplicate triangle dropped"},
      {"repairable_missing_triangle.stl", 8, "1 triangle added to close planar openings"},
  };
  for (const auto& file : files) {
    std::vector<std::string> warnings;
    const Mesh mesh = loadMesh(kMeshes + file.name, &warnings);
    EXPECT_DOUBLE_EQ(mesh.volume(), file.volume) << file.name;
    EXPECT_EQ(mesh.componentCount(), 1u) << file.name;
    EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(),
                            [&](const std::string& warning) { return warning.find(file.change) != std::string::npos; }))
        << file.name;
  }
}

TEST_P(MalformedMeshFile, IsRejectedWithItsMessage) {
  const std::string path = kMeshes + GetParam().name;
  ASSERT_TRUE(fs::exists(path)) << path;
  EXPECT_TRUE(contains(loadProblem(path), GetParam().problem));
}

std::string fileTestName(const ::testing::TestParamInfo<MalformedFile>& info) {
  std::string name = info.param.name;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(MeshReader, MalformedMeshFile, ::testing::ValuesIn(kMalformedFiles),
                         fileTestName);

TEST(MeshReader, EveryBadFileIsInTheTable) {
  for (const auto& entry : fs::directory_iterator(kMeshes)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("bad_", 0) != 0) continue;
    const bool listed = std::any_of(std::begin(kMalformedFiles), std::end(kMalformedFiles),
                                    [&](const MalformedFile& file) { return name == file.name; });
    EXPECT_TRUE(listed) << name;
  }
}

TEST(MeshReader, ReportsAMissingFile) {
  EXPECT_TRUE(contains(loadProblem(kMeshes + "no_such_file.obj"), "cannot open file"));
}

TEST(MeshReader, ReportsADirectory) {
  EXPECT_TRUE(contains(loadProblem(kMeshes), "cannot open file: it is a directory"));
}

TEST(MeshReader, ReportsAFileWithoutExtension) {
  const testing::TempDir directory;
  EXPECT_EQ(loadProblem(directory.write("mesh", "v 0 0 0\n")),
            "unsupported mesh format: the file name has no extension "
            "(expected obj, stl, ply, off, dae or vtk)");
}

}  // namespace
}  // namespace freespace
