#pragma once

// The sides of a triangle mesh's edges, sorted so that each edge's uses are one run;
// used by the checks of Mesh::fromSoup and by the solid interpretation.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "freespace/geometry/mesh.h"

namespace freespace::detail {

/// One side of an undirected edge within a group of triangles (a component; 0 for
/// all when groups do not matter): the triangle and the direction it runs along it.
struct EdgeUse {
  std::uint32_t group;
  std::uint32_t low;  // the edge's vertices, low < high
  std::uint32_t high;
  std::uint32_t triangle;
  bool lowToHigh;
};

/// Edge uses sorted by group, edge and triangle; `groupOf` gives each triangle's
/// group, or is empty for one group.
inline std::vector<EdgeUse> sortedEdgeUses(const std::vector<TriangleIndices>& triangles,
                                           const std::vector<std::uint32_t>& groupOf = {}) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const std::uint32_t group = groupOf.empty() ? 0 : groupOf[t];
    for (int corner = 0; corner < 3; ++corner) {
      const std::uint32_t from = triangles[t][corner], to = triangles[t][(corner + 1) % 3];
      uses.push_back({group, std::min(from, to), std::max(from, to), t, from < to});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& a, const EdgeUse& b) {
    if (a.group != b.group) return a.group < b.group;
    if (a.low != b.low) return a.low < b.low;
    return a.high != b.high ? a.high < b.high : a.triangle < b.triangle;
  });
  return uses;
}

/// Calls visit(first, count) for the run of uses of each edge of each group.
template <class Visitor>
void forEachEdge(const std::vector<EdgeUse>& uses, Visitor visit) {
  std::size_t first = 0;
  while (first < uses.size()) {
    std::size_t end = first + 1;
    while (end < uses.size() && uses[end].group == uses[first].group && uses[end].low == uses[first].low &&
           uses[end].high == uses[first].high) {
      ++end;
    }
    visit(first, end - first);
    first = end;
  }
}

}  // namespace freespace::detail
