#include "freespace/geometry/patch_geometry.h"

#include <algorithm>
#include <cmath>

#include "angle_bounds.h"

namespace freespace {

std::vector<PatchGeometry> patchGeometries(const std::vector<Patch>& patches, const Mesh& robot,
                                           const MeshTopology& robotTopology, const Mesh& world,
                                           const MeshTopology& worldTopology, PredicateStatistics& statistics,
                                           const Cancellation& cancellation) {
  std::vector<PatchGeometry> geometries;
  geometries.reserve(patches.size());
  for (const Patch& patch : patches) {
    cancellation.check();
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

/// Calls piece(a, b) for the equal pieces [a, b] of [from, to] at most maxWidth
/// wide, in order (neighbours share the same double).
template <class Piece>
void forEachPiece(double from, double to, double maxWidth, const Piece& piece) {
  const double pieces = std::max(1.0, std::ceil((to - from) / maxWidth));
  const auto at = [&](double i) { return i == pieces ? to : from + (to - from) * (i / pieces); };
  for (double i = 0; i < pieces; ++i) piece(at(i), at(i + 1));
}

/// A patch end's spiral u + R(theta) v in doubles, with |v|.
struct SpiralCircle {
  Spiral<double> spiral;
  double radius;
};

/// The widest range of angles addSpiralPiece takes: below pi, so that a coordinate
/// of R(theta) v changes sign at most once over it.
constexpr double kWidestPiece = M_PI / 4;

/// Adds the points u + R(theta) v for theta between two angles at most kWidestPiece
/// apart (given with their cosines and sines): the ends, and the point where R v
/// points along an axis when the other coordinate of R v changes sign in between.
/// (Where a sign is misjudged by rounding, the axis is passed within rounding of an
/// end, and the end's point is that extreme to second order.)
void addSpiralPiece(const SpiralCircle& circle, const detail::RadianCosSin& from, const detail::RadianCosSin& to,
                    XyBox& box) {
  const Spiral<double>& s = circle.spiral;
  const auto rotated = [&s](const detail::RadianCosSin& at) {
    return std::array<double, 2>{at.cosine * s.vx - at.sine * s.vy, at.sine * s.vx + at.cosine * s.vy};
  };
  const std::array<double, 2> a = rotated(from), b = rotated(to);
  box.add(s.ux + a[0], s.uy + a[1]);
  box.add(s.ux + b[0], s.uy + b[1]);
  if (a[1] < 0 && b[1] > 0) box.add(s.ux + circle.radius, s.uy);
  if (a[1] > 0 && b[1] < 0) box.add(s.ux - circle.radius, s.uy);
  if (a[0] > 0 && b[0] < 0) box.add(s.ux, s.uy + circle.radius);
  if (a[0] < 0 && b[0] > 0) box.add(s.ux, s.uy - circle.radius);
}

/// The box of both ends' spirals over [from, to] (radians, from <= to), in pieces
/// at most kWidestPiece wide. The angles are padded by kAnglePadding through the
/// lengths: turning by it moves a point at most radius * kAnglePadding.
PatchBox boxOver(const std::array<SpiralCircle, 2>& ends, double from, double to) {
  XyBox xy;
  detail::RadianCosSin start = detail::RadianCosSin::at(from);
  forEachPiece(from, to, kWidestPiece, [&](double, double pieceEnd) {
    const detail::RadianCosSin end = detail::RadianCosSin::at(pieceEnd);
    for (const SpiralCircle& circle : ends) addSpiralPiece(circle, start, end, xy);
    start = end;
  });
  double size = 0, radius = 0;
  for (const SpiralCircle& circle : ends) {
    size = std::max({size, std::fabs(circle.spiral.ux), std::fabs(circle.spiral.uy), circle.radius});
    radius = std::max(radius, circle.radius);
  }
  const double padding = kRelativePadding * (1 + size) + kAnglePadding * radius;
  return {{xy.low[0] - padding, xy.low[1] - padding, std::max(-M_PI, from - kAnglePadding)},
          {xy.high[0] + padding, xy.high[1] + padding, std::min(M_PI, to + kAnglePadding)}};
}

}  // namespace

std::vector<PatchBox> patchBoxes(const PatchGeometry& patch, double maxWidth) {
  std::array<SpiralCircle, 2> ends;
  for (int k = 0; k < 2; ++k) {
    const Spiral<double> spiral = spiralOf<double>(patch.ends[k]);
    ends[k] = {spiral, std::hypot(spiral.vx, spiral.vy)};
  }
  std::vector<PatchBox> boxes;
  for (const auto& [from, to] : detail::radianRanges(patch.patch.range)) {
    forEachPiece(from, to, maxWidth, [&](double a, double b) { boxes.push_back(boxOver(ends, a, b)); });
  }
  return boxes;
}

}  // namespace freespace
