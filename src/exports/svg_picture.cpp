#include "svg_picture.h"

#include <algorithm>
#include <cmath>

namespace freespace::svg {

namespace {

/// Steps of 1, 2 or 5 times a power of ten, about `count` of them across `span`.
double tickStep(double span, int count) {
  const double rough = span / count, power = std::pow(10, std::floor(std::log10(rough)));
  for (const double factor : {1.0, 2.0, 5.0}) {
    if (factor * power >= rough) return factor * power;
  }
  return 10 * power;
}

}  // namespace

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

void openPicture(const Frame& frame, const View& view, const std::string& title, std::ostream& out) {
  const double perUnit = frame.plotWidth / view.width;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << frame.width() << "\" height=\"" << frame.height()
      << "\" viewBox=\"0 0 " << frame.width() << " " << frame.height() << "\">\n"
      << "<title>" << title << "</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
      << "<text x=\"" << frame.left << "\" y=\"24\" font-family=\"sans-serif\" font-size=\"16\">" << title
      << "</text>\n"
      << "<g transform=\"translate(" << frame.left << "," << frame.top + frame.plotHeight << ") scale(" << perUnit
      << "," << -perUnit << ") translate(" << -view.left << "," << -view.bottom << ")\">\n";
}

void writeAxes(const View& view, const Frame& frame, std::ostream& out) {
  const double perUnit = frame.plotWidth / view.width;
  const auto pixelX = [&](double x) { return frame.left + (x - view.left) * perUnit; };
  const auto pixelY = [&](double y) { return frame.top + frame.plotHeight - (y - view.bottom) * perUnit; };
  const double step = tickStep(std::max(view.width, view.height), 6), base = frame.top + frame.plotHeight;
  out << "<g font-family=\"sans-serif\" font-size=\"12\" stroke=\"#000000\">\n"
      << "<rect x=\"" << frame.left << "\" y=\"" << frame.top << "\" width=\"" << frame.plotWidth << "\" height=\""
      << frame.plotHeight << "\" fill=\"none\"/>\n";
  for (double x = std::ceil(view.left / step) * step; x <= view.left + view.width; x += step) {
    out << "<line x1=\"" << pixelX(x) << "\" y1=\"" << base << "\" x2=\"" << pixelX(x) << "\" y2=\"" << base + 5
        << "\"/><text x=\"" << pixelX(x) << "\" y=\"" << base + 18 << "\" text-anchor=\"middle\" stroke=\"none\">"
        << (std::fabs(x) < step / 2 ? 0 : x) << "</text>\n";
  }
  for (double y = std::ceil(view.bottom / step) * step; y <= view.bottom + view.height; y += step) {
    out << "<line x1=\"" << frame.left - 5 << "\" y1=\"" << pixelY(y) << "\" x2=\"" << frame.left << "\" y2=\""
        << pixelY(y) << "\"/><text x=\"" << frame.left - 8 << "\" y=\"" << pixelY(y) + 4
        << "\" text-anchor=\"end\" stroke=\"none\">" << (std::fabs(y) < step / 2 ? 0 : y) << "</text>\n";
  }
  out << "<text x=\"" << frame.left + frame.plotWidth / 2 << "\" y=\"" << base + 40
      << "\" text-anchor=\"middle\" stroke=\"none\">x (the meshes' units)</text>\n"
      << "<text transform=\"translate(" << 18 << "," << frame.top + frame.plotHeight / 2
      << ") rotate(-90)\" text-anchor=\"middle\" stroke=\"none\">y (the meshes' units)</text>\n</g>\n";
}

void writeRobot(const FreeSpace& space, const std::array<double, 2>& at, double theta, const std::string& fill,
                double opacity, std::ostream& out) {
  const Mesh& robot = space.meshes().robot;
  const double c = std::cos(theta), s = std::sin(theta), scale = space.meshes().scale;
  out << "<g fill=\"" << fill << "\" fill-opacity=\"" << opacity << "\" stroke=\"none\">\n";
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

}  // namespace freespace::svg
