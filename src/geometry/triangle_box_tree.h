#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "freespace/geometry/mesh.h"

namespace freespace::detail {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using TreePoint = bg::model::point<double, 3, bg::cs::cartesian>;
using TreeBox = bg::model::box<TreePoint>;
using TreeEntry = std::pair<TreeBox, std::uint32_t>;  // box, triangle
/// An R-tree (Boost.Geometry) of the bounding boxes of a mesh's triangles, for the
/// pairs of triangles that may meet.
using TriangleTree = bgi::rtree<TreeEntry, bgi::rstar<16>>;

inline TreeBox treeBox(const Box3& box) {
  return {TreePoint(box.min().x(), box.min().y(), box.min().z()),
          TreePoint(box.max().x(), box.max().y(), box.max().z())};
}

inline TreeBox triangleBox(const std::vector<Point3>& vertices, const TriangleIndices& triangle) {
  Box3 box;
  for (std::uint32_t vertex : triangle) box.extend(vertices[vertex]);
  return treeBox(box);
}

inline TriangleTree triangleTree(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles) {
  std::vector<TreeEntry> entries;
  entries.reserve(triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t) entries.emplace_back(triangleBox(vertices, triangles[t]), t);
  return TriangleTree(entries.begin(), entries.end());  // bulk loading
}

}  // namespace freespace::detail
