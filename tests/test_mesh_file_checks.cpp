// Mesh files are checked against their own headers before the import library reads
// them: every prefix of a valid PLY (ASCII and binary) and OFF file, and every
// single-byte edit of a binary PLY, either loads or is an InputError naming the file;
// none crashes, hangs or exhausts memory (a crash fails the whole test program).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>

#include "freespace/input_error.h"
#include "freespace/io/mesh_reader.h"
#include "freespace/io/mesh_writer.h"
#include "freespace/scenes/scene_generator.h"
#include "temp_dir.h"

using namespace freespace;
using freespace::testing::TempDir;

namespace {

std::string fileContent(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A tetrahedron as a binary PLY of the given byte order (float coordinates, uchar
// counts, int indices).
std::string binaryTetrahedronPly(bool bigEndian) {
  const float vertices[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::int32_t faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string content = std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                        " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                        "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const auto append = [&](const void* value, std::size_t size) {
    char bytes[8];
    std::memcpy(bytes, value, size);
    if (bigEndian) std::reverse(bytes, bytes + size);  // the machine is little endian
    content.append(bytes, size);
  };
  for (const auto& vertex : vertices) {
    for (float coordinate : vertex) append(&coordinate, 4);
  }
  for (const auto& face : faces) {
    content.push_back(3);
    for (std::int32_t index : face) append(&index, 4);
  }
  return content;
}

// Loads `content` as a file of the given name: true if it loads, false if refused
// with an InputError naming the file.
bool loadsOrIsRefused(const TempDir& dir, const std::string& name, const std::string& content) {
  const std::string path = dir.write(name, content);
  try {
    readTriangleSoup(path);
    return true;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    return false;
  }
}

std::string problemOf(const TempDir& dir, const std::string& name, const std::string& content) {
  try {
    readTriangleSoup(dir.write(name, content));
  } catch (const InputError& error) {
    return error.problem();
  }
  return "";
}

}  // namespace

TEST(MeshFileChecks, EveryPrefixOfAValidFileLoadsOrIsRefused) {
  const TempDir dir;
  const Mesh world = makeScene("keyhole").world;
  for (const char* extension : {"ply", "off", "obj", "dae"}) {
    const std::string whole = dir.file(std::string("world.") + extension);
    writeMesh(world, whole);
    const std::string content = fileContent(whole);
    int loaded = 0;
    for (std::size_t length = 0; length < content.size(); ++length) {
      loaded += loadsOrIsRefused(dir, std::string("prefix.") + extension, content.substr(0, length));
    }
    EXPECT_TRUE(loadsOrIsRefused(dir, std::string("prefix.") + extension, content)) << extension;
    // PLY and OFF give their counts: only prefixes that end inside the last record's
    // final number can still pass. An OBJ file cut short is a smaller valid file.
    if (std::string(extension) != "obj") {
      EXPECT_LT(loaded, 40) << extension;
    }
  }
  for (bool bigEndian : {false, true}) {
    const std::string content = binaryTetrahedronPly(bigEndian);
    for (std::size_t length = 0; length < content.size(); ++length) {
      EXPECT_FALSE(loadsOrIsRefused(dir, "prefix.ply", content.substr(0, length))) << length;
    }
    EXPECT_EQ(readTriangleSoup(dir.write("tetrahedron.ply", content)).triangles.size(), 4u);
  }
}

TEST(MeshFileChecks, EverySingleByteEditOfABinaryPlyLoadsOrIsRefused) {
  const TempDir dir;
  const std::string content = binaryTetrahedronPly(false);
  for (std::size_t at = 0; at < content.size(); ++at) {
    for (unsigned char value : {0x00, 0x7f, 0x80, 0xff}) {
      std::string edited = content;
      edited[at] = static_cast<char>(value);
      loadsOrIsRefused(dir, "edited.ply", edited);
    }
  }
}

TEST(MeshFileChecks, CountsBeyondTheFileAreRefusedAtOnce) {
  const TempDir dir;
  EXPECT_EQ(problemOf(dir, "huge.off", "OFF\n1000000000 1 0\n0 0 0\n"),
            "OFF file is truncated: it promises 1000000000 vertices and 1 faces in 25 bytes");
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_NE(problemOf(dir, "huge.ply", header + "0 0 0\n").find("PLY file is truncated"), std::string::npos);
  EXPECT_EQ(problemOf(dir, "cut.ply", header.substr(0, 60)), "PLY header line 4: unexpected 'property floa'");
  EXPECT_EQ(problemOf(dir, "unended.ply", header.substr(0, header.size() - 11)), "PLY header has no end_header line");
}

TEST(MeshFileChecks, FacesWithFewerThanThreeVerticesAreRefused) {
  const TempDir dir;
  const std::string tetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  EXPECT_EQ(problemOf(dir, "line.obj", tetrahedron + "f 1 2\n"), "OBJ line 9: a face with 2 vertices (at least 3 needed)");
  EXPECT_EQ(problemOf(dir, "point.obj", tetrahedron + "f 1\n"), "OBJ line 9: a face with 1 vertices (at least 3 needed)");
  EXPECT_EQ(problemOf(dir, "tetrahedron.obj", tetrahedron + "l 1 2\n"), "") << "a line element is no face";
  EXPECT_EQ(problemOf(dir, "line.off", "OFF\n4 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n2 0 1\n"),
            "face 4 has 2 vertices (at least 3 needed)");
  EXPECT_EQ(problemOf(dir, "line.ply",
                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"),
            "face 0 has 2 vertices (at least 3 needed)");
  EXPECT_EQ(problemOf(dir, "index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
            "face 0 uses vertex 7 of 3 (out of range)");
}

TEST(MeshFileChecks, HostileColladaIsRefusedNamingTheDefect) {
  const TempDir dir;
  const std::string whole = dir.file("world.dae");
  writeMesh(makeScene("keyhole").world, whole);
  const std::string content = fileContent(whole);
  ASSERT_EQ(problemOf(dir, "valid.dae", content), "");
  const auto edited = [&](const std::string& find, const std::string& replacement) {
    const std::size_t at = content.find(find);
    EXPECT_NE(at, std::string::npos) << find;
    return content.substr(0, at) + replacement + content.substr(at + find.size());
  };
  std::string deep;
  for (int i = 0; i < 10000; ++i) deep += "<node>";
  for (int i = 0; i < 10000; ++i) deep += "</node>";
  EXPECT_EQ(problemOf(dir, "deep.dae", edited("</visual_scene>", deep + "</visual_scene>")),
            "COLLADA elements nested deeper than 256 (<node>)");
  EXPECT_EQ(problemOf(dir, "loop.dae", edited("</visual_scene>", "<node id=\"a\"><node id=\"b\"><instance_node url=\"#a\"/>"
                                                                  "</node></node></visual_scene>")),
            "COLLADA <node id=\"a\">: instances itself (through <instance_node>)");
  // A second source of the same id, without an array (the import library crashed).
  const std::size_t source = content.find("<source id=\"");
  ASSERT_NE(source, std::string::npos);
  const std::string sourceId = content.substr(source + 12, content.find('"', source + 12) - source - 12);
  EXPECT_EQ(problemOf(dir, "twice.dae", edited("</mesh>", "<source id=\"" + sourceId + "\"/></mesh>")),
            "COLLADA <source id=\"" + sourceId + "\">: its id names other data too (ids must be unique)");
  const std::size_t count = content.find("count=\"", content.find("<float_array"));
  ASSERT_NE(count, std::string::npos);
  const std::string huge = content.substr(0, count) + "count=\"1000000000" + content.substr(content.find('"', count + 7));
  EXPECT_NE(problemOf(dir, "count.dae", huge).find("count=\"1000000000\" but"), std::string::npos);
  EXPECT_NE(problemOf(dir, "junk.dae", edited("<p>", "<p>99999999999999 ")).find("holds something other than indices"),
            std::string::npos);
  EXPECT_NE(problemOf(dir, "words.dae", edited("<p>", "<p>x ")).find("holds something other than indices"),
            std::string::npos);
  // A coordinate the import library would read as another number (hexadecimal: 0).
  const std::size_t first = content.find_first_not_of(" \n", content.find('>', content.find("<float_array")) + 1);
  const std::string hexadecimal =
      content.substr(0, first) + "0x1p2" + content.substr(content.find_first_of(" <", first));
  EXPECT_NE(problemOf(dir, "hexadecimal.dae", hexadecimal).find("'0x1p2' is not a decimal number"), std::string::npos)
      << problemOf(dir, "hexadecimal.dae", hexadecimal);
}

TEST(MeshFileChecks, CoordinatesBeyondSinglePrecisionAreReportedAsRead) {
  const TempDir dir;
  const std::string faces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  EXPECT_EQ(problemOf(dir, "big.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1e39\n" + faces),
            "a vertex at (0, 0, inf) as read: coordinates must be finite and within single precision's range (about "
            "3.4e38), in which the file is read");
  EXPECT_NE(problemOf(dir, "inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 -inf\n" + faces).find("(0, 0, -inf) as read"),
            std::string::npos);
}

// The import library reads ASCII PLY and OFF a record per line: a PLY record split over
// lines or sharing one is refused, and an OFF file with blank lines and comments among
// its records loads as the same file without them (its own reader took a line holding
// a space for a face, and crashed on such a file; found by fuzzing).
TEST(MeshFileChecks, RecordsAreReadOnePerLine) {
  const TempDir dir;
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  EXPECT_EQ(problemOf(dir, "whole.ply", header + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces), "");
  EXPECT_EQ(problemOf(dir, "split.ply", header + "0 0\n0 1 0 0\n0 1 0\n0 0 1\n" + faces),
            "PLY line 10: vertex 0 has fewer values than its properties (records are one per line)");
  EXPECT_EQ(problemOf(dir, "shared.ply", header + "0 0 0 1 0 0\n0 1 0\n0 0 1\n" + faces + "3 0 1 2\n"),
            "PLY line 10: vertex 0 has more values than its properties (records are one per line)");
  // Numbers in the syntax the import library reads: it takes "+3" for 0.
  EXPECT_EQ(problemOf(dir, "plus.ply", header + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n+3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"),
            "PLY line 14: face 0: '+3' is not a whole number");
  EXPECT_EQ(problemOf(dir, "hex.off", "OFF\n4 4 0\n0x1p0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces),
            "OFF line 3: vertex 0 is not three numbers");
  const std::string off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces;
  const std::string spaced = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n \n \n3 0 1 3 # a comment\n"
                             "# a line of its own\n3 0 3 2\n\t\n3 1 2 3\n";
  const TriangleSoup plain = readTriangleSoup(dir.write("plain.off", off));
  const TriangleSoup blanks = readTriangleSoup(dir.write("blanks.off", spaced));
  EXPECT_EQ(blanks.vertices, plain.vertices);
  EXPECT_EQ(blanks.triangles, plain.triangles);
  EXPECT_EQ(plain.triangles.size(), 4u);
}
