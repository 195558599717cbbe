// Closed triangle surfaces from polygons: prisms, side profiles, boxes, unions of
// rectangles.

#include <stdexcept>
#include <utility>

#include "freespace/scenes/scene_generator.h"
#include "polygon_triangulation.h"
#include "rectangle_union.h"

namespace freespace {
namespace {

void checkPolygon(const Polygon2& polygon) {
  if (polygon.size() < 3 || detail::twiceSignedArea(polygon) == 0) {
    throw std::invalid_argument("extrusion: a polygon needs three corners and a non-zero area");
  }
}

}  // namespace

TriangleSoup extrudeRegion(const PolygonWithHoles& region, double z0, double z1) {
  if (!(z0 < z1)) throw std::invalid_argument("extrusion: z0 must be below z1");
  checkPolygon(region.outer);
  std::vector<Polygon2> boundaries{detail::counterClockwise(region.outer)};
  for (const Polygon2& hole : region.holes) {
    checkPolygon(hole);
    boundaries.push_back(detail::clockwise(hole));
  }

  // Corner k of the concatenated boundaries becomes vertex 2k (bottom) and 2k + 1 (top).
  TriangleSoup soup;
  std::uint32_t first = 0;
  for (const Polygon2& boundary : boundaries) {
    const auto n = static_cast<std::uint32_t>(boundary.size());
    for (const Point2& corner : boundary) {
      soup.vertices.emplace_back(corner.x(), corner.y(), z0);
      soup.vertices.emplace_back(corner.x(), corner.y(), z1);
    }
    // Each boundary runs with the solid on its left, so a side quad from corner a
    // to corner b faces right (outwards) when listed bottom a, bottom b, top b, top a.
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t a = first + k;
      const std::uint32_t b = first + (k + 1) % n;
      soup.triangles.push_back({2 * a, 2 * b, 2 * b + 1});
      soup.triangles.push_back({2 * a, 2 * b + 1, 2 * a + 1});
    }
    first += n;
  }
  const std::vector<Polygon2> holes(boundaries.begin() + 1, boundaries.end());
  for (const TriangleIndices& t : detail::triangulateRegion(boundaries.front(), holes)) {
    soup.triangles.push_back({2 * t[0] + 1, 2 * t[1] + 1, 2 * t[2] + 1});  // top, facing +z
    soup.triangles.push_back({2 * t[0], 2 * t[2], 2 * t[1]});              // bottom, facing -z
  }
  return soup;
}

TriangleSoup extrudePolygon(const Polygon2& outline, double z0, double z1) {
  return extrudeRegion({outline, {}}, z0, z1);
}

TriangleSoup extrudeProfileXZ(const Polygon2& profile, double y0, double y1) {
  // Extrude in (x, y) and swap y with z. The swap is a reflection, so every
  // triangle is reversed to stay outward.
  TriangleSoup soup = extrudePolygon(profile, y0, y1);
  for (Point3& v : soup.vertices) std::swap(v.y(), v.z());
  for (TriangleIndices& t : soup.triangles) std::swap(t[1], t[2]);
  return soup;
}

TriangleSoup makeBox(const Box3& box) {
  const Point3& lo = box.min();
  const Point3& hi = box.max();
  return extrudePolygon({{lo.x(), lo.y()}, {hi.x(), lo.y()}, {hi.x(), hi.y()}, {lo.x(), hi.y()}}, lo.z(), hi.z());
}

TriangleSoup extrudeRectangleUnion(const std::vector<Box2>& rectangles, double z0, double z1) {
  std::vector<TriangleSoup> pieces;
  for (const PolygonWithHoles& region : detail::rectangleUnionRegions(rectangles)) {
    pieces.push_back(extrudeRegion(region, z0, z1));
  }
  return joinParts(pieces);
}

TriangleSoup joinParts(const std::vector<TriangleSoup>& parts) {
  TriangleSoup joined;
  for (const TriangleSoup& part : parts) {
    const auto offset = static_cast<std::uint32_t>(joined.vertices.size());
    joined.vertices.insert(joined.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const TriangleIndices& t : part.triangles) {
      joined.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
  }
  return joined;
}

TriangleSoup translateSoup(const TriangleSoup& soup, const Point3& offset) {
  TriangleSoup moved = soup;
  for (Point3& v : moved.vertices) v += offset;
  return moved;
}

Mesh makeCheckedMesh(const TriangleSoup& soup, const std::string& name) {
  std::vector<std::string> warnings;
  Mesh mesh = Mesh::fromSoup(soup, name, &warnings);
  if (!warnings.empty()) throw std::logic_error("generated mesh " + name + " needed a repair: " + warnings.front());
  return mesh;
}

}  // namespace freespace
