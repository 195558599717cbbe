// Triangle soups as modelling tools export them, built from the generator's
// primitives.

#include "freespace/scenes/soup_variants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "polygon_triangulation.h"
#include "seeded_random.h"

namespace freespace {
namespace {

/// The soup without the triangles whose three corners lie in `region` (a closed
/// box, possibly flat: a face or a strip of one).
TriangleSoup withoutTrianglesIn(const TriangleSoup& soup, const Box3& region) {
  TriangleSoup kept{soup.vertices, {}};
  for (const TriangleIndices& t : soup.triangles) {
    const bool inside =
        std::all_of(t.begin(), t.end(), [&](std::uint32_t v) { return region.contains(soup.vertices[v]); });
    if (!inside) kept.triangles.push_back(t);
  }
  return kept;
}

Box3 faceOf(const Box3& box, BoxFace face) {
  const int axis = static_cast<int>(face) / 2;
  const bool lowSide = static_cast<int>(face) % 2 == 0;
  Point3 low = box.min();
  Point3 high = box.max();
  if (lowSide) {
    high[axis] = low[axis];
  } else {
    low[axis] = high[axis];
  }
  return Box3(low, high);
}

/// A coordinate as a float file holds it after a transform: see withFloatNoise.
double noisyCoordinate(double value, unsigned ulps, detail::SeededRandom& random) {
  const float rounded = static_cast<float>(value);
  const int exponent = std::ilogb(std::max(std::abs(rounded), 1.0f));
  const double step = std::ldexp(1.0, exponent - (std::numeric_limits<float>::digits - 1));
  const auto steps = static_cast<double>(random.integer(-static_cast<std::int64_t>(ulps), ulps));
  return static_cast<float>(rounded + steps * step);
}

}  // namespace

TriangleSoup doubleSided(const TriangleSoup& soup) {
  TriangleSoup doubled{soup.vertices, {}};
  doubled.triangles.reserve(2 * soup.triangles.size());
  for (const TriangleIndices& t : soup.triangles) {
    doubled.triangles.push_back(t);
    doubled.triangles.push_back({t[0], t[2], t[1]});
  }
  return doubled;
}

TriangleSoup withFloatNoise(const TriangleSoup& soup, std::uint64_t seed, unsigned ulps) {
  detail::SeededRandom random(seed);
  TriangleSoup noisy = soup;
  for (Point3& v : noisy.vertices) {
    for (int k = 0; k < 3; ++k) v[k] = noisyCoordinate(v[k], ulps, random);
  }
  return noisy;
}

TriangleSoup gluedPrisms(const Polygon2& outline, double z0, double z1) {
  const Polygon2 corners = detail::counterClockwise(outline);
  std::vector<TriangleSoup> prisms;
  for (const TriangleIndices& t : detail::triangulateRegion(corners, {})) {
    prisms.push_back(extrudePolygon({corners[t[0]], corners[t[1]], corners[t[2]]}, z0, z1));
  }
  return joinParts(prisms);
}

TriangleSoup openBox(const Box3& box, const std::vector<BoxFace>& missing) {
  TriangleSoup soup = makeBox(box);
  for (BoxFace face : missing) soup = withoutTrianglesIn(soup, faceOf(box, face));
  return soup;
}

TriangleSoup tJunctionWall(const Box3& longBox, double split, double depth) {
  const Point3& low = longBox.min();
  const Point3& high = longBox.max();
  if (!(low.x() < split && split < high.x() && depth > 0)) {
    throw std::invalid_argument("T-junction wall: the split must lie inside the long box and the depth be positive");
  }
  const Box3 west(Point3(low.x(), high.y(), low.z()), Point3(split, high.y() + depth, high.z()));
  const Box3 east(Point3(split, high.y(), low.z()), Point3(high.x(), high.y() + depth, high.z()));
  return joinParts({openBox(longBox, {BoxFace::north}), openBox(west, {BoxFace::south, BoxFace::east}),
                    openBox(east, {BoxFace::south, BoxFace::west})});
}

TriangleSoup wallWithBuriedEnds(const Box3& wall) {
  const bool alongX = wall.sizes().x() >= wall.sizes().y();
  return openBox(wall, alongX ? std::vector<BoxFace>{BoxFace::west, BoxFace::east}
                              : std::vector<BoxFace>{BoxFace::south, BoxFace::north});
}

TriangleSoup touchingBoxes(const Box3& box, Contact contact) {
  const Point3 size = box.sizes();
  Point3 offset(size.x(), 0, 0);
  if (contact != Contact::face) offset.y() = size.y();
  if (contact == Contact::edge) offset.z() = size.z() / 2;
  if (contact == Contact::vertex) offset.z() = size.z();
  return joinParts({makeBox(box), makeBox(box.translated(offset))});
}

TriangleSoup openSheetBesideBox(const Box3& box) {
  const Point3& low = box.min();
  const Point3& high = box.max();
  const double x = high.x() + box.sizes().x();
  TriangleSoup sheet;
  sheet.vertices = {{x, low.y(), low.z()}, {x, high.y(), low.z()}, {x, high.y(), high.z()}, {x, low.y(), high.z()}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
  return joinParts({makeBox(box), doubleSided(sheet)});
}

TriangleSoup tornSeamBox(const Box3& box, double gap) {
  const Point3& low = box.min();
  const Point3& high = box.max();
  if (!(gap > 0 && gap < box.sizes().x() && gap < box.sizes().z())) {
    throw std::invalid_argument("torn seam: the gap must be positive and narrower than the box");
  }
  // Side view (x, z): the box's outline with corners where the two faces stop short
  // of the seam; the end faces keep the whole outline.
  const Polygon2 profile{{low.x(), low.z()},   {high.x(), low.z()},        {high.x(), high.z() - gap},
                         {high.x(), high.z()}, {high.x() - gap, high.z()}, {low.x(), high.z()}};
  const TriangleSoup whole = extrudeProfileXZ(profile, low.y(), high.y());
  const Box3 eastStrip(Point3(high.x(), low.y(), high.z() - gap), high);
  const Box3 topStrip(Point3(high.x() - gap, low.y(), high.z()), high);
  return withoutTrianglesIn(withoutTrianglesIn(whole, eastStrip), topStrip);
}

SoupRobot doubleSidedRobot(const Mesh& robot) {
  return {doubleSided(TriangleSoup{robot.vertices(), robot.triangles()}), robot};
}

}  // namespace freespace
