#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "freespace/geometry/mesh.h"

namespace freespace::detail {

/// The first pair of triangles (i < j, by i and then j) of one connected component
/// that meet anywhere but in the vertices they share and the edge between two shared
/// vertices: the component's surface crosses or touches itself, and the side of each
/// of its facets that faces outward is no longer outside the solid. Decided exactly
/// (signs of determinants on the vertices); pairs are found from their bounding
/// boxes. Triangles of different components may meet (their solids are joined).
std::optional<std::pair<std::uint32_t, std::uint32_t>> firstSelfIntersection(
    const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
    const std::vector<std::uint32_t>& componentOf);

/// The components (numbers of `componentOf`) whose surface meets itself, as for
/// firstSelfIntersection, each once, in increasing order.
std::vector<std::uint32_t> selfIntersectingComponents(const std::vector<Point3>& vertices,
                                                      const std::vector<TriangleIndices>& triangles,
                                                      const std::vector<std::uint32_t>& componentOf);

/// Every pair (i < j, by i and then j) of triangles that meet anywhere but in the
/// vertices they share and the edge between two shared vertices, decided exactly as
/// for firstSelfIntersection.
std::vector<std::pair<std::uint32_t, std::uint32_t>> meetingPairs(const std::vector<Point3>& vertices,
                                                                  const std::vector<TriangleIndices>& triangles);

}  // namespace freespace::detail
