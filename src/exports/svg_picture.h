#pragma once

#include <array>
#include <ostream>
#include <string>

#include "freespace/space/free_space.h"

namespace freespace::svg {

/// The part of the plane drawn, in the input's coordinates (the construction's are
/// scaled, FreeSpace::meshes): the environment's box with room for the robot around
/// it, cut into `columns` x `rows` square pixels.
struct View {
  double left, bottom, width, height;
  int columns, rows;
};
View viewOf(const FreeSpace& space, int resolution);

/// The picture's frame in pixels: the plot between margins for the title and the
/// axes' labels, and the legend on the right.
struct Frame {
  double left = 70, top = 40, plotWidth = 0, plotHeight = 0, legendWidth = 230, bottom = 50;
  double width() const { return left + plotWidth + legendWidth; }
  double height() const { return top + plotHeight + bottom; }
};

/// The picture's start: the SVG element, its title (also written above the plot), a
/// white background, and a group drawing in the input's (x, y), y up, that the
/// caller closes.
void openPicture(const Frame& frame, const View& view, const std::string& title, std::ostream& out);

/// The axes below and left of the plot, with ticks labelled in the input's units.
void writeAxes(const View& view, const Frame& frame, std::ostream& out);

/// The robot's triangles seen from above, placed at (x, y) turned by theta.
void writeRobot(const FreeSpace& space, const std::array<double, 2>& at, double theta, const std::string& fill,
                double opacity, std::ostream& out);

}  // namespace freespace::svg
