#pragma once

#include <ostream>

#include "freespace/space/free_space.h"

namespace freespace {

struct BoundaryPlyOptions {
  /// Largest distance (in x, y units) between the exported triangles and the
  /// surfaces they sample, from the chord of each end point's circle; 0 chooses 1%
  /// of the environment's size.
  double tolerance = 0;
};

/// The boundaries of the free cells as a triangle mesh in PLY (ASCII), with
/// vertices (x, y, r theta), r the robot's reach (the distance of its farthest
/// vertex from its reference point, so that turning by theta moves that vertex by
/// about r theta: x, y and theta in comparable units) and each vertex coloured by
/// its cell. Each sub-face that bounds a free cell is sampled slab by slab: between
/// consecutive angles its piece of segment spans a quadrilateral, two triangles.
void writeBoundaryPly(const FreeSpace& space, const BoundaryPlyOptions& options, std::ostream& out);

}  // namespace freespace
