#pragma once

// Checks and clean-ups of a triangle soup shared by the repair (soup_repair) and the
// validation of meshes (Mesh::fromSoup), and the text of their messages.

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "freespace/geometry/mesh.h"

namespace freespace::detail {

/// Shortest decimal text that reads back as the same double ("0.1", "-inf"); every
/// NaN prints as "nan" (its sign means nothing).
std::string formatNumber(double value);
std::string formatPoint(const Point3& point);

/// "1 triangle", "3 triangles": a count with its noun (a regular plural).
std::string countOf(std::size_t count, const std::string& noun);

/// "; vertex 3 is at (0, 0, 1), vertex 8 at (1, 0, 1)": where the vertices named by a
/// message are, since welded indices do not appear in the user's file.
std::string vertexLocations(const std::vector<Point3>& vertices, std::initializer_list<std::uint32_t> indices);

/// Throw InputError naming `source` (and the soup's own vertex and triangle numbers).
void requireFiniteCoordinates(const TriangleSoup& soup, const std::string& source);
void requireTriangles(const TriangleSoup& soup, const std::string& source);
void requireIndicesInRange(const TriangleSoup& soup, const std::string& source);

/// Merges vertices with identical coordinates and drops unused ones; the kept
/// vertices stay in the order of their first appearance in the soup.
TriangleSoup weldIdenticalVertices(const TriangleSoup& soup);

/// Keeps only the vertices some triangle uses, in their order.
void dropUnusedVertices(TriangleSoup& soup);

/// A triangle with a repeated vertex, or whose corners are collinear (decided
/// exactly).
bool hasZeroArea(const std::vector<Point3>& vertices, const TriangleIndices& triangle);

/// Whether two triangles on the same three vertices run through them the same way.
bool sameOrientation(const TriangleIndices& first, const TriangleIndices& second);

}  // namespace freespace::detail
