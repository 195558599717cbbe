#include "freespace/geometry/patch_geometry.h"

#include <algorithm>
#include <cmath>

#include "angle_bounds.h"

namespace freespace {

std::vector<PatchGeometry> patchGeometries(const std::vector<Patch>& patches, const Mesh& robot,
                                           const MeshTopology& robotTopology, const Mesh& world,
                                           const MeshTopology& worldTopology, PredicateStatistics& statistics) {
  std::vector<PatchGeometry> geometries;
  geometries.reserve(patches.size());
  for (const Patch& patch : patches) {
    const PatchSegment segment = patchSegment(patch.contact, robot, robotTopology, world, worldTopology, statistics);
    geometries.push_back({patch, segment, contactPoints(patch.contact, robot, robotTopology, world, worldTopology),
                          {spiralPoints(segment.ends[0], robot, world), spiralPoints(segment.ends[1], robot, world)}});
  }
  return geometries;
}

namespace {

/// Padding of angles (radians) and, relative to the coordinates' size, of lengths:
/// far above the rounding of the double computations below.
constexpr double kAnglePadding = 1e-7;
constexpr double kRelativePadding = 1e-9;

struct XyBox {
  double low[2] = {HUGE_VAL, HUGE_VAL};
  double high[2] = {-HUGE_VAL, -HUGE_VAL};

  void add(double x, double y) {
    low[0] = std::min(low[0], x), low[1] = std::min(low[1], y);
    high[0] = std::max(high[0], x), high[1] = std::max(high[1], y);
  }
};

/// Adds the points u + R(theta) v for theta in [from, to] (to >= from): the circle
/// of radius |v| around u, between the arc's ends and through the axis extremes it
/// passes.
void addSpiralArc(const Spiral<double>& spiral, double from, double to, XyBox& box) {
  const double radius = std::hypot(spiral.vx, spiral.vy);
  const double phase = std::atan2(spiral.vy, spiral.vx);
  const auto addAt = [&](double angle) {
    box.add(spiral.ux + radius * std::cos(angle), spiral.uy + radius * std::sin(angle));
  };
  const double start = from + phase, end = to + phase;
  addAt(start);
  addAt(end);
  // Multiples of pi/2 inside [start, end] are where x or y is extreme.
  for (double quarter = std::ceil(start / M_PI_2); quarter * M_PI_2 <= end; quarter += 1) addAt(quarter * M_PI_2);
}

PatchBox boxOver(const PatchGeometry& patch, double from, double to) {
  XyBox xy;
  double size = 0;
  for (const SpiralPoints& end : patch.ends) {
    const Spiral<double> spiral = spiralOf<double>(end);
    addSpiralArc(spiral, from - kAnglePadding, to + kAnglePadding, xy);
    size = std::max({size, std::fabs(spiral.ux), std::fabs(spiral.uy), std::hypot(spiral.vx, spiral.vy)});
  }
  const double padding = kRelativePadding * (1 + size);
  return {{xy.low[0] - padding, xy.low[1] - padding, std::max(-M_PI, from - kAnglePadding)},
          {xy.high[0] + padding, xy.high[1] + padding, std::min(M_PI, to + kAnglePadding)}};
}

}  // namespace

std::vector<PatchBox> patchBoxes(const PatchGeometry& patch) {
  std::vector<PatchBox> boxes;
  for (const auto& [from, to] : detail::radianRanges(patch.patch.range)) boxes.push_back(boxOver(patch, from, to));
  return boxes;
}

}  // namespace freespace
