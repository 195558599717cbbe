#include "soup_checks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include <boost/multiprecision/gmp.hpp>

#include "freespace/input_error.h"

namespace freespace::detail {

namespace {

using Index = std::uint32_t;
using Rational = boost::multiprecision::mpq_rational;

constexpr Index kNoIndex = std::numeric_limits<Index>::max();

bool lexicographicallyLess(const Point3& a, const Point3& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

// Component k of (b - a) x (c - a) is u[i] v[j] - u[j] v[i]: a 2D orientation
// determinant. Computed in doubles it is wrong by less than 3.0000000000000018 eps
// (|u[i] v[j]| + |u[j] v[i]|) (Shewchuk's orient2d bound) when no product under- or
// overflows; 8 eps leaves room for a non-default rounding mode.
bool crossProductClearlyNonZero(const Point3& a, const Point3& b, const Point3& c) {
  constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;
  constexpr double kErrorFactor = 8 * kUnitRoundoff;
  constexpr double kSmallestSafeMagnitude = 1e-280;
  const Point3 u = b - a;
  const Point3 v = c - a;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3;
    const int j = (k + 2) % 3;
    const double left = u[i] * v[j];
    const double right = u[j] * v[i];
    const double magnitude = std::abs(left) + std::abs(right);
    if (std::isfinite(magnitude) && magnitude >= kSmallestSafeMagnitude &&
        std::abs(left - right) > kErrorFactor * magnitude) {
      return true;
    }
  }
  return false;
}

bool crossProductExactlyZero(const Point3& a, const Point3& b, const Point3& c) {
  Rational u[3];
  Rational v[3];
  for (int k = 0; k < 3; ++k) {
    const Rational origin(a[k]);
    u[k] = Rational(b[k]) - origin;
    v[k] = Rational(c[k]) - origin;
  }
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3;
    const int j = (k + 2) % 3;
    if (u[i] * v[j] != u[j] * v[i]) return false;
  }
  return true;
}

}  // namespace

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

std::string formatPoint(const Point3& point) {
  return "(" + formatNumber(point.x()) + ", " + formatNumber(point.y()) + ", " +
         formatNumber(point.z()) + ")";
}

std::string countOf(std::size_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

std::string vertexLocations(const std::vector<Point3>& vertices,
                            std::initializer_list<Index> indices) {
  std::string text;
  std::vector<Index> listed;
  for (Index index : indices) {
    if (std::find(listed.begin(), listed.end(), index) != listed.end()) continue;
    text += listed.empty() ? "; vertex " + std::to_string(index) + " is at "
                           : ", vertex " + std::to_string(index) + " at ";
    text += formatPoint(vertices[index]);
    listed.push_back(index);
  }
  return text;
}

void requireFiniteCoordinates(const TriangleSoup& soup, const std::string& source) {
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      const double coordinate = soup.vertices[v][axis];
      if (!std::isfinite(coordinate)) {
        throw InputError(source, "vertex " + std::to_string(v) +
                                     " has a non-finite coordinate (" +
                                     formatNumber(coordinate) + ")");
      }
    }
  }
}

void requireTriangles(const TriangleSoup& soup, const std::string& source) {
  if (soup.triangles.empty()) throw InputError(source, "contains no triangles");
}

void requireIndicesInRange(const TriangleSoup& soup, const std::string& source) {
  const std::size_t vertexCount = soup.vertices.size();
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    for (Index index : soup.triangles[t]) {
      if (index >= vertexCount) {
        throw InputError(source, "triangle " + std::to_string(t) + " refers to vertex " +
                                     std::to_string(index) + ", but there are only " +
                                     std::to_string(vertexCount) + " vertices");
      }
    }
  }
}

TriangleSoup weldIdenticalVertices(const TriangleSoup& soup) {
  const std::size_t soupSize = soup.vertices.size();
  std::vector<bool> used(soupSize, false);
  for (const TriangleIndices& triangle : soup.triangles) {
    for (Index index : triangle) used[index] = true;
  }

  std::vector<Index> byPosition;
  for (Index v = 0; v < soupSize; ++v) {
    if (used[v]) byPosition.push_back(v);
  }
  std::sort(byPosition.begin(), byPosition.end(), [&](Index a, Index b) {
    const Point3& p = soup.vertices[a];
    const Point3& q = soup.vertices[b];
    if (lexicographicallyLess(p, q)) return true;
    if (lexicographicallyLess(q, p)) return false;
    return a < b;
  });

  // Each used soup vertex points to the first soup vertex at the same position.
  std::vector<Index> firstAtPosition(soupSize, kNoIndex);
  for (std::size_t i = 0; i < byPosition.size(); ++i) {
    const bool startsRun =
        i == 0 || soup.vertices[byPosition[i]] != soup.vertices[byPosition[i - 1]];
    firstAtPosition[byPosition[i]] = startsRun ? byPosition[i] : firstAtPosition[byPosition[i - 1]];
  }

  TriangleSoup surface;
  std::vector<Index> weldedIndex(soupSize, kNoIndex);
  for (Index v = 0; v < soupSize; ++v) {
    if (used[v] && firstAtPosition[v] == v) {
      weldedIndex[v] = static_cast<Index>(surface.vertices.size());
      surface.vertices.push_back(soup.vertices[v]);
    }
  }
  surface.triangles.reserve(soup.triangles.size());
  for (const TriangleIndices& triangle : soup.triangles) {
    TriangleIndices welded;
    for (int corner = 0; corner < 3; ++corner) {
      welded[corner] = weldedIndex[firstAtPosition[triangle[corner]]];
    }
    surface.triangles.push_back(welded);
  }
  return surface;
}

void dropUnusedVertices(TriangleSoup& soup) {
  std::vector<Index> newIndex(soup.vertices.size(), kNoIndex);
  for (const TriangleIndices& triangle : soup.triangles) {
    for (Index v : triangle) newIndex[v] = 0;
  }
  std::vector<Point3> used;
  for (Index v = 0; v < soup.vertices.size(); ++v) {
    if (newIndex[v] == kNoIndex) continue;
    newIndex[v] = static_cast<Index>(used.size());
    used.push_back(soup.vertices[v]);
  }
  for (TriangleIndices& triangle : soup.triangles) {
    for (Index& v : triangle) v = newIndex[v];
  }
  soup.vertices = std::move(used);
}

bool hasZeroArea(const std::vector<Point3>& vertices, const TriangleIndices& triangle) {
  const auto [a, b, c] = triangle;
  if (a == b || b == c || c == a) return true;
  const Point3& p = vertices[a];
  const Point3& q = vertices[b];
  const Point3& r = vertices[c];
  return !crossProductClearlyNonZero(p, q, r) && crossProductExactlyZero(p, q, r);
}

bool sameOrientation(const TriangleIndices& first, const TriangleIndices& second) {
  const auto start = std::find(second.begin(), second.end(), first[0]) - second.begin();
  return second[(start + 1) % 3] == first[1];
}

}  // namespace freespace::detail
