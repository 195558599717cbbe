#include "freespace/geometry/soup_repair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "disjoint_sets.h"
#include "freespace/geometry/determinants.h"
#include "freespace/numbers/adaptive_sign.h"
#include "soup_checks.h"
#include "triangle_box_tree.h"

namespace freespace {

namespace {

using Index = std::uint32_t;

// ---------------------------------------------------------------------------
// Welding within the tolerance

// A cell of a grid of cubes as wide as the tolerance, counted from the soup's lowest
// corner; indices are clamped so that no tolerance, however small, overflows them
// (clamped points share cells: slower, never wrong).
using GridCell = std::array<std::int64_t, 3>;

struct GridCellHash {
  std::size_t operator()(const GridCell& cell) const {
    std::size_t hash = 0;
    for (std::int64_t index : cell) hash = hash * 0x9E3779B97F4A7C15ull + static_cast<std::size_t>(index);
    return hash;
  }
};

GridCell cellOf(const Point3& point, const Point3& origin, double width) {
  constexpr double kLimit = 4.0e18;
  GridCell cell;
  for (int axis = 0; axis < 3; ++axis) {
    const double index = std::floor((point[axis] - origin[axis]) / width);
    cell[axis] = static_cast<std::int64_t>(std::clamp(index, -kLimit, kLimit));
  }
  return cell;
}

// For each point, the first point of its cluster: points chained by distances up to
// the tolerance.
std::vector<Index> clusterFirsts(const std::vector<Point3>& points, double tolerance) {
  detail::DisjointSets clusters(points.size());
  if (tolerance > 0 && !points.empty()) {
    Box3 bounds;
    for (const Point3& point : points) bounds.extend(point);
    // Each cell holds a list of its points: the last one added, then `next` links.
    constexpr Index kEnd = std::numeric_limits<Index>::max();
    std::unordered_map<GridCell, Index, GridCellHash> lastInCell;
    lastInCell.reserve(points.size());
    std::vector<Index> next(points.size(), kEnd);
    for (Index p = 0; p < points.size(); ++p) {
      const GridCell cell = cellOf(points[p], bounds.min(), tolerance);
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          for (std::int64_t dz = -1; dz <= 1; ++dz) {
            const auto found = lastInCell.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
            if (found == lastInCell.end()) continue;
            for (Index q = found->second; q != kEnd; q = next[q]) {
              if ((points[p] - points[q]).norm() <= tolerance) clusters.unite(p, q);
            }
          }
        }
      }
      const auto [slot, inserted] = lastInCell.emplace(cell, p);
      if (!inserted) {
        next[p] = slot->second;
        slot->second = p;
      }
    }
  }
  std::vector<Index> first(points.size());
  for (Index p = 0; p < points.size(); ++p) first[p] = clusters.find(p);
  return first;
}

// Moves every vertex to the first point of its cluster and drops the others; vertices
// keep their order.
TriangleSoup weldWithinTolerance(const TriangleSoup& welded, double tolerance, RepairReport& report) {
  const std::vector<Index> first = clusterFirsts(welded.vertices, tolerance);
  TriangleSoup result;
  std::vector<Index> newIndex(welded.vertices.size());
  for (Index v = 0; v < welded.vertices.size(); ++v) {
    if (first[v] == v) {
      newIndex[v] = static_cast<Index>(result.vertices.size());
      result.vertices.push_back(welded.vertices[v]);
    } else {
      ++report.pointsWelded;
      report.largestWeldDistance =
          std::max(report.largestWeldDistance, (welded.vertices[v] - welded.vertices[first[v]]).norm());
    }
  }
  result.triangles.reserve(welded.triangles.size());
  for (const TriangleIndices& triangle : welded.triangles) {
    result.triangles.push_back({newIndex[first[triangle[0]]], newIndex[first[triangle[1]]],
                                newIndex[first[triangle[2]]]});
  }
  return result;
}

// Moves every coordinate to the most frequent value among those within the
// tolerance above the smallest of its group (groups taken from the smallest value
// up), axis by axis: float noise that tilts faces meant to be level or flush by a
// hair is removed, so that they meet exactly. No coordinate moves by more than the
// tolerance; points that become identical are welded afterwards.
void snapCoordinates(TriangleSoup& soup, double tolerance, RepairReport& report) {
  if (tolerance == 0) return;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<Index> order(soup.vertices.size());
    for (Index v = 0; v < order.size(); ++v) order[v] = v;
    std::sort(order.begin(), order.end(),
              [&](Index a, Index b) { return soup.vertices[a][axis] < soup.vertices[b][axis]; });
    std::size_t first = 0;
    while (first < order.size()) {
      const double start = soup.vertices[order[first]][axis];
      std::size_t end = first;
      while (end < order.size() && soup.vertices[order[end]][axis] <= start + tolerance) ++end;
      // The most frequent value of the sorted run [first, end).
      double chosen = start;
      std::size_t best = 0;
      for (std::size_t i = first; i < end;) {
        std::size_t j = i;
        while (j < end && soup.vertices[order[j]][axis] == soup.vertices[order[i]][axis]) ++j;
        if (j - i > best) {
          best = j - i;
          chosen = soup.vertices[order[i]][axis];
        }
        i = j;
      }
      for (std::size_t i = first; i < end; ++i) {
        double& value = soup.vertices[order[i]][axis];
        if (value != chosen) ++report.coordinatesSnapped;
        value = chosen;
      }
      first = end;
    }
  }
}

// ---------------------------------------------------------------------------
// Zero-area and duplicate triangles

// A triangle whose corners are all within the tolerance of the line through two of
// them: its smallest height, twice its area over its longest side, is at most the
// tolerance (a sliver left where points were meant to be on one line).
bool flatWithinTolerance(const std::vector<Point3>& vertices, const TriangleIndices& triangle, double tolerance) {
  const Point3 &a = vertices[triangle[0]], &b = vertices[triangle[1]], &c = vertices[triangle[2]];
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  return (b - a).cross(c - a).norm() <= tolerance * longest;
}

void dropZeroAreaAndDuplicates(TriangleSoup& soup, std::vector<Index>& pieces, double tolerance,
                               RepairReport& report) {
  std::vector<std::pair<TriangleIndices, Index>> byVertexSet;  // sorted corners, triangle
  byVertexSet.reserve(soup.triangles.size());
  for (Index t = 0; t < soup.triangles.size(); ++t) {
    const TriangleIndices& triangle = soup.triangles[t];
    if (flatWithinTolerance(soup.vertices, triangle, tolerance) || detail::hasZeroArea(soup.vertices, triangle)) {
      ++report.zeroAreaDropped;
      continue;
    }
    TriangleIndices vertexSet = triangle;
    std::sort(vertexSet.begin(), vertexSet.end());
    byVertexSet.emplace_back(vertexSet, t);
  }
  std::sort(byVertexSet.begin(), byVertexSet.end());
  std::vector<bool> kept(soup.triangles.size(), false);
  for (std::size_t i = 0; i < byVertexSet.size(); ++i) {
    if (i == 0 || byVertexSet[i].first != byVertexSet[i - 1].first) {
      kept[byVertexSet[i].second] = true;  // the first of its vertex set: sorted by triangle within a set
      continue;
    }
    std::size_t first = i;
    while (first > 0 && byVertexSet[first - 1].first == byVertexSet[i].first) --first;
    const TriangleIndices& original = soup.triangles[byVertexSet[first].second];
    if (detail::sameOrientation(original, soup.triangles[byVertexSet[i].second])) {
      ++report.duplicatesDropped;
    } else {
      ++report.reversedDuplicatesDropped;
    }
  }
  std::vector<TriangleIndices> remaining;
  std::vector<Index> remainingPieces;
  remaining.reserve(byVertexSet.size());
  for (Index t = 0; t < soup.triangles.size(); ++t) {
    if (!kept[t]) continue;
    remaining.push_back(soup.triangles[t]);
    remainingPieces.push_back(pieces[t]);
  }
  soup.triangles = std::move(remaining);
  pieces = std::move(remainingPieces);
}

// ---------------------------------------------------------------------------
// T-junctions

using EdgeKey = std::uint64_t;

EdgeKey edgeKey(Index a, Index b) { return (EdgeKey{std::min(a, b)} << 32) | std::max(a, b); }
Index edgeLow(EdgeKey key) { return static_cast<Index>(key >> 32); }
Index edgeHigh(EdgeKey key) { return static_cast<Index>(key & 0xFFFFFFFFu); }

// Edges used by an odd number of triangles: where a surface has a T-junction, the
// long edge on one side faces two short ones on the other.
std::vector<EdgeKey> oddEdges(const std::vector<TriangleIndices>& triangles) {
  std::unordered_map<EdgeKey, Index> uses;
  for (const TriangleIndices& triangle : triangles) {
    for (int corner = 0; corner < 3; ++corner) ++uses[edgeKey(triangle[corner], triangle[(corner + 1) % 3])];
  }
  std::vector<EdgeKey> odd;
  for (const auto& [key, count] : uses) {
    if (count % 2 == 1) odd.push_back(key);
  }
  std::sort(odd.begin(), odd.end());
  return odd;
}

// Whether `p` lies inside the segment ab, at least the tolerance from both ends and
// within it of the segment; with no tolerance, exactly on the open segment.
bool liesInsideEdge(const Point3& p, const Point3& a, const Point3& b, double tolerance) {
  if (tolerance == 0) {
    if (!detail::hasZeroArea({a, b, p}, {0, 1, 2})) return false;
    const Point3 lower = a.cwiseMin(b);
    const Point3 upper = a.cwiseMax(b);
    return (p.array() >= lower.array()).all() && (p.array() <= upper.array()).all() && p != a && p != b;
  }
  const Point3 direction = b - a;
  const double length = direction.norm();
  const double along = (p - a).dot(direction) / length;
  if (along <= tolerance || along >= length - tolerance) return false;
  return (p - a - direction * (along / length)).norm() <= tolerance;
}

// The vertices to insert into each odd edge, in order along it from its lower
// vertex; only vertices of odd edges are candidates.
std::map<EdgeKey, std::vector<Index>> junctionsOnEdges(const TriangleSoup& soup, double tolerance) {
  std::map<EdgeKey, std::vector<Index>> junctions;
  const std::vector<EdgeKey> odd = oddEdges(soup.triangles);
  if (odd.empty()) return junctions;
  std::vector<detail::TreeEntry> entries;
  std::vector<Index> candidates;
  for (Index e = 0; e < odd.size(); ++e) {
    Box3 box(soup.vertices[edgeLow(odd[e])]);
    box.extend(soup.vertices[edgeHigh(odd[e])]);
    box.min().array() -= tolerance;
    box.max().array() += tolerance;
    entries.emplace_back(detail::treeBox(box), e);
    candidates.push_back(edgeLow(odd[e]));
    candidates.push_back(edgeHigh(odd[e]));
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  const detail::TriangleTree tree(entries.begin(), entries.end());
  for (Index v : candidates) {
    const Point3& p = soup.vertices[v];
    std::vector<detail::TreeEntry> near;
    tree.query(detail::bgi::intersects(detail::treeBox(Box3(p))), std::back_inserter(near));
    for (const detail::TreeEntry& entry : near) {
      const EdgeKey key = odd[entry.second];
      const Index a = edgeLow(key);
      const Index b = edgeHigh(key);
      if (v != a && v != b && liesInsideEdge(p, soup.vertices[a], soup.vertices[b], tolerance)) {
        junctions[key].push_back(v);
      }
    }
  }
  for (auto& [key, vertices] : junctions) {
    const Point3& from = soup.vertices[edgeLow(key)];
    std::sort(vertices.begin(), vertices.end(), [&](Index p, Index q) {
      return (soup.vertices[p] - from).squaredNorm() < (soup.vertices[q] - from).squaredNorm();
    });
  }
  return junctions;
}

// The triangle's corners with the junction vertices of its edges between them, in
// the triangle's order.
std::vector<Index> boundaryWithJunctions(const TriangleIndices& triangle,
                                         const std::map<EdgeKey, std::vector<Index>>& junctions) {
  std::vector<Index> boundary;
  for (int corner = 0; corner < 3; ++corner) {
    const Index from = triangle[corner];
    const Index to = triangle[(corner + 1) % 3];
    boundary.push_back(from);
    const auto found = junctions.find(edgeKey(from, to));
    if (found == junctions.end()) continue;
    if (from < to) {
      boundary.insert(boundary.end(), found->second.begin(), found->second.end());
    } else {
      boundary.insert(boundary.end(), found->second.rbegin(), found->second.rend());
    }
  }
  return boundary;
}

// Triangulates a polygon made of a triangle's corners and points on (or within the
// tolerance of) its edges, keeping the triangle's orientation, by clipping ears: a
// corner whose two neighbours turn the triangle's way (decided exactly in the
// projection that keeps the triangle's normal's largest component) and whose
// triangle holds no other polygon vertex. Points on one straight side never form an
// ear, so no triangle of zero area is made.
class EarClipper {
 public:
  EarClipper(const std::vector<Point3>& vertices, PredicateStatistics& statistics)
      : vertices_(vertices), engine_(statistics) {}

  std::vector<TriangleIndices> triangulate(std::vector<Index> polygon, const TriangleIndices& triangle) {
    const Point3& a = vertices_[triangle[0]];
    const Point3 normal = (vertices_[triangle[1]] - a).cross(vertices_[triangle[2]] - a);
    normal.cwiseAbs().maxCoeff(&droppedAxis_);
    turn_ = normal[droppedAxis_] > 0 ? Sign::Positive : Sign::Negative;
    std::vector<TriangleIndices> triangles;
    while (polygon.size() > 3) {
      const std::size_t ear = findEar(polygon);
      const std::size_t n = polygon.size();
      triangles.push_back({polygon[(ear + n - 1) % n], polygon[ear], polygon[(ear + 1) % n]});
      polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(ear));
    }
    triangles.push_back({polygon[0], polygon[1], polygon[2]});
    return triangles;
  }

 private:
  Sign orientation(Index a, Index b, Index c) {
    return engine_.sign(PredicateKind::Orientation, [&](auto numberType) {
      using T = typename decltype(numberType)::type;
      return orient2dDeterminant(point<T>(a), point<T>(b), point<T>(c), droppedAxis_);
    });
  }

  template <class T>
  Vec3T<T> point(Index vertex) const {
    const Point3& p = vertices_[vertex];
    return {T(p.x()), T(p.y()), T(p.z())};
  }

  bool isEar(const std::vector<Index>& polygon, std::size_t i) {
    const std::size_t n = polygon.size();
    const Index previous = polygon[(i + n - 1) % n], corner = polygon[i], next = polygon[(i + 1) % n];
    if (orientation(previous, corner, next) != turn_) return false;
    for (Index other : polygon) {
      if (other == previous || other == corner || other == next) continue;
      if (orientation(previous, corner, other) != -turn_ && orientation(corner, next, other) != -turn_ &&
          orientation(next, previous, other) != -turn_) {
        return false;
      }
    }
    return true;
  }

  // A polygon bent beyond its tolerance may have no ear left; its first corner is
  // clipped then, and a triangle of zero area that this makes is dropped later.
  std::size_t findEar(const std::vector<Index>& polygon) {
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      if (isEar(polygon, i)) return i;
    }
    return 0;
  }

  const std::vector<Point3>& vertices_;
  AdaptiveSignEngine engine_;
  int droppedAxis_ = 2;
  Sign turn_ = Sign::Positive;
};

// Inserts every junction vertex into the edges it lies on: each triangle along such
// an edge is replaced by a triangulation of its corners and the inserted vertices.
// Returns whether there were any.
bool snapJunctions(TriangleSoup& soup, std::vector<Index>& pieces, double tolerance, RepairReport& report) {
  const std::map<EdgeKey, std::vector<Index>> junctions = junctionsOnEdges(soup, tolerance);
  if (junctions.empty()) return false;
  for (const auto& [key, vertices] : junctions) report.verticesSnapped += vertices.size();
  PredicateStatistics statistics;
  EarClipper clipper(soup.vertices, statistics);
  std::vector<TriangleIndices> result;
  std::vector<Index> resultPieces;
  for (Index t = 0; t < soup.triangles.size(); ++t) {
    std::vector<Index> boundary = boundaryWithJunctions(soup.triangles[t], junctions);
    if (boundary.size() == 3) {
      result.push_back(soup.triangles[t]);
      resultPieces.push_back(pieces[t]);
      continue;
    }
    ++report.trianglesSplit;
    for (const TriangleIndices& part : clipper.triangulate(std::move(boundary), soup.triangles[t])) {
      result.push_back(part);
      resultPieces.push_back(pieces[t]);
    }
  }
  soup.triangles = std::move(result);
  pieces = std::move(resultPieces);
  return true;
}

// Whether the distinct values of each coordinate lie more than the tolerance apart:
// then no coordinate snaps, and no two distinct points lie within the tolerance of
// each other (they would differ by at most it on the axis where they differ).
bool coordinatesApartBeyond(const std::vector<Point3>& vertices, double tolerance) {
  std::vector<double> values(vertices.size());
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t v = 0; v < vertices.size(); ++v) values[v] = vertices[v][axis];
    std::sort(values.begin(), values.end());
    for (std::size_t i = 1; i < values.size(); ++i) {
      if (values[i] != values[i - 1] && values[i] - values[i - 1] <= tolerance) return false;
    }
  }
  return true;
}

}  // namespace

RepairReport unrepairedReport(const TriangleSoup& soup, const RepairSettings& settings) {
  RepairReport report;
  report.inputVertices = report.outputVertices = soup.vertices.size();
  report.inputTriangles = report.outputTriangles = soup.triangles.size();
  Box3 bounds;
  for (const TriangleIndices& triangle : soup.triangles) {
    for (Index v : triangle) bounds.extend(soup.vertices[v]);
  }
  report.toleranceIsRelative = !settings.absoluteTolerance.has_value();
  report.relativeTolerance = settings.relativeTolerance;
  report.tolerance = settings.absoluteTolerance.value_or(settings.relativeTolerance * bounds.diagonal().stableNorm());
  if (!std::isfinite(report.tolerance) || report.tolerance < 0) {
    throw std::invalid_argument("repair tolerance must be finite and not negative");
  }
  return report;
}

bool weldsAndSnapsNothing(const TriangleSoup& soup, double tolerance) {
  if (tolerance == 0) return true;
  for (const TriangleIndices& triangle : soup.triangles) {
    if (flatWithinTolerance(soup.vertices, triangle, tolerance)) return false;
  }
  return coordinatesApartBeyond(soup.vertices, tolerance);
}

bool RepairReport::changedAnything() const {
  return pointsWelded + coordinatesSnapped + verticesSnapped + zeroAreaDropped + duplicatesDropped +
             reversedDuplicatesDropped >
         0;
}

std::vector<std::string> RepairReport::describe() const {
  using detail::countOf;
  std::vector<std::string> lines;
  if (pointsWelded > 0) {
    lines.push_back(countOf(pointsWelded, "point") + " welded to a point within the tolerance (moved at most " +
                    detail::formatNumber(largestWeldDistance) + ")");
  }
  if (coordinatesSnapped > 0) {
    lines.push_back(countOf(coordinatesSnapped, "coordinate") + " moved to a value within the tolerance shared by "
                    "others (float noise)");
  }
  if (verticesSnapped > 0) {
    lines.push_back(countOf(verticesSnapped, "vertex insertion") + " into edges the vertices lie on (T-junctions), "
                    "splitting " + countOf(trianglesSplit, "triangle"));
  }
  if (zeroAreaDropped > 0) {
    lines.push_back(countOf(zeroAreaDropped, "triangle") + " of zero area (within the tolerance) dropped");
  }
  if (duplicatesDropped > 0) lines.push_back(countOf(duplicatesDropped, "duplicate triangle") + " dropped");
  if (reversedDuplicatesDropped > 0) {
    lines.push_back(countOf(reversedDuplicatesDropped, "triangle") + " dropped as reversed copies of others (a double-sided surface)");
  }
  const std::string tolerance = "tolerance " + detail::formatNumber(this->tolerance);
  lines.push_back(toleranceIsRelative ? tolerance + " (" + detail::formatNumber(relativeTolerance) +
                                            " of the bounding box diagonal)"
                                      : tolerance);
  return lines;
}

TriangleSoup repairSoup(const TriangleSoup& soup, const std::string& sourceName, const RepairSettings& settings,
                        RepairReport* report, std::vector<std::uint32_t>* pieces) {
  detail::requireFiniteCoordinates(soup, sourceName);
  detail::requireTriangles(soup, sourceName);
  detail::requireIndicesInRange(soup, sourceName);
  RepairReport counts = unrepairedReport(soup, settings);

  std::vector<Index> piece = soup.pieces.size() == soup.triangles.size() ? soup.pieces
                                                                         : std::vector<Index>(soup.triangles.size(), 0);
  TriangleSoup repaired = weldWithinTolerance(detail::weldIdenticalVertices(soup), counts.tolerance, counts);
  const std::size_t snappedBefore = counts.coordinatesSnapped;
  snapCoordinates(repaired, counts.tolerance, counts);
  if (counts.coordinatesSnapped > snappedBefore) repaired = detail::weldIdenticalVertices(repaired);
  dropZeroAreaAndDuplicates(repaired, piece, counts.tolerance, counts);
  if (snapJunctions(repaired, piece, counts.tolerance, counts)) {
    dropZeroAreaAndDuplicates(repaired, piece, counts.tolerance, counts);
  }
  detail::dropUnusedVertices(repaired);
  if (pieces) *pieces = std::move(piece);
  counts.outputVertices = repaired.vertices.size();
  counts.outputTriangles = repaired.triangles.size();
  if (report) *report = counts;
  return repaired;
}

}  // namespace freespace
