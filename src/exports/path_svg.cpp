#include "freespace/exports/path_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "freespace/space/motion_checker.h"
#include "svg_picture.h"

namespace freespace {

namespace {

const std::string kTouchable = "#555555", kOutOfReach = "#cccccc", kStart = "#1f77b4", kGoal = "#9467bd";
constexpr double kOutlineOpacity = 0.45;
/// About this many robot outlines along a path.
constexpr int kOutlines = 60;

/// From red (0) through yellow to green (1).
std::string clearanceColour(double fraction) {
  const double f = std::clamp(fraction, 0.0, 1.0);
  const int red = static_cast<int>(std::lround(255 * std::min(1.0, 2 * (1 - f))));
  const int green = static_cast<int>(std::lround(200 * std::min(1.0, 2 * f)));
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x00", red, green);
  return text;
}

/// The environment's triangles seen from above: those whose heights meet the robot's
/// dark, the others light.
void writeFootprint(const FreeSpace& space, std::ostream& out) {
  const Mesh &world = space.meshes().world, &robot = space.meshes().robot;
  const double scale = space.meshes().scale, low = robot.bounds().min().z(), high = robot.bounds().max().z();
  for (const bool touchable : {false, true}) {
    out << "<g fill=\"" << (touchable ? kTouchable : kOutOfReach) << "\" stroke=\"none\">\n";
    for (const TriangleIndices& triangle : world.triangles()) {
      double bottom = HUGE_VAL, top = -HUGE_VAL;
      for (std::uint32_t vertex : triangle) {
        bottom = std::min(bottom, world.vertices()[vertex].z());
        top = std::max(top, world.vertices()[vertex].z());
      }
      if ((top >= low && bottom <= high) != touchable) continue;
      out << "<polygon points=\"";
      for (std::uint32_t vertex : triangle) {
        out << world.vertices()[vertex].x() / scale << "," << world.vertices()[vertex].y() / scale << " ";
      }
      out << "\"/>\n";
    }
    out << "</g>\n";
  }
}

/// The robot's outline at about kOutlines configurations spread along the path by
/// length, coloured by their clearance relative to `reference`.
void writeOutlines(const FreeSpace& space, const MaxClearancePath& path, double reference, std::ostream& out) {
  // Each motion's length in |dxy| + |dtheta|.
  std::vector<double> lengths;
  for (std::size_t k = 0; k + 1 < path.waypoints.size(); ++k) {
    const Pose2 &from = path.waypoints[k], &to = path.waypoints[k + 1];
    lengths.push_back(std::hypot(to.x - from.x, to.y - from.y) +
                      std::fabs(MotionChecker::shorterTurn(from.theta, to.theta)));
  }
  double total = 0;
  for (double length : lengths) total += length;
  const double spacing = std::max(total / kOutlines, 1e-12);
  for (std::size_t k = 0; k < lengths.size(); ++k) {
    const int steps = std::max(1, static_cast<int>(std::ceil(lengths[k] / spacing)));
    for (int step = 0; step < steps; ++step) {
      const Pose2 pose =
          MotionChecker::interpolate(path.waypoints[k], path.waypoints[k + 1], static_cast<double>(step) / steps);
      const double clearance = space.clearance(pose).lower;
      svg::writeRobot(space, {pose.x, pose.y}, pose.theta, clearanceColour(clearance / reference), kOutlineOpacity,
                      out);
    }
  }
}

void writeLegend(const svg::Frame& frame, double reference, std::ostream& out) {
  double y = frame.top + 10;
  const double x = frame.left + frame.plotWidth + 20;
  out << "<g font-family=\"sans-serif\" font-size=\"12\">\n";
  const auto swatch = [&](const std::string& fill, const std::string& label) {
    out << "<rect x=\"" << x << "\" y=\"" << y - 10 << "\" width=\"14\" height=\"12\" fill=\"" << fill
        << "\" stroke=\"#000000\" stroke-width=\"0.5\"/><text x=\"" << x + 22 << "\" y=\"" << y << "\">" << label
        << "</text>\n";
    y += 20;
  };
  swatch(kTouchable, "environment the robot can touch");
  swatch(kOutOfReach, "environment above or below it");
  swatch(kStart, "the robot at the start");
  swatch(kGoal, "the robot at the goal");
  out << "<line x1=\"" << x << "\" y1=\"" << y - 4 << "\" x2=\"" << x + 14 << "\" y2=\"" << y - 4
      << "\" stroke=\"#000000\" stroke-width=\"1.5\"/><text x=\"" << x + 22 << "\" y=\"" << y
      << "\">the path (x, y)</text>\n";
  y += 28;
  out << "<text x=\"" << x << "\" y=\"" << y << "\">the robot along it, by clearance:</text>\n";
  y += 8;
  for (int i = 0; i <= 10; ++i) {
    out << "<rect x=\"" << x + 18 * i << "\" y=\"" << y << "\" width=\"18\" height=\"12\" fill=\""
        << clearanceColour(i / 10.0) << "\"/>\n";
  }
  std::ostringstream high;
  high << reference;
  out << "<text x=\"" << x << "\" y=\"" << y + 26 << "\">0</text><text x=\"" << x + 198 << "\" y=\"" << y + 26
      << "\" text-anchor=\"end\">" << high.str() << "</text>\n</g>\n";
}

std::string titleOf(const MaxClearancePath& path) {
  std::ostringstream title;
  switch (path.status) {
    case PathStatus::solved:
      title << "Path: clearance " << path.passage.lower << " certified, at most " << path.passage.upper
            << " on any path; " << path.waypoints.size() << " waypoints";
      break;
    case PathStatus::infeasible:
      title << "No path: " << path.proof;
      break;
    default:
      title << "No path certified within the time limit";
  }
  return title.str();
}

}  // namespace

void writePathSvg(const FreeSpace& space, const Pose2& start, const Pose2& goal, const MaxClearancePath& path,
                  std::ostream& out) {
  const svg::View view = svg::viewOf(space, 240);
  svg::Frame frame;
  frame.plotWidth = 720;
  frame.legendWidth = 260;
  const double perUnit = frame.plotWidth / view.width;
  frame.plotHeight = perUnit * view.height;
  svg::openPicture(frame, view, titleOf(path), out);
  writeFootprint(space, out);
  // Colours relative to the bound on any path's clearance (or the path's own).
  const double reference = std::isfinite(path.passage.upper) && path.passage.upper > 0
                               ? path.passage.upper
                               : std::max(path.startClearance, path.goalClearance);
  if (path.status == PathStatus::solved) writeOutlines(space, path, reference, out);
  svg::writeRobot(space, {start.x, start.y}, start.theta, kStart, 0.8, out);
  svg::writeRobot(space, {goal.x, goal.y}, goal.theta, kGoal, 0.8, out);
  if (path.status == PathStatus::solved) {
    out << "<polyline fill=\"none\" stroke=\"#000000\" stroke-width=\"" << 1.5 / perUnit << "\" points=\"";
    for (const Pose2& pose : path.waypoints) out << pose.x << "," << pose.y << " ";
    out << "\"/>\n";
  }
  out << "</g>\n";
  svg::writeAxes(view, frame, out);
  writeLegend(frame, reference, out);
  out << "</svg>\n";
}

}  // namespace freespace
