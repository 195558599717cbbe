#include "freespace/exports/slice_svg.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "freespace/topology/slice_pieces.h"
#include "svg_picture.h"

namespace freespace {

namespace {

/// A colour per cell (cell 0, the unbounded one, first), darker for boundaries.
std::string cellColour(std::uint32_t cell, bool dark) {
  static const char* const kLight[] = {"#e8f1fb", "#fde9d4", "#dff3df", "#f8dede", "#ece3f5", "#f3eadf", "#fbe4f2"};
  static const char* const kDark[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2"};
  return (dark ? kDark : kLight)[cell % 7];
}

const std::string kBlocked = "#555555", kOtherPiece = "#aaaaaa";
// The robot's outline: black, seen through.
const std::string kRobotFill = "#000000";
constexpr double kRobotOpacity = 0.35;

using svg::Frame;
using svg::View;

/// What the pixels met: the free cells, and for each node of the cell graph the
/// centres of its pixels.
struct PixelsMet {
  std::set<std::uint32_t> cells;
  std::map<std::uint32_t, std::vector<std::array<double, 2>>> nodes;
};

/// The pixels, run by run along each row.
PixelsMet writePixels(const FreeSpace& space, const View& view, double theta, std::ostream& out) {
  PixelsMet met;
  const double pixelWidth = view.width / view.columns, pixelHeight = view.height / view.rows;
  out << "<g shape-rendering=\"crispEdges\">\n";
  for (int row = 0; row < view.rows; ++row) {
    const double y = view.bottom + (row + 0.5) * pixelHeight;
    std::string runColour;
    int runStart = 0;
    for (int column = 0; column <= view.columns; ++column) {
      std::string colour;
      if (column < view.columns) {
        const Pose2 pose{view.left + (column + 0.5) * pixelWidth, y, theta};
        const NodeLocation located = space.locateNode(pose);
        const Location& location = located.location;
        colour = location.free ? cellColour(location.cell, false) : kBlocked;
        if (location.free) met.cells.insert(location.cell);
        if (located.node) met.nodes[*located.node].push_back({pose.x, pose.y});
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
  return met;
}

/// Each node's label at the pixel of its face nearest the face's centre of pixels,
/// in picture coordinates (`toPicture`).
void writeNodeLabels(const PixelsMet& met,
                     const std::function<std::array<double, 2>(const std::array<double, 2>&)>& toPicture,
                     std::ostream& out) {
  out << "<g font-family=\"sans-serif\" font-size=\"11\" text-anchor=\"middle\" stroke=\"#ffffff\" "
         "stroke-width=\"3\" paint-order=\"stroke\">\n";
  for (const auto& [node, pixels] : met.nodes) {
    std::array<double, 2> centre{0, 0};
    for (const auto& p : pixels) centre = {centre[0] + p[0] / pixels.size(), centre[1] + p[1] / pixels.size()};
    const auto nearest = std::min_element(pixels.begin(), pixels.end(), [&](const auto& a, const auto& b) {
      return std::hypot(a[0] - centre[0], a[1] - centre[1]) < std::hypot(b[0] - centre[0], b[1] - centre[1]);
    });
    const std::array<double, 2> at = toPicture(*nearest);
    out << "<text x=\"" << at[0] << "\" y=\"" << at[1] << "\">node " << node << "</text>\n";
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
    return std::array<double, 2>{nearDouble(p[0]) / scale, nearDouble(p[1]) / scale};
  };
  out << "<g stroke-linecap=\"round\">\n";
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    if (!algebra.contains(arrangement.patches[patch].patch.range, angle)) continue;
    const PatchSlab* slab = slabAt(arrangement.subdivisions[patch], angle, algebra);
    if (!slab) continue;  // the angle is an event of the patch
    const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[patch], cosine, sine);
    for (std::size_t gap = 0; gap < slab->faces.size(); ++gap) {
      const auto [low, high] = slices::pieceOf(arrangement, patch, *slab, gap, segment, cosine, sine).value();
      const std::array<double, 2> a = toDouble(segment.at(low)), b = toDouble(segment.at(high));
      const std::optional<std::uint32_t> cell = space.cellOfSubFace({patch, slab->faces[gap]});
      out << "<line x1=\"" << a[0] << "\" y1=\"" << a[1] << "\" x2=\"" << b[0] << "\" y2=\"" << b[1] << "\" stroke=\""
          << (cell ? cellColour(*cell, true) : kOtherPiece) << "\" stroke-width=\"" << (cell ? 2 : 0.6) * strokeWidth
          << "\"/>\n";
    }
  }
  out << "</g>\n";
}

/// What the colours and lines mean: blocked, each free cell met, the boundary
/// pieces, the robot.
void writeLegend(const Frame& frame, const std::set<std::uint32_t>& cells, bool robot, std::ostream& out) {
  double y = frame.top + 10;
  const double x = frame.left + frame.plotWidth + 20;
  out << "<g font-family=\"sans-serif\" font-size=\"12\">\n";
  const auto swatch = [&](const std::string& fill, const std::string& label, double opacity = 1) {
    out << "<rect x=\"" << x << "\" y=\"" << y - 10 << "\" width=\"14\" height=\"12\" fill=\"" << fill
        << "\" fill-opacity=\"" << opacity << "\" stroke=\"#000000\" stroke-width=\"0.5\"/><text x=\"" << x + 22
        << "\" y=\"" << y << "\">" << label << "</text>\n";
    y += 20;
  };
  const auto line = [&](const std::string& stroke, double width, const std::string& label) {
    out << "<line x1=\"" << x << "\" y1=\"" << y - 4 << "\" x2=\"" << x + 14 << "\" y2=\"" << y - 4 << "\" stroke=\""
        << stroke << "\" stroke-width=\"" << width << "\"/><text x=\"" << x + 22 << "\" y=\"" << y << "\">" << label
        << "</text>\n";
    y += 20;
  };
  swatch(kBlocked, "blocked (robot touches or overlaps)");
  for (std::uint32_t cell : cells) {
    swatch(cellColour(cell, false), "free, cell " + std::to_string(cell) + (cell == 0 ? " (unbounded)" : ""));
  }
  for (std::uint32_t cell : cells) line(cellColour(cell, true), 3, "boundary of cell " + std::to_string(cell));
  line(kOtherPiece, 1, "other contact pieces");
  out << "<text x=\"" << x << "\" y=\"" << y << "\">node N: a face of the cell graph's node N</text>\n";
  y += 20;
  if (robot) swatch(kRobotFill, "the robot at the point given", kRobotOpacity);
  out << "</g>\n";
}

}  // namespace

void writeSliceSvg(const FreeSpace& space, const SliceSvgOptions& options, std::ostream& out) {
  const View view = svg::viewOf(space, options.resolution);
  const double pixel = view.width / view.columns;
  Frame frame;
  frame.plotWidth = 3 * view.columns;  // three picture pixels per located pixel
  const double perUnit = frame.plotWidth / view.width;
  frame.plotHeight = perUnit * view.height;
  std::ostringstream title;
  title << "Free space slice at theta = " << options.theta << " rad (" << options.theta * 180 / M_PI << " degrees), "
        << space.cellCount() << " free cells";
  svg::openPicture(frame, view, title.str(), out);
  const PixelsMet met = writePixels(space, view, options.theta, out);
  writePieces(space, options.theta, pixel / 3, out);
  if (options.robotAt) svg::writeRobot(space, *options.robotAt, options.theta, kRobotFill, kRobotOpacity, out);
  out << "</g>\n";
  writeNodeLabels(
      met,
      [&](const std::array<double, 2>& p) {
        return std::array<double, 2>{frame.left + (p[0] - view.left) * perUnit,
                                     frame.top + frame.plotHeight - (p[1] - view.bottom) * perUnit};
      },
      out);
  svg::writeAxes(view, frame, out);
  writeLegend(frame, met.cells, options.robotAt.has_value(), out);
  out << "</svg>\n";
}

}  // namespace freespace
