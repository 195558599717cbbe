#include <gtest/gtest.h>

#include "freespace/input_error.h"
#include "freespace/problem/path_file.h"
#include "temp_dir.h"

using namespace freespace;
using freespace::testing::TempDir;

namespace {

std::string errorOf(const std::string& path) {
  try {
    readPath(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(PathFile, ReadsOmplAppPathsWithCommentsAndBlankLines) {
  TempDir dir;
  dir.write("p.path", "0.01 -0.15 0.0\n\n# a comment line\n  0.322686\t1.60768 0.0937888  # trailing comment\n"
                      "-1e-3 2.5E2 -3.141592653589793\r\n");
  const std::vector<Pose2> poses = readPath(dir.file("p.path"));
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_EQ(poses[0].x, 0.01);
  EXPECT_EQ(poses[0].y, -0.15);
  EXPECT_EQ(poses[1].y, 1.60768);
  EXPECT_EQ(poses[1].theta, 0.0937888);
  EXPECT_EQ(poses[2].x, -1e-3);
  EXPECT_EQ(poses[2].y, 250);
  EXPECT_EQ(poses[2].theta, -3.141592653589793);
}

TEST(PathFile, WriteThenReadGivesTheSameDoubles) {
  TempDir dir;
  const std::vector<Pose2> poses{{0.1, -0.2, 0.3}, {1e-300, 123456789.123456789, -3.141592653589793}, {0, 0, 0}};
  writePath(poses, dir.file("out.path"));
  const std::vector<Pose2> back = readPath(dir.file("out.path"));
  ASSERT_EQ(back.size(), poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_EQ(back[i].x, poses[i].x);
    EXPECT_EQ(back[i].y, poses[i].y);
    EXPECT_EQ(back[i].theta, poses[i].theta);
  }
  EXPECT_THROW(writePath(poses, dir.file("out.path")), InputError) << "nothing the user had is overwritten";
  EXPECT_NO_THROW(writePath({}, dir.file("out.path"), true));
  EXPECT_TRUE(readPath(dir.file("out.path")).empty());
}

TEST(PathFile, BadLinesAreErrorsNamingTheLine) {
  TempDir dir;
  dir.write("two.path", "0 0 0\n1 2\n");
  EXPECT_EQ(errorOf(dir.file("two.path")), dir.file("two.path") + ": line 2: expected three finite numbers X Y THETA");
  dir.write("four.path", "0 0 0 0\n");
  EXPECT_EQ(errorOf(dir.file("four.path")), dir.file("four.path") + ": line 1: expected three finite numbers X Y THETA");
  dir.write("inf.path", "# header\n0 inf 0\n");
  EXPECT_EQ(errorOf(dir.file("inf.path")), dir.file("inf.path") + ": line 2: expected three finite numbers X Y THETA");
  dir.write("word.path", "0 0 abc\n");
  EXPECT_EQ(errorOf(dir.file("word.path")), dir.file("word.path") + ": line 1: expected three finite numbers X Y THETA");
  EXPECT_EQ(errorOf(dir.file("missing.path")), dir.file("missing.path") + ": cannot open file");
  EXPECT_EQ(errorOf(dir.file("")), dir.file("") + ": cannot open file: it is a directory");
}
