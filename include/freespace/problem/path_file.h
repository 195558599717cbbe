#pragma once

#include <string>
#include <vector>

#include "freespace/problem/planar_problem.h"

namespace freespace {

/// Reads an OMPL.app path file (".path", as OMPL's PathGeometric::printAsMatrix
/// writes it for SE(2)): one configuration "X Y THETA" per line. Blank lines are
/// skipped and '#' starts a comment that runs to the end of its line. Throws
/// InputError naming the file and the line of the first defect (a missing or extra
/// field, a number that is not finite).
std::vector<Pose2> readPath(const std::string& path);

/// Writes configurations one per line, each number in the shortest form that reads
/// back as the same double. Refuses (InputError) to replace an existing file unless
/// `overwrite`; the file appears only once complete.
void writePath(const std::vector<Pose2>& poses, const std::string& path, bool overwrite = false);

}  // namespace freespace
