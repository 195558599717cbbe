#include <algorithm>
#include <map>
#include <stdexcept>

#include "freespace/geometry/patch_vertex.h"
#include "freespace/topology/slice_pieces.h"
#include "freespace/topology/sub_face_gluing.h"
#include "gluing_parts.h"
#include "horizontal_edge.h"

namespace freespace {

namespace {

using slices::ExactSegment;
using slices::Point;
using slices::segmentAt;
using gluing::EdgeCrossSections;
using gluing::EdgeRay;
using gluing::EdgeSide;
using gluing::HorizontalEdge;
using gluing::EdgePoint;
using gluing::kCrossingLine;
using gluing::kSpiral;
using gluing::curvePointOf;
using gluing::spiralPointOf;
using gluing::PointReading;
using gluing::onePointOfEdge;

/// How near the angles the cross-sections are read at lie to a horizontal edge (one
/// on each side, inside the slabs meeting the edge there): within 2^-kBits in the
/// tangent parameter. The named points of the edge (see EdgePoint) must come out
/// apart and in one order on both sides; if not, the bits are doubled (twice at most).
constexpr int kBits = 64;

/// Groups range ends and overlaps by the EF function they are roots of (range ends
/// of one function's root share a line there: the edge lies in the facet's plane;
/// an overlap's coincidence function is keyed as an EF function) and by root.
std::vector<HorizontalEdge> horizontalEdges(const std::vector<PatchGeometry>& patches,
                                            const std::vector<PatchOverlap>& overlaps, AngleAlgebra& algebra) {
  std::map<AngleFunction::RootKey, std::vector<HorizontalEdge>> byFunction;
  const auto add = [&](const AlgebraicAngle& angle, EdgeSide side) {
    const auto& function = angle.function();
    if (!function || !function->key()) throw std::logic_error("glueAcrossHorizontalEdges: an edge's angle has no key");
    std::vector<HorizontalEdge>& edges = byFunction[*function->key()];
    for (HorizontalEdge& edge : edges) {
      if (algebra.compare(edge.angle, angle) == 0) return edge.sides.push_back(side);
    }
    edges.push_back({angle, {side}});
  };
  for (std::uint32_t patch = 0; patch < patches.size(); ++patch) {
    for (const AngleInterval& arc : patches[patch].patch.range.arcs) {
      add(arc.from, {patch, false});
      add(arc.to, {patch, true});
    }
  }
  for (const PatchOverlap& overlap : overlaps) {
    for (std::uint32_t patch : overlap.patches) {
      add(overlap.angle, {patch, true});
      add(overlap.angle, {patch, false});
    }
  }
  std::vector<HorizontalEdge> edges;
  for (auto& [key, ofFunction] : byFunction) {
    for (HorizontalEdge& edge : ofFunction) edges.push_back(std::move(edge));
  }
  return edges;
}

/// A side of the edge read at its near angle: its segment, the crossings of its
/// slab's curves by lambda, and its named points with their positions along the edge.
struct SideAtAngle {
  EdgeSide side;
  const PatchSlab* slab;
  ExactSegment segment;
  std::vector<Rational> crossings;
  Rational position0, position1;
  /// +1 when the positive side faces +s of the cross-section.
  int orientation = 0;
};

/// A patch in the cross-section at one position, with its exact offset there.
struct OffsetRay {
  Rational offset;
  EdgeRay ray;
};

/// The named points of the edge in their order along it, each with the range of
/// positions it was read at (the two sides of the edge read it at two angles, and
/// different segments at different points of a crossing line).
struct NamedPosition {
  EdgePoint point;
  Rational low, high;
  /// The points merged into this one (onePointOfEdge), itself first.
  std::vector<EdgePoint> names;
};

/// Reads the cross-sections of an edge exactly, at rational angles next to it.
class ExactEdgeReader {
 public:
  ExactEdgeReader(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                  AngleAlgebra& algebra)
      : patches_(patches), curves_(curves), algebra_(algebra) {}

  gluing::EdgeRead read(const HorizontalEdge& edge, const std::vector<const PatchSlab*>& slabs) {
    onEdge_.clear();
    for (const EdgeSide& side : edge.sides) onEdge_.push_back(side.patch);
    const std::array<std::optional<AlgebraicAngle>, 2> bounds = boundsOf(edge, slabs);
    for (int bits = kBits; bits <= 4 * kBits; bits *= 2) {
      const std::vector<SideAtAngle> sides = sidesNextTo(edge, slabs, bounds, bits);
      if (const std::optional<std::vector<NamedPosition>> points = namedPositions(sides, edge.angle)) {
        gluing::EdgeRead reading;
        for (std::size_t i = 0; i < points->size(); ++i) {
          reading.points.push_back((*points)[i].names);
          if (i > 0) reading.pieces.push_back(raysAt(((*points)[i - 1].high + (*points)[i].low) / 2, sides));
        }
        return reading;
      }
    }
    throw std::logic_error("glueAcrossHorizontalEdges: points of an edge not apart");
  }

 private:
  /// For each side of the edge (index 1 below), if any slab meets the edge there, an
  /// angle such that the open arc from it to the edge lies inside every such slab.
  std::array<std::optional<AlgebraicAngle>, 2> boundsOf(const HorizontalEdge& edge,
                                                        const std::vector<const PatchSlab*>& slabs) {
    std::array<std::optional<AlgebraicAngle>, 2> bounds;
    for (std::size_t i = 0; i < slabs.size(); ++i) {
      const bool below = edge.sides[i].below;
      std::optional<AlgebraicAngle>& bound = bounds[below ? 1 : 0];
      const AlgebraicAngle& otherEnd = below ? slabs[i]->from : slabs[i]->to;
      if (!bound) {
        bound = slabs[i]->sample;
      } else if (algebra_.contains(between(*bound, edge.angle, below), otherEnd, AngleAlgebra::Boundary::Excluded)) {
        bound = otherEnd;
      }
    }
    return bounds;
  }

  /// The sides read at rational angles within 2^-bits of the edge, below and above.
  std::vector<SideAtAngle> sidesNextTo(const HorizontalEdge& edge, const std::vector<const PatchSlab*>& slabs,
                                       const std::array<std::optional<AlgebraicAngle>, 2>& bounds, int bits) {
    std::array<std::optional<std::pair<Rational, Rational>>, 2> rotations;
    for (int below = 1; below >= 0; --below) {
      if (bounds[below]) rotations[below] = exactCosSin(algebra_.rationalNextTo(edge.angle, *bounds[below], below == 1, bits));
    }
    std::vector<SideAtAngle> sides;
    for (std::size_t i = 0; i < edge.sides.size(); ++i) {
      const auto& [cosine, sine] = *rotations[edge.sides[i].below ? 1 : 0];
      sides.push_back(sideAt(edge.sides[i], slabs[i], cosine, sine));
    }
    orient(sides);
    return sides;
  }

  /// The open arc between an angle and the edge's, counterclockwise toward the edge
  /// when `below`.
  AngleInterval between(const AlgebraicAngle& angle, const AlgebraicAngle& edge, bool below) {
    const AlgebraicAngle &from = below ? angle : edge, &to = below ? edge : angle;
    return {from, to, algebra_.compare(from, to) > 0};
  }

  SideAtAngle sideAt(const EdgeSide& side, const PatchSlab* slab, const Rational& cosine, const Rational& sine) {
    SideAtAngle at{side, slab, segmentAt(patches_[side.patch], cosine, sine), {}, 0, 0};
    for (std::uint32_t curve : slab->curves) {
      const ExactSegment other = segmentAt(patches_[curves_[curve].other(side.patch)], cosine, sine);
      const Rational v0 = other.valueAt(at.segment.end0), v1 = other.valueAt(at.segment.end1);
      if (v0 == v1) throw std::logic_error("glueAcrossHorizontalEdges: a curve's line is parallel to a segment");
      at.crossings.push_back(v0 / (v0 - v1));
    }
    if (!std::is_sorted(at.crossings.begin(), at.crossings.end())) {
      throw std::logic_error("glueAcrossHorizontalEdges: curves out of their slab's order");
    }
    return at;
  }

  /// Positions along the edge are read along the first side's line, offsets across
  /// it along its normal.
  void orient(std::vector<SideAtAngle>& sides) {
    normal_ = {sides.front().segment.nx, sides.front().segment.ny};
    for (SideAtAngle& side : sides) {
      side.position0 = position(side.segment.end0);
      side.position1 = position(side.segment.end1);
      if (side.position0 == side.position1) throw std::logic_error("glueAcrossHorizontalEdges: a segment across the edge");
      const Rational dot = side.segment.nx * normal_[0] + side.segment.ny * normal_[1];
      if (dot == 0) throw std::logic_error("glueAcrossHorizontalEdges: a line across the edge");
      side.orientation = dot > 0 ? 1 : -1;
    }
  }

  Rational position(const Point& p) const { return p[1] * normal_[0] - p[0] * normal_[1]; }

  /// A named point as read by one side, and where.
  struct Reading {
    Rational at;
    PointReading what;
  };

  /// The named points the sides reach, in order along the edge: readings of one
  /// point, and of points that are one point of the edge (onePointOfEdge), are merged.
  /// None when readings of points apart at the edge interleave (the angles read at
  /// are not near enough to the edge to tell their order).
  std::optional<std::vector<NamedPosition>> namedPositions(const std::vector<SideAtAngle>& sides,
                                                           const AlgebraicAngle& edge) {
    std::vector<Reading> read;
    for (const SideAtAngle& side : sides) {
      const std::uint32_t patch = side.side.patch;
      read.push_back({side.position0, {spiralPointOf(patches_[patch], 0), patch, 0, 0}});
      read.push_back({side.position1, {spiralPointOf(patches_[patch], 1), patch, 1, 0}});
      for (std::size_t i = 0; i < side.crossings.size(); ++i) {
        const std::uint32_t curve = side.slab->curves[i];
        read.push_back({side.position0 + side.crossings[i] * (side.position1 - side.position0),
                        {curvePointOf(patch, curves_[curve].other(patch), onEdge_), patch, -1,
                         curves_[curve].other(patch)}});
      }
    }
    // The range of positions each point is read at, by first reading.
    std::map<EdgePoint, std::pair<Rational, Rational>> range;
    std::map<EdgePoint, const PointReading*> first;
    for (const Reading& reading : read) {
      const auto [found, inserted] = range.try_emplace(reading.what.point, reading.at, reading.at);
      if (inserted) first[reading.what.point] = &reading.what;
      found->second.first = std::min(found->second.first, reading.at);
      found->second.second = std::max(found->second.second, reading.at);
    }
    std::vector<NamedPosition> byLow;
    for (const auto& [point, extent] : range) byLow.push_back({point, extent.first, extent.second, {point}});
    std::sort(byLow.begin(), byLow.end(), [](const NamedPosition& a, const NamedPosition& b) { return a.low < b.low; });
    // Overlapping ranges are one point of the edge or the order is not known yet;
    // consecutive points apart at the near angles may be one point of the edge too.
    std::vector<NamedPosition> points;
    for (const NamedPosition& next : byLow) {
      const bool overlapping = !points.empty() && next.low <= points.back().high;
      if (!points.empty() && onePointOfEdge(*first[points.back().point], *first[next.point], edge, patches_, algebra_)) {
        points.back().high = std::max(points.back().high, next.high);
        points.back().names.push_back(next.point);
        continue;
      }
      if (overlapping) return std::nullopt;
      points.push_back(next);
    }
    return points;
  }

  /// The rays of the sides over one position of the edge, ordered counterclockwise
  /// in the cross-section. The offset of a line read above the edge is its slope
  /// times a positive gap, below times a negative one: rays up by decreasing offset,
  /// rays down by increasing offset.
  std::vector<EdgeRay> raysAt(const Rational& at, const std::vector<SideAtAngle>& sides) {
    std::vector<OffsetRay> rays;
    for (const SideAtAngle& side : sides) {
      const Rational lambda = (at - side.position0) / (side.position1 - side.position0);
      if (lambda <= 0 || lambda >= 1) continue;
      const ExactSegment& s = side.segment;
      const Point p = s.at(lambda);
      const auto gap = std::upper_bound(side.crossings.begin(), side.crossings.end(), lambda) - side.crossings.begin();
      rays.push_back({p[0] * normal_[0] + p[1] * normal_[1],
                      {side.side.below, side.orientation,
                       {side.side.patch, side.slab->faces[static_cast<std::size_t>(gap)]}}});
    }
    std::sort(rays.begin(), rays.end(), [](const OffsetRay& a, const OffsetRay& b) {
      if (a.ray.below != b.ray.below) return b.ray.below;
      return a.ray.below ? a.offset < b.offset : a.offset > b.offset;
    });
    std::vector<EdgeRay> counterclockwise;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      if (i > 0 && rays[i - 1].ray.below == rays[i].ray.below && rays[i - 1].offset == rays[i].offset) {
        throw std::logic_error("glueAcrossHorizontalEdges: two lines cross over a sample of an edge");
      }
      counterclockwise.push_back(rays[i].ray);
    }
    return counterclockwise;
  }

  const std::vector<PatchGeometry>& patches_;
  const std::vector<PatchCurve>& curves_;
  AngleAlgebra& algebra_;
  std::vector<std::uint32_t> onEdge_;
  Point normal_;
};

/// The slab of each side of the edge: the one ending at its angle for a side below,
/// starting there otherwise.
std::vector<const PatchSlab*> slabsMeeting(const HorizontalEdge& edge, const std::vector<PatchSubdivision>& subdivisions,
                                           AngleAlgebra& algebra) {
  std::vector<const PatchSlab*> slabs;
  for (const EdgeSide& side : edge.sides) {
    slabs.push_back(gluing::slabMeeting(subdivisions[side.patch], edge.angle, side.below, algebra));
    if (!slabs.back()) throw std::logic_error("glueAcrossHorizontalEdges: a patch has no slab at its edge");
  }
  return slabs;
}

/// Glues consecutive rays around the edge, as around a spiral: a ray down faces the
/// sector after it (on its left) when its positive side is +s; a ray up when it is -s.
void glueAcross(const HorizontalEdge& edge, const EdgeCrossSections& sections, gluing::GlueList& glues) {
  for (const std::vector<EdgeRay>& rays : sections) {
    gluing::glueAround(
        rays, [](const EdgeRay& ray) { return ray.below == (ray.orientation > 0); },
        [](const EdgeRay& ray, bool) { return ray.face; }, GluedEdge::Horizontal,
        [&](const EdgeRay&, const EdgeRay&) { return edge.angle; }, glues);
  }
}

}  // namespace

namespace gluing {

bool onePointOfEdge(const PointReading& a, const PointReading& b, const AlgebraicAngle& edge,
                    const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra) {
  if (a.point[0] > b.point[0]) return onePointOfEdge(b, a, edge, patches, algebra);
  if (a.point[0] == kSpiral && b.point[0] == kCrossingLine) {
    const PatchGeometry& spiralOwner = patches[a.patch];
    const auto function = spiralOnLine(patches[b.other].line, spiralOwner.ends[a.end], spiralOwner.segment.ends[a.end]);
    return algebra.signAt(*function, edge) == Sign::Zero;
  }
  if (a.point[0] == kCrossingLine && b.point[0] == kCrossingLine) {
    const auto function = threePatchFunction(patches[a.patch].line, patches[a.other].line, patches[b.other].line);
    return algebra.signAt(*function, edge) == Sign::Zero;
  }
  return false;
}

std::vector<EdgeSlice> horizontalEdgeSlices(const std::vector<PatchGeometry>& patches,
                                            const std::vector<PatchCurve>& curves,
                                            const std::vector<PatchOverlap>& overlaps,
                                            const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra) {
  std::vector<EdgeSlice> slices;
  ExactEdgeReader exact(patches, curves, algebra);
  for (HorizontalEdge& edge : horizontalEdges(patches, overlaps, algebra)) {
    std::vector<const PatchSlab*> slabs = slabsMeeting(edge, subdivisions, algebra);
    EdgeRead reading = exact.read(edge, slabs);
    slices.push_back({std::move(edge), std::move(slabs), std::move(reading)});
  }
  return slices;
}

}  // namespace gluing

SubFaceGluing glueAcrossHorizontalEdges(const std::vector<PatchGeometry>& patches,
                                        const std::vector<PatchCurve>& curves,
                                        const std::vector<PatchOverlap>& overlaps,
                                        const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra,
                                        const Cancellation& cancellation, EdgeReading reading) {
  gluing::GlueList glues;
  ExactEdgeReader exact(patches, curves, algebra);
  for (const HorizontalEdge& edge : horizontalEdges(patches, overlaps, algebra)) {
    cancellation.check();
    const std::vector<const PatchSlab*> slabs = slabsMeeting(edge, subdivisions, algebra);
    std::optional<EdgeCrossSections> sections;
    PrecisionLevel level = PrecisionLevel::Exact;
    if (reading == EdgeReading::Filtered) {
      sections = gluing::crossSectionsInIntervals(edge, slabs, patches, curves, algebra);
      level = PrecisionLevel::DoubleInterval;
      if (!sections) {
        sections = gluing::crossSectionsInDoubleDoubles(edge, slabs, patches, curves, algebra);
        level = PrecisionLevel::DoubleDouble;
      }
    }
    algebra.statistics().recordDecision(PredicateKind::EdgeCrossSection,
                                        static_cast<int>(sections ? level : PrecisionLevel::Exact));
    glueAcross(edge, sections ? *sections : exact.read(edge, slabs).pieces, glues);
  }
  return glues.take();
}

}  // namespace freespace
