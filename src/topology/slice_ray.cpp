#include "freespace/topology/slice_ray.h"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <stdexcept>

#include "slice_pieces.h"

namespace freespace {

namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BoxPoint = bg::model::point<double, 3, bg::cs::cartesian>;
using Box = bg::model::box<BoxPoint>;
using BoxEntry = std::pair<Box, std::uint32_t>;
using slices::Point;

/// Padding of a query's angle: far more than the error of a rational angle's radians.
constexpr double kAnglePad = 1e-9;

/// A candidate met by the ray: the patch, where along the ray (signed distance
/// from the start) and where along its segment.
struct Crossing {
  std::uint32_t patch;
  Rational distance;
  Rational lambda;
  bool alongSegment;
};

}  // namespace

struct SliceRays::Impl {
  const Arrangement& arrangement;
  AngleAlgebra& algebra;
  bgi::rtree<BoxEntry, bgi::rstar<16>> tree;

  Impl(const Arrangement& a, AngleAlgebra& alg) : arrangement(a), algebra(alg) {
    std::vector<BoxEntry> entries;
    for (std::uint32_t i = 0; i < arrangement.patches.size(); ++i) {
      for (const PatchBox& box : patchBoxes(arrangement.patches[i])) {
        entries.emplace_back(Box(BoxPoint(box.low[0], box.low[1], box.low[2]), BoxPoint(box.high[0], box.high[1], box.high[2])), i);
      }
    }
    tree = bgi::rtree<BoxEntry, bgi::rstar<16>>(entries.begin(), entries.end());
  }

  /// The patches whose boxes the ray's box meets (the boxes are padded far beyond
  /// the rounding of the query's doubles, see patchBoxes).
  std::vector<std::uint32_t> candidates(const AlgebraicAngle& angle, const Point& from, int direction) const {
    const double theta = std::remainder(angle.radians(), 2 * M_PI);
    const double x = from[0].convert_to<double>(), y = from[1].convert_to<double>();
    const double pad = 1e-9 * (1 + std::fabs(x) + std::fabs(y)), huge = std::numeric_limits<double>::max();
    std::vector<BoxEntry> found;
    // Boxes stop at theta = +-pi: near it, look on both sides.
    for (const double at : {theta, theta - 2 * M_PI, theta + 2 * M_PI}) {
      if (at < -M_PI - kAnglePad || at > M_PI + kAnglePad) continue;
      const Box query(BoxPoint(direction > 0 ? x - pad : -huge, y - pad, at - kAnglePad),
                      BoxPoint(direction > 0 ? huge : x + pad, y + pad, at + kAnglePad));
      tree.query(bgi::intersects(query), std::back_inserter(found));
    }
    std::vector<std::uint32_t> patches;
    for (const BoxEntry& entry : found) patches.push_back(entry.second);
    std::sort(patches.begin(), patches.end());
    patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
    return patches;
  }

  /// Where the ray y = from.y, x = from.x + direction * distance (distance >= 0)
  /// meets the patch's segment, if it does.
  static std::optional<Crossing> crossing(std::uint32_t patch, const Point& end0, const Point& end1, const Point& from,
                                          int direction) {
    const Rational dy0 = end0[1] - from[1], dy1 = end1[1] - from[1];
    if ((dy0 > 0 && dy1 > 0) || (dy0 < 0 && dy1 < 0)) return std::nullopt;
    if (dy0 == 0 && dy1 == 0) {
      const Rational d0 = direction * (end0[0] - from[0]), d1 = direction * (end1[0] - from[0]);
      if (d0 < 0 && d1 < 0) return std::nullopt;
      return Crossing{patch, std::max(Rational(0), std::min(d0, d1)), 0, true};
    }
    const Rational lambda = dy0 / (dy0 - dy1);
    const Rational x = end0[0] + lambda * (end1[0] - end0[0]);
    const Rational distance = direction * (x - from[0]);
    if (distance < 0) return std::nullopt;
    return Crossing{patch, distance, lambda, false};
  }
};

SliceRays::SliceRays(const Arrangement& arrangement, AngleAlgebra& algebra)
    : impl_(std::make_unique<Impl>(arrangement, algebra)) {}

SliceRays::~SliceRays() = default;

RayHit SliceRays::cast(const AlgebraicAngle& rationalAngle, const Point& from, int direction) const {
  if (!rationalAngle.isRational()) throw std::invalid_argument("SliceRays::cast: the angle must be rational");
  const Arrangement& arrangement = impl_->arrangement;
  const auto [cosine, sine] = exactCosSin(rationalAngle);
  std::optional<Crossing> first;
  bool tie = false;
  for (std::uint32_t patch : impl_->candidates(rationalAngle, from, direction)) {
    if (!impl_->algebra.contains(arrangement.patches[patch].patch.range, rationalAngle)) continue;
    const slices::ExactSegment segment = slices::segmentAt(arrangement.patches[patch], cosine, sine);
    const std::optional<Crossing> found = Impl::crossing(patch, segment.end0, segment.end1, from, direction);
    if (!found) continue;
    if (!first || found->distance < first->distance) {
      first = found;
      tie = false;
    } else if (found->distance == first->distance) {
      tie = true;
    }
  }
  RayHit hit;
  if (!first) return hit;
  if (first->distance == 0) {
    hit.kind = RayHit::Kind::OnSegment;
    return hit;
  }
  hit.kind = RayHit::Kind::Degenerate;
  if (tie || first->alongSegment || first->lambda == 0 || first->lambda == 1) return hit;
  const PatchSlab* slab = slabAt(arrangement.subdivisions[first->patch], rationalAngle, impl_->algebra);
  if (!slab) return hit;  // the angle is an event of the patch
  const slices::ExactSegment own = slices::segmentAt(arrangement.patches[first->patch], cosine, sine);
  std::size_t gap = 0;
  for (std::uint32_t curve : slab->curves) {
    const std::uint32_t other = arrangement.curves[curve].other(first->patch);
    const Rational lambda = slices::crossingLambda(own, slices::segmentAt(arrangement.patches[other], cosine, sine));
    if (lambda == first->lambda) return hit;  // through a curve's crossing
    gap += lambda < first->lambda;
  }
  hit.kind = RayHit::Kind::SubFace;
  hit.face = {first->patch, slab->faces[gap]};
  hit.point = {from[0] + direction * first->distance, from[1]};
  // The ray arrives from the side of the start.
  hit.fromPositiveSide = own.valueAt(from) > 0;
  return hit;
}

}  // namespace freespace
