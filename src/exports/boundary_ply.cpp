#include "freespace/exports/boundary_ply.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace freespace {

namespace {

/// At most this many angles per slab, whatever the tolerance.
constexpr int kMostSteps = 4096;

struct Vertex {
  double x, y, z;
  std::uint32_t cell;
};

/// The piece of a patch's segment between two curves (or its ends), in doubles.
struct PieceSampler {
  const Arrangement& arrangement;
  std::uint32_t patch;
  const PatchSlab& slab;

  /// The ends of the piece at index `gap` at angle theta (in double intervals, for
  /// output only: their midpoints; inside a RoundingScope).
  std::array<std::array<double, 2>, 2> at(std::size_t gap, double theta) const {
    Interval c, s;
    HalfAngle::fromRadians(theta).cosSin(c, s);
    const PatchGeometry& geometry = arrangement.patches[patch];
    const std::array<Interval, 2> end0 = spiralPoint(spiralOf<Interval>(geometry.ends[0]), c, s);
    const std::array<Interval, 2> end1 = spiralPoint(spiralOf<Interval>(geometry.ends[1]), c, s);
    const auto middle = [](const Interval& value) { return 0.5 * (value.lower() + value.upper()); };
    const auto lambdaOf = [&](std::size_t index) {
      const PatchGeometry& other = arrangement.patches[arrangement.curves[slab.curves[index]].other(patch)];
      const LineAtAngle<Interval> line = lineAtAngle(lineOf<Interval>(other.line), c, s);
      const Interval v0 = line.nx * end0[0] + line.ny * end0[1] + line.w, v1 = line.nx * end1[0] + line.ny * end1[1] + line.w;
      const double m0 = middle(v0), difference = m0 - middle(v1);
      return difference == 0 ? 0.5 : std::clamp(m0 / difference, 0.0, 1.0);
    };
    const double low = gap == 0 ? 0.0 : lambdaOf(gap - 1), high = gap == slab.curves.size() ? 1.0 : lambdaOf(gap);
    const auto point = [&](double lambda) {
      const std::array<double, 2> a{middle(end0[0]), middle(end0[1])}, b{middle(end1[0]), middle(end1[1])};
      return std::array<double, 2>{a[0] + lambda * (b[0] - a[0]), a[1] + lambda * (b[1] - a[1])};
    };
    return {point(low), point(high)};
  }
};

/// The slab's angles in radians, increasing (a slab through theta = pi runs past
/// pi; a whole circle is one turn).
std::pair<double, double> anglesOf(const PatchSlab& slab) {
  double from = slab.from.radians(), to = slab.to.radians();
  if (to <= from) to += 2 * M_PI;
  return {from, to};
}

}  // namespace

void writeBoundaryPly(const FreeSpace& space, const BoundaryPlyOptions& options, std::ostream& out) {
  const Arrangement& arrangement = space.arrangement();
  // Written in the input's coordinates: the construction's are scaled (FreeSpace::meshes).
  const double scale = space.meshes().scale;
  // (A solid robot reaches beyond its centre; 1 guards a degenerate one.)
  const double farthest = space.meshes().robot.horizontalReach() / scale, reach = farthest > 0 ? farthest : 1;
  const Eigen::Vector2d worldSize = space.meshes().world.bounds().sizes().head<2>() / scale;
  const double tolerance = options.tolerance > 0 ? options.tolerance : 0.01 * worldSize.norm();
  // The end points run on circles of radius at most the robot's reach plus the
  // environment's size: a chord over dtheta is off by r dtheta^2 / 8.
  const double radius = reach + worldSize.norm();
  const double step = std::sqrt(8 * tolerance / radius);
  std::vector<Vertex> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    for (const PatchSlab& slab : arrangement.subdivisions[patch].slabs) {
      const auto [from, to] = anglesOf(slab);
      const int steps = static_cast<int>(std::clamp(std::ceil((to - from) / step), 1.0, double{kMostSteps}));
      const PieceSampler sampler{arrangement, patch, slab};
      for (std::size_t gap = 0; gap < slab.faces.size(); ++gap) {
        const std::optional<std::uint32_t> cell = space.cellOfSubFace({patch, slab.faces[gap]});
        if (!cell) continue;
        for (int i = 0; i <= steps; ++i) {
          // Just inside the slab: at its ends, curves may meet or end.
          const double t = static_cast<double>(i) / steps, theta = from + (to - from) * (1e-9 + t * (1 - 2e-9));
          std::array<std::array<double, 2>, 2> ends;
          {
            RoundingScope rounding;
            ends = sampler.at(gap, theta);
          }
          for (const std::array<double, 2>& p : ends) {
            vertices.push_back({p[0] / scale, p[1] / scale, reach * theta, *cell});
          }
          if (i == 0) continue;
          const auto n = static_cast<std::uint32_t>(vertices.size());
          triangles.push_back({n - 4, n - 3, n - 1});
          triangles.push_back({n - 4, n - 1, n - 2});
        }
      }
    }
  }
  static const std::array<std::array<int, 3>, 7> kColours{
      {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40}, {148, 103, 189}, {140, 86, 75}, {227, 119, 194}}};
  out.precision(17);
  out << "ply\nformat ascii 1.0\ncomment free space boundaries: x y (reach * theta), reach " << reach
      << "\nelement vertex " << vertices.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nproperty uchar green\n"
         "property uchar blue\nelement face "
      << triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vertex& v : vertices) {
    const std::array<int, 3>& colour = kColours[v.cell % kColours.size()];
    out << v.x << ' ' << v.y << ' ' << v.z << ' ' << colour[0] << ' ' << colour[1] << ' ' << colour[2] << '\n';
  }
  for (const auto& t : triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

}  // namespace freespace
