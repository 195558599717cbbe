#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "freespace/geometry/mesh.h"

namespace freespace {

/// How far apart two points may be and still be taken for one (docs/design.md
/// section 9).
struct RepairSettings {
  /// The tolerance as a fraction of the diagonal of the soup's bounding box, unless
  /// `absoluteTolerance` is set.
  double relativeTolerance = 1e-6;
  /// A tolerance in the model's units; 0 welds only identical points and snaps only
  /// vertices lying exactly on an edge.
  std::optional<double> absoluteTolerance;
};

/// What a repair changed, in counts.
struct RepairReport {
  double tolerance = 0;          // as used, in the model's units
  bool toleranceIsRelative = true;
  double relativeTolerance = 0;  // the fraction of the diagonal, when relative
  std::size_t inputVertices = 0;
  std::size_t inputTriangles = 0;
  std::size_t pointsWelded = 0;      // distinct positions merged into a nearby one
  double largestWeldDistance = 0;    // how far a welded point moved at most
  std::size_t coordinatesSnapped = 0;  // x, y or z values moved to a nearby shared value
  std::size_t verticesSnapped = 0;   // (vertex, edge) pairs: a vertex inserted into an edge it lies on
  std::size_t trianglesSplit = 0;    // triangles split at such vertices
  std::size_t zeroAreaDropped = 0;   // no higher than the tolerance
  std::size_t duplicatesDropped = 0;          // same three vertices, same orientation
  std::size_t reversedDuplicatesDropped = 0;  // same three vertices, opposite orientation (double-sided)
  std::size_t outputVertices = 0;
  std::size_t outputTriangles = 0;

  /// Whether any point moved or any triangle was dropped or split.
  bool changedAnything() const;
  /// One line per kind of change, then the tolerance ("tolerance 1.4e-4 (1e-6 of
  /// the bounding box diagonal)").
  std::vector<std::string> describe() const;
};

/// The report of a repair that changes nothing: the soup's counts and the tolerance
/// `settings` give it. Throws std::invalid_argument for a negative or non-finite
/// tolerance.
RepairReport unrepairedReport(const TriangleSoup& soup, const RepairSettings& settings);

/// Whether repairSoup's welding and snapping within `tolerance` would leave the soup
/// as it is: the distinct values of each coordinate lie more than the tolerance apart
/// and no triangle is flatter than it. (Identical points, duplicates and T-junctions
/// are not looked at: a surface that Mesh::fromSoup accepts has none of them.)
bool weldsAndSnapsNothing(const TriangleSoup& soup, double tolerance);

/// Repairs a soup before it is interpreted as a solid (docs/design.md section 9):
/// welds points closer than the tolerance (each cluster of points chained
/// by distances within it goes to its point that comes first in the soup), moves
/// each coordinate to the most frequent value among those within the tolerance of it
/// (axis by axis, in groups from the smallest value up, so that float noise no
/// longer tilts faces meant to be level or flush), inserts
/// vertices into the edges they lie on within the tolerance where an edge is used by
/// an odd number of triangles (T-junctions: the triangles along the edge are split),
/// and drops triangles of zero area (exactly, or no higher than the tolerance: a
/// sliver) and all but the first of triangles on the same three vertices, in either
/// orientation. The result
/// has distinct vertices, each used by a triangle, in the order of their first use;
/// triangles keep their order. `pieces`, when given, receives for each triangle of
/// the result the piece of the input it comes from (soup.pieces; all 0 when the soup
/// does not say). Throws InputError
/// naming `sourceName` for a non-finite coordinate, an index out of range or no
/// triangles, and std::invalid_argument for a negative or non-finite tolerance.
TriangleSoup repairSoup(const TriangleSoup& soup, const std::string& sourceName, const RepairSettings& settings,
                        RepairReport* report = nullptr, std::vector<std::uint32_t>* pieces = nullptr);

}  // namespace freespace
