#pragma once

#include <optional>
#include <ostream>

#include "freespace/space/free_space.h"

namespace freespace {

struct SliceSvgOptions {
  /// The slice's angle (radians).
  double theta = 0;
  /// Where to draw the robot's outline (at the slice's angle), if anywhere.
  std::optional<std::array<double, 2>> robotAt;
  /// Pixels across the wider side of the picture.
  int resolution = 240;
};

/// The slice of the free space at one angle as SVG, in (x, y) with y up: every
/// pixel located (blocked dark grey, free tinted by cell), the sub-faces' pieces of
/// segment on top (those that bound a free cell in the cell's colour, the others
/// thin grey), each face labelled with its node of the cell graph, and the robot's
/// outline at a point; with a title (the angle and the number of free cells), axes
/// ticked in the meshes' units, and a legend.
void writeSliceSvg(const FreeSpace& space, const SliceSvgOptions& options, std::ostream& out);

}  // namespace freespace
