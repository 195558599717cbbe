#include <map>

#include "freespace/geometry/patch_segment.h"
#include "freespace/topology/slice_pieces.h"
#include "horizontal_edge.h"

namespace freespace::gluing {

namespace {

template <class T>
using Vector = std::array<T, 2>;

template <class T>
T dot(const Vector<T>& a, const Vector<T>& b) {
  return a[0] * b[0] + a[1] * b[1];
}

using slices::toInterval;

Interval hull(const Interval& a, const Interval& b) {
  return {std::min(a.lower(), b.lower()), std::max(a.upper(), b.upper())};
}

/// a / b, when b is certainly not zero.
template <class T>
std::optional<T> quotient(const T& a, const T& b) {
  const std::optional<Sign> sign = certainSign(b);
  if (!sign || *sign == Sign::Zero) return std::nullopt;
  return a / b;
}

/// A patch's line at the edge's angle and its first derivative in theta:
///   n = R a1 + a2, n' = R' a1;  w = k1 sin + k2 cos + k3, w' = k1 cos - k2 sin.
template <class T>
struct LineWithSlope {
  Vector<T> n, dn;
  T w, dw;
};

template <class Slice, class T = typename Slice::Number>
LineWithSlope<T> lineWithSlope(const PatchGeometry& patch, const Slice& slice) {
  const T &cosine = slice.cosine, &sine = slice.sine;
  const PatchLine<T> line = lineOf<T>(patch.line);
  const LineAtAngle<T> at = lineAtAngle(line, cosine, sine);
  return {{at.nx, at.ny},
          {-sine * line.a1x - cosine * line.a1y, cosine * line.a1x - sine * line.a1y},
          at.w,
          line.k1 * cosine - line.k2 * sine};
}

/// Whether a < b for certain, b < a for certain, or neither.
std::optional<bool> certainlyBelow(const Interval& a, const Interval& b) {
  if (a.upper() < b.lower()) return true;
  if (b.upper() < a.lower()) return false;
  return std::nullopt;
}

/// The edge's line L: N . d + W = 0, the line of its first side at the edge's angle
/// (every side's line is a multiple of it there). Points of L are named by their
/// position m = d x N... precisely m = d_y N_x - d_x N_y, as in the exact reading,
/// so that d(m) = q0 + m D / |N|^2 with q0 = -W N / |N|^2 and D = (-N_y, N_x).
///
/// Slopes (docs/design.md section 6, step 5; the cross-section of a horizontal edge): near
/// the edge's angle, patch i's line meets the normal through d(m) at
/// d(m) + sigma_i N with sigma_i = -(n_i . d(m) + w_i) / (n_i . N), and sigma_i
/// vanishes at the edge's angle, so its derivative there is
///   sigma_i' = -(n_i' . d(m) + w_i') / (n_i . N) = A_i + m B_i,
/// the slope of the ray of patch i in the cross-section at m (the turn of N itself
/// changes all offsets alike to first order). The rays are ordered by these slopes.
///
/// In the number type of a slice at the edge's angle: double intervals, or double-
/// double intervals for edges whose named points or slopes are too close for those.
template <class Slice>
class EdgeAtAngle {
 public:
  using T = typename Slice::Number;

  /// Needs the first side's normal to be certainly not zero (`valid`).
  EdgeAtAngle(const HorizontalEdge& edge, const std::vector<PatchGeometry>& patches, const Slice& slice)
      : slice_(slice) {
    const LineWithSlope<T> first = lineWithSlope(patches[edge.sides.front().patch], slice_);
    normal_ = first.n;
    squaredNorm_ = dot(normal_, normal_);
    across_ = {-normal_[1], normal_[0]};
    const std::optional<Sign> normSign = certainSign(squaredNorm_);
    valid_ = normSign && *normSign == Sign::Positive;
    if (valid_) origin_ = {-first.w * normal_[0] / squaredNorm_, -first.w * normal_[1] / squaredNorm_};
  }

  bool valid() const { return valid_; }

  T position(const Vector<T>& p) const { return p[1] * normal_[0] - p[0] * normal_[1]; }

  T positionOfEnd(const PatchGeometry& patch, int k) const { return position(slice_.end(patch, k)); }

  /// Where the line of a patch not on the edge crosses L: n . d(m) + w = 0.
  std::optional<T> positionOfCrossing(const PatchGeometry& patch) const {
    const LineWithSlope<T> line = lineWithSlope(patch, slice_);
    return quotient<T>(-(dot(line.n, origin_) + line.w) * squaredNorm_, dot(line.n, across_));
  }

  struct Slope {
    T a, b;  // sigma' = a + m b
    int orientation;
  };

  std::optional<Slope> slopeOf(const PatchGeometry& patch) const {
    const LineWithSlope<T> line = lineWithSlope(patch, slice_);
    const T alongNormal = dot(line.n, normal_);
    const std::optional<Sign> orientation = certainSign(alongNormal);
    if (!orientation || *orientation == Sign::Zero) return std::nullopt;
    return Slope{-(dot(line.dn, origin_) + line.dw) / alongNormal,
                 -dot(line.dn, across_) / (squaredNorm_ * alongNormal), static_cast<int>(*orientation)};
  }

 private:
  Slice slice_;
  T squaredNorm_;
  Vector<T> normal_, across_, origin_;
  bool valid_ = false;
};

/// A side of the edge read at the edge's angle, its ends' positions in double
/// intervals.
template <class Slice>
struct SideAtAngle {
  EdgeSide side;
  const PatchSlab* slab;
  typename EdgeAtAngle<Slice>::Slope slope;
  Interval position0, position1;
  /// The named point of each of the slab's curves.
  std::vector<EdgePoint> crossings;
};

/// A named point's positions as read by the sides (their hull), with its first reading.
struct NamedPoint {
  Interval position;
  PointReading first;
};

/// The positions of the named points of the edge, in order along it, those that
/// are one point of the edge merged; nothing when two may be in either order.
std::optional<std::vector<Interval>> orderedPositions(const std::map<EdgePoint, NamedPoint>& named,
                                                      const AlgebraicAngle& edge,
                                                      const std::vector<PatchGeometry>& patches,
                                                      AngleAlgebra& algebra) {
  std::vector<const NamedPoint*> byLow;
  for (const auto& [point, reading] : named) byLow.push_back(&reading);
  std::sort(byLow.begin(), byLow.end(),
            [](const NamedPoint* a, const NamedPoint* b) { return a->position.lower() < b->position.lower(); });
  std::vector<Interval> positions;
  const NamedPoint* last = nullptr;
  for (const NamedPoint* next : byLow) {
    if (last && !(positions.back().upper() < next->position.lower())) {
      if (!onePointOfEdge(last->first, next->first, edge, patches, algebra)) return std::nullopt;
      positions.back() = hull(positions.back(), next->position);
      continue;
    }
    positions.push_back(next->position);
    last = next;
  }
  return positions;
}

/// The ray of a side over position m, if its segment reaches over m; nothing when
/// the slab's curves are not in the order of their points along the segment.
template <class Slice>
std::optional<std::optional<EdgeRay>> rayOver(const SideAtAngle<Slice>& side, double m,
                                              const std::map<EdgePoint, NamedPoint>& named) {
  const std::optional<bool> end0Below = certainlyBelow(side.position0, Interval(m));
  const std::optional<bool> end1Below = certainlyBelow(side.position1, Interval(m));
  if (!end0Below || !end1Below) return std::nullopt;
  if (*end0Below == *end1Below) return std::optional<EdgeRay>();
  // The gap holding m: the curves crossing the segment between end 0 and m.
  std::size_t gap = 0;
  for (std::size_t i = 0; i < side.crossings.size(); ++i) {
    const std::optional<bool> below = certainlyBelow(named.at(side.crossings[i]).position, Interval(m));
    if (!below) return std::nullopt;
    const bool beforeM = *below == *end0Below;
    if (beforeM && gap != i) return std::nullopt;
    gap += beforeM;
  }
  return std::optional<EdgeRay>(
      EdgeRay{side.side.below, side.slope.orientation, {side.side.patch, side.slab->faces[gap]}});
}

/// The cross-sections read in the slice's number type.
template <class Slice>
std::optional<EdgeCrossSections> crossSectionsAt(const Slice& slice, const HorizontalEdge& edge,
                                                 const std::vector<const PatchSlab*>& slabs,
                                                 const std::vector<PatchGeometry>& patches,
                                                 const std::vector<PatchCurve>& curves, AngleAlgebra& algebra) {
  using T = typename Slice::Number;
  const typename Slice::Rounding rounding;
  const EdgeAtAngle<Slice> at(edge, patches, slice);
  if (!at.valid()) return std::nullopt;
  std::vector<std::uint32_t> onEdge;
  for (const EdgeSide& side : edge.sides) onEdge.push_back(side.patch);
  std::vector<SideAtAngle<Slice>> sides;
  std::map<EdgePoint, NamedPoint> named;
  const auto name = [&named](const PointReading& reading, const Interval& position) {
    const auto [found, inserted] = named.try_emplace(reading.point, NamedPoint{position, reading});
    if (!inserted) found->second.position = hull(found->second.position, position);
  };
  for (std::size_t i = 0; i < edge.sides.size(); ++i) {
    const PatchGeometry& patch = patches[edge.sides[i].patch];
    const auto slope = at.slopeOf(patch);
    if (!slope) return std::nullopt;
    sides.push_back({edge.sides[i], slabs[i], *slope, toInterval(at.positionOfEnd(patch, 0)),
                     toInterval(at.positionOfEnd(patch, 1)), {}});
    name({spiralPointOf(patch, 0), edge.sides[i].patch, 0, 0}, sides.back().position0);
    name({spiralPointOf(patch, 1), edge.sides[i].patch, 1, 0}, sides.back().position1);
  }
  for (SideAtAngle<Slice>& side : sides) {
    for (std::uint32_t curve : side.slab->curves) {
      const std::uint32_t other = curves[curve].other(side.side.patch);
      const EdgePoint point = curvePointOf(side.side.patch, other, onEdge);
      side.crossings.push_back(point);
      const auto otherSide =
          std::find_if(sides.begin(), sides.end(), [&](const SideAtAngle<Slice>& s) { return s.side.patch == other; });
      // A crossing line, or equal slopes: a_i + m b_i = a_j + m b_j.
      const std::optional<T> position =
          point[0] == kCrossingLine ? at.positionOfCrossing(patches[other])
                                    : quotient<T>(otherSide->slope.a - side.slope.a, side.slope.b - otherSide->slope.b);
      if (!position) return std::nullopt;
      name({point, side.side.patch, -1, other}, toInterval(*position));
    }
  }
  const auto positions = orderedPositions(named, edge.angle, patches, algebra);
  if (!positions) return std::nullopt;
  EdgeCrossSections sections;
  for (std::size_t i = 0; i + 1 < positions->size(); ++i) {
    const double low = (*positions)[i].upper(), high = (*positions)[i + 1].lower();
    const double m = 0.5 * low + 0.5 * high;
    if (!(low < m && m < high)) return std::nullopt;
    std::vector<std::pair<Interval, EdgeRay>> rays;
    for (const SideAtAngle<Slice>& side : sides) {
      const auto ray = rayOver(side, m, named);
      if (!ray) return std::nullopt;
      if (*ray) rays.emplace_back(toInterval(side.slope.a + T(m) * side.slope.b), **ray);
    }
    // Up before down, each by decreasing slope.
    std::sort(rays.begin(), rays.end(), [](const auto& x, const auto& y) {
      if (x.second.below != y.second.below) return y.second.below;
      return x.first.lower() > y.first.lower();
    });
    std::vector<EdgeRay> counterclockwise;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      if (k > 0 && rays[k - 1].second.below == rays[k].second.below &&
          !(rays[k].first.upper() < rays[k - 1].first.lower())) {
        return std::nullopt;
      }
      counterclockwise.push_back(rays[k].second);
    }
    sections.push_back(std::move(counterclockwise));
  }
  return sections;
}

}  // namespace

std::optional<EdgeCrossSections> crossSectionsInIntervals(const HorizontalEdge& edge,
                                                          const std::vector<const PatchSlab*>& slabs,
                                                          const std::vector<PatchGeometry>& patches,
                                                          const std::vector<PatchCurve>& curves,
                                                          AngleAlgebra& algebra) {
  return crossSectionsAt(*slices::IntervalSlice::at(edge.angle), edge, slabs, patches, curves, algebra);
}

std::optional<EdgeCrossSections> crossSectionsInDoubleDoubles(const HorizontalEdge& edge,
                                                              const std::vector<const PatchSlab*>& slabs,
                                                              const std::vector<PatchGeometry>& patches,
                                                              const std::vector<PatchCurve>& curves,
                                                              AngleAlgebra& algebra) {
  const std::optional<slices::DoubleDoubleSlice> slice = slices::DoubleDoubleSlice::at(edge.angle);
  if (!slice) return std::nullopt;
  return crossSectionsAt(*slice, edge, slabs, patches, curves, algebra);
}

}  // namespace freespace::gluing
