#include "freespace/exports/slice_svg.h"

#include "freespace/topology/slice_pieces.h"

#include <algorithm>
#include <cmath>

namespace freespace {

namespace {

/// A colour per cell (cell 0, the unbounded one, first), darker for boundaries.
std::string cellColour(std::uint32_t cell, bool dark) {
  static const char* const kLight[] = {"#e8f1fb", "#fde9d4", "#dff3df", "#f8dede", "#ece3f5", "#f3eadf", "#fbe4f2"};
  static const char* const kDark[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2"};
  return (dark ? kDark : kLight)[cell % 7];
}

struct View {
  double left, bottom, width, height;
  int columns, rows;
};

// Drawn in the input's coordinates: the construction's are scaled (FreeSpace::meshes).
View viewOf(const FreeSpace& space, int resolution) {
  const double scale = space.meshes().scale;
  const Box3 world = space.meshes().world.bounds();
  const double reach = space.meshes().robot.bounds().sizes().head<2>().norm() / scale;
  const Eigen::Vector2d low = world.min().head<2>() / scale, size = world.sizes().head<2>() / scale;
  View view{low.x() - reach, low.y() - reach, size.x() + 2 * reach, size.y() + 2 * reach, 0, 0};
  const double pixel = std::max(view.width, view.height) / resolution;
  view.columns = std::max(1, static_cast<int>(std::ceil(view.width / pixel)));
  view.rows = std::max(1, static_cast<int>(std::ceil(view.height / pixel)));
  return view;
}

/// The pixels, run by run along each row.
void writePixels(const FreeSpace& space, const View& view, double theta, std::ostream& out) {
  const double pixelWidth = view.width / view.columns, pixelHeight = view.height / view.rows;
  out << "<g shape-rendering=\"crispEdges\">\n";
  for (int row = 0; row < view.rows; ++row) {
    const double y = view.bottom + (row + 0.5) * pixelHeight;
    std::string runColour;
    int runStart = 0;
    for (int column = 0; column <= view.columns; ++column) {
      std::string colour;
      if (column < view.columns) {
        const Location location = space.locate({view.left + (column + 0.5) * pixelWidth, y, theta});
        colour = location.free ? cellColour(location.cell, false) : "#555555";
      }
      if (colour == runColour) continue;
      if (!runColour.empty()) {
        out << "<rect x=\"" << view.left + runStart * pixelWidth << "\" y=\"" << view.bottom + row * pixelHeight
            << "\" width=\"" << (column - runStart) * pixelWidth << "\" height=\"" << pixelHeight << "\" fill=\""
            << runColour << "\"/>\n";
      }
      runColour = colour;
      runStart = column;
    }
  }
  out << "</g>\n";
}

/// The pieces of segment of every sub-face active at the angle.
void writePieces(const FreeSpace& space, double theta, double strokeWidth, std::ostream& out) {
  const Arrangement& arrangement = space.arrangement();
  AngleAlgebra& algebra = space.algebra();
  const AlgebraicAngle angle = AlgebraicAngle::rational(HalfAngle::fromRadians(theta));
  const auto [cosine, sine] = exactCosSin(angle);
  const double scale = space.meshes().scale;
  const auto toDouble = [scale](const std::array<Rational, 2>& p) {
    return std::array<double, 2>{p[0].convert_to<double>() / scale, p[1].convert_to<double>() / scale};
  };
  out << "<g stroke-linecap=\"round\">\n";
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    if (!algebra.contains(arrangement.patches[patch].patch.range, angle)) continue;
    const PatchSlab* slab = slabAt(arrangement.subdivisions[patch], angle, algebra);
    if (!slab) continue;  // the angle is an event of the patch
    const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[patch], cosine, sine);
    for (std::size_t gap = 0; gap < slab->faces.size(); ++gap) {
      const auto [low, high] = slices::pieceOf(arrangement, patch, *slab, gap, segment, cosine, sine);
      const std::array<double, 2> a = toDouble(segment.at(low)), b = toDouble(segment.at(high));
      const std::optional<std::uint32_t> cell = space.cellOfSubFace({patch, slab->faces[gap]});
      out << "<line x1=\"" << a[0] << "\" y1=\"" << a[1] << "\" x2=\"" << b[0] << "\" y2=\"" << b[1] << "\" stroke=\""
          << (cell ? cellColour(*cell, true) : std::string("#aaaaaa")) << "\" stroke-width=\""
          << (cell ? 2 : 0.6) * strokeWidth << "\"/>\n";
    }
  }
  out << "</g>\n";
}

/// The robot's triangles seen from above, placed at (x, y) turned by theta.
void writeRobot(const FreeSpace& space, const std::array<double, 2>& at, double theta, std::ostream& out) {
  const Mesh& robot = space.meshes().robot;
  const double c = std::cos(theta), s = std::sin(theta), scale = space.meshes().scale;
  out << "<g fill=\"#000000\" fill-opacity=\"0.35\" stroke=\"none\">\n";
  for (const TriangleIndices& triangle : robot.triangles()) {
    out << "<polygon points=\"";
    for (std::uint32_t vertex : triangle) {
      const Point3 p = robot.vertices()[vertex] / scale;
      out << at[0] + c * p.x() - s * p.y() << "," << at[1] + s * p.x() + c * p.y() << " ";
    }
    out << "\"/>\n";
  }
  out << "</g>\n";
}

}  // namespace

void writeSliceSvg(const FreeSpace& space, const SliceSvgOptions& options, std::ostream& out) {
  const View view = viewOf(space, options.resolution);
  const double pixel = view.width / view.columns;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 3 * view.columns << "\" height=\"" << 3 * view.rows
      << "\" viewBox=\"" << view.left << " " << -(view.bottom + view.height) << " " << view.width << " " << view.height
      << "\">\n"
      << "<title>free space slice at theta = " << options.theta << " (" << space.cellCount() << " free cells)</title>\n"
      << "<g transform=\"scale(1,-1)\">\n";
  writePixels(space, view, options.theta, out);
  writePieces(space, options.theta, pixel / 3, out);
  if (options.robotAt) writeRobot(space, *options.robotAt, options.theta, out);
  out << "</g>\n</svg>\n";
}

}  // namespace freespace
