#pragma once

// Small meshes built in tests.

#include "freespace/geometry/mesh.h"

namespace freespace::testing {

/// Axis-aligned box, outward oriented.
inline TriangleSoup boxSoup(const Point3& low, const Point3& high) {
  TriangleSoup soup;
  for (int i = 0; i < 8; ++i) {
    soup.vertices.emplace_back(i & 1 ? high.x() : low.x(), i & 2 ? high.y() : low.y(), i & 4 ? high.z() : low.z());
  }
  soup.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return soup;
}

inline Mesh boxMesh(const Point3& low, const Point3& high) { return Mesh::fromSoup(boxSoup(low, high), "box"); }

/// Tetrahedron on four points in any order (an inside-out result is flipped by
/// Mesh::fromSoup). Throws InputError for a flat one.
inline Mesh tetrahedronMesh(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  TriangleSoup soup;
  soup.vertices = {a, b, c, d};
  soup.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return Mesh::fromSoup(soup, "tetrahedron");
}

/// A mesh with every coordinate multiplied by `factor`.
inline Mesh scaled(const Mesh& mesh, double factor) {
  TriangleSoup soup{{}, mesh.triangles()};
  for (const Point3& p : mesh.vertices()) soup.vertices.push_back(p * factor);
  return Mesh::fromSoup(soup, "scaled");
}

/// Several soups as one mesh with several components.
inline TriangleSoup joinSoups(const std::vector<TriangleSoup>& parts) {
  TriangleSoup joined;
  for (const TriangleSoup& part : parts) {
    const auto offset = static_cast<std::uint32_t>(joined.vertices.size());
    joined.vertices.insert(joined.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const TriangleIndices& t : part.triangles) joined.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  return joined;
}

}  // namespace freespace::testing
