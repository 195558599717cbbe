#pragma once

// A horizontal edge of the arrangement and its cross-sections, shared by the two
// readings of them: in double intervals at the edge's angle
// (horizontal_edge_intervals.cpp) and exact, at rational angles next to it
// (horizontal_gluing.cpp).

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "freespace/topology/sub_face_gluing.h"

namespace freespace::gluing {

/// A patch meeting a horizontal edge with its slab that ends there (`below`) or
/// starts there.
struct EdgeSide {
  std::uint32_t patch;
  bool below;
};

/// The sides of the patches meeting along one line at one angle.
struct HorizontalEdge {
  AlgebraicAngle angle;
  std::vector<EdgeSide> sides;
};

/// Names a point of the edge that the sides' segments and curves reach from both
/// sides of the edge: a spiral (a segment end), the crossing with the line of a patch
/// not on the edge, or the point where two patches on the edge have equal slopes
/// (their curve lands there).
using EdgePoint = std::array<std::uint32_t, 5>;
constexpr std::uint32_t kSpiral = 0, kCrossingLine = 1, kEqualSlopes = 2;

inline EdgePoint spiralPointOf(const PatchGeometry& patch, int k) {
  const SegmentEnd& end = patch.segment.ends[k];
  return {kSpiral, end.robotVertex, end.vertex, end.edge[0], end.edge[1]};
}

/// The point where the curve of `patch` and `other` meets the edge; `onEdge` lists
/// the patches with a side on it.
inline EdgePoint curvePointOf(std::uint32_t patch, std::uint32_t other, const std::vector<std::uint32_t>& onEdge) {
  if (std::find(onEdge.begin(), onEdge.end(), other) == onEdge.end()) return {kCrossingLine, other, 0, 0, 0};
  return {kEqualSlopes, std::min(other, patch), std::max(other, patch), 0, 0};
}

/// A named point as read by one side: the patch that reads it, with the segment end
/// (a spiral) or the curve's other patch (a crossing line).
struct PointReading {
  EdgePoint point;
  std::uint32_t patch;
  int end;
  std::uint32_t other;
};

/// Whether two named points are one point of the edge, decided exactly at its
/// angle: a spiral on a crossing line (an SF root at the edge's angle), or two
/// crossing lines through one point of the edge (an FFF root).
bool onePointOfEdge(const PointReading& a, const PointReading& b, const AlgebraicAngle& edge,
                    const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra);

/// A patch in the cross-section of the edge at one point (offset s across the edge's
/// line against theta): a ray from the edge, down for a side below. `orientation` is
/// +1 when the patch's positive side faces +s.
struct EdgeRay {
  bool below;
  int orientation;
  SubFaceId face;
};

/// The cross-sections of an edge, one over each piece between consecutive named
/// points: the rays there in counterclockwise order (s across, theta up), rays up by
/// decreasing slope ds/dtheta, then rays down by decreasing slope.
using EdgeCrossSections = std::vector<std::vector<EdgeRay>>;

/// The cross-sections read at the edge's angle in double intervals: the slopes of
/// the patches' lines there (first derivatives in theta), the named points where the
/// edge's line meets spirals and crossing lines or two slopes agree. Nothing when an
/// order is uncertain (points too close to be told apart, or equal slopes over a
/// piece); the exact reading decides those. Points whose positions overlap are
/// merged when they are one point of the edge (onePointOfEdge).
std::optional<EdgeCrossSections> crossSectionsInIntervals(const HorizontalEdge& edge,
                                                          const std::vector<const PatchSlab*>& slabs,
                                                          const std::vector<PatchGeometry>& patches,
                                                          const std::vector<PatchCurve>& curves, AngleAlgebra& algebra);

/// The same reading in double-double intervals at the edge's angle refined to about
/// 2^-100: for edges whose points or slopes double intervals do not tell apart (a
/// line nearly parallel to the edge crosses it far less precisely than it is given).
std::optional<EdgeCrossSections> crossSectionsInDoubleDoubles(const HorizontalEdge& edge,
                                                              const std::vector<const PatchSlab*>& slabs,
                                                              const std::vector<PatchGeometry>& patches,
                                                              const std::vector<PatchCurve>& curves,
                                                              AngleAlgebra& algebra);

/// An edge read exactly: the named points along it in order, each with the names of
/// the points merged into it (onePointOfEdge), and the rays over each piece between
/// two consecutive points.
struct EdgeRead {
  std::vector<std::vector<EdgePoint>> points;
  EdgeCrossSections pieces;
};

/// A horizontal edge, the slab of each of its sides meeting it, and its exact
/// reading.
struct EdgeSlice {
  HorizontalEdge edge;
  std::vector<const PatchSlab*> slabs;
  EdgeRead reading;
};

/// Every horizontal edge read exactly (for checks of the arrangement's topology).
std::vector<EdgeSlice> horizontalEdgeSlices(const std::vector<PatchGeometry>& patches,
                                            const std::vector<PatchCurve>& curves,
                                            const std::vector<PatchOverlap>& overlaps,
                                            const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra);

}  // namespace freespace::gluing
