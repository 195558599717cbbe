#include "clearance_boxes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <tuple>

#include "contact_point.h"
#include "every_core.h"
#include "freespace/geometry/patch_segment.h"
#include "freespace/numbers/angle_reduction.h"
#include "freespace/numbers/half_angle.h"
#include "freespace/numbers/interval.h"
#include "freespace/space/motion_checker.h"
#include "freespace/topology/slice_pieces.h"

namespace freespace {

namespace {

/// How many parts halving along the axes of `axes` (bit k for axis k) makes.
std::uint32_t partCount(std::uint8_t axes) {
  std::uint32_t count = 1;
  for (int axis = 0; axis < 3; ++axis) count <<= axes >> axis & 1;
  return count;
}

/// The turn between two angles of [-pi, pi] the shorter way round (|remainder(a - b,
/// 2 pi)| within rounding, which the bounds' slack covers; std::remainder in general).
double turnBetween(double a, double b) {
  const double apart = std::fabs(a - b);
  if (apart > 2 * M_PI) return std::fabs(std::remainder(a - b, 2 * M_PI));
  return std::min(apart, 2 * M_PI - apart);
}

/// `count` + 1 edges from `low` to `high`, the last exactly `high` (boxes that touch
/// share their edges' values exactly, and halving keeps them exact).
std::vector<double> edgesBetween(double low, double high, int count) {
  std::vector<double> edges(count + 1);
  for (int i = 0; i < count; ++i) edges[i] = low + (high - low) * i / count;
  edges[count] = high;
  return edges;
}

/// The index of the interval between consecutive edges that holds `value` (clamped).
std::size_t intervalOf(const std::vector<double>& edges, double value) {
  const auto above = std::upper_bound(edges.begin(), edges.end(), value);
  const std::ptrdiff_t index = (above - edges.begin()) - 1;
  return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(index, 0, static_cast<std::ptrdiff_t>(edges.size()) - 2));
}

bool closedOverlap(double lowA, double highA, double lowB, double highB) { return lowA <= highB && lowB <= highA; }

void addAnchors(const std::vector<ClearanceAnchor>& anchors, std::vector<const ClearanceAnchor*>& candidates) {
  for (const ClearanceAnchor& anchor : anchors) candidates.push_back(&anchor);
}

/// A box's (x, y) corners, in order: (low, low), (low, high), (high, low), (high, high).
using CornerValues = std::array<double, 4>;

/// The bound a segment anchor gives at each (x, y) corner of a box whose angles lie
/// within `turn` of the anchor's: the distance to the segment's point nearest the
/// corner plus the lever there times the turn. The least over the segment's points of
/// that sum is convex in (x, y) (the distance and the lever's norm are of affine
/// functions of (x, y) and the fraction along the segment), so its most over the
/// rectangle lies at a corner (rounding left to the caller).
CornerValues segmentBounds(const ClearanceAnchor& anchor, const ClearanceBox& box, double turn) {
  const double length2 = anchor.along[0] * anchor.along[0] + anchor.along[1] * anchor.along[1];
  CornerValues values{};
  int corner = 0;
  for (const double x : {box.low[0], box.high[0]}) {
    for (const double y : {box.low[1], box.high[1]}) {
      const double dx = x - anchor.at[0], dy = y - anchor.at[1];
      const double t = std::clamp((dx * anchor.along[0] + dy * anchor.along[1]) / length2, 0.0, 1.0);
      const double leverX = anchor.contactFrom[0] + t * anchor.contactAlong[0];
      const double leverY = anchor.contactFrom[1] + t * anchor.contactAlong[1];
      const double apartX = dx - t * anchor.along[0], apartY = dy - t * anchor.along[1];
      values[corner++] = std::sqrt(apartX * apartX + apartY * apartY) +
                         std::sqrt(leverX * leverX + leverY * leverY) * (1 + 1e-12) * turn;
    }
  }
  return values;
}

/// The least, over lambda in [0, 1], of the most over the corners of lambda a +
/// (1 - lambda) b, for two anchors' bounds at a box's corners: the clearance is at
/// most the least of the two bounds, so at most any such mix of them, which is convex
/// in (x, y) and so largest at a corner (docs/design.md section 7). The most over the
/// corners is convex and piecewise linear in lambda: least at an end or where two
/// corners' lines cross.
double mixedBound(const CornerValues& a, const CornerValues& b) {
  const auto most = [&](double lambda) {
    double value = -HUGE_VAL;
    for (int corner = 0; corner < 4; ++corner) value = std::max(value, b[corner] + lambda * (a[corner] - b[corner]));
    return value;
  };
  double least = std::min(most(0), most(1));
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      const double slopes = (a[i] - b[i]) - (a[j] - b[j]);
      if (slopes == 0) continue;
      const double lambda = (b[j] - b[i]) / slopes;
      if (lambda > 0 && lambda < 1) least = std::min(least, most(lambda));
    }
  }
  // Rounded up: the mix's rounding is a few ulps of the largest value mixed.
  double largest = 0;
  for (int corner = 0; corner < 4; ++corner) largest = std::max({largest, std::fabs(a[corner]), std::fabs(b[corner])});
  return least * (1 + 1e-12) + 8 * std::numeric_limits<double>::epsilon() * largest;
}

/// Whether the segment from `from` to `to` meets the rectangle [low, high] (clipped
/// to it, Liang and Barsky's way).
bool segmentMeetsRectangle(const std::array<double, 2>& from, const std::array<double, 2>& to,
                           const std::array<double, 2>& low, const std::array<double, 2>& high) {
  double enter = 0, leave = 1;
  for (int axis = 0; axis < 2; ++axis) {
    const double along = to[axis] - from[axis];
    for (const double limit : {low[axis], high[axis]}) {
      // Inside this side of the limit: (point - limit) has the sign `inward`.
      const double inward = limit == low[axis] ? 1 : -1, start = inward * (from[axis] - limit);
      const double rate = inward * along;
      if (rate == 0) {
        if (start < 0) return false;
        continue;
      }
      const double crossing = -start / rate;
      if (rate > 0) {
        enter = std::max(enter, crossing);
      } else {
        leave = std::min(leave, crossing);
      }
    }
  }
  return enter <= leave;
}

/// Whether the part [lambdas[0], lambdas[1]] of a patch's segment (its two features
/// touching) may pass through the (x, y) rectangle of `query` at an angle within
/// `turn` of the angle of `slice` (inside a RoundingScope): each point of it moves no
/// farther than its ends' largest turning radius times the turn (docs/design.md
/// section 3: each end is u + R v, and so is each point between), so it may only
/// where that part meets the rectangle widened by as much.
bool segmentMayMeet(const PatchGeometry& patch, const slices::SliceIn<Interval>& slice, double turn,
                    const PatchBox& query, const std::array<double, 2>& lambdas) {
  std::array<std::array<double, 2>, 2> ends;
  double error = 0, lever = 0;
  for (int end = 0; end < 2; ++end) {
    const Spiral<Interval> spiral = spiralOf<Interval>(patch.ends[end]);
    lever = std::max(lever, sqrt(spiral.vx * spiral.vx + spiral.vy * spiral.vy).upper());
    const std::array<Interval, 2> point = slice.pointOn(patch, Interval(lambdas[end]));
    for (int axis = 0; axis < 2; ++axis) {
      ends[end][axis] = point[axis].midpoint();
      error = std::max(error, point[axis].upper() - point[axis].lower());
    }
  }
  if (!std::isfinite(error + lever)) return true;
  // Widened by the turn, the ends' placing and the clipping's rounding.
  double magnitude = 0;
  for (int axis = 0; axis < 2; ++axis) {
    magnitude +=
        std::fabs(ends[0][axis]) + std::fabs(ends[1][axis]) + std::fabs(query.low[axis]) + std::fabs(query.high[axis]);
  }
  const double widening = (lever * turn + error) * (1 + 1e-9) + 1e-12 * magnitude;
  return segmentMeetsRectangle(ends[0], ends[1], {query.low[0] - widening, query.low[1] - widening},
                               {query.high[0] + widening, query.high[1] + widening});
}

/// The angles of a slab (its ends' enclosures included, and more than their
/// conversion's rounding), counterclockwise from `from` to `to`; the whole circle
/// for a slab from an event round to it (or without events).
AngleArc arcOf(const PatchSlab& slab, AngleAlgebra& algebra) {
  const bool nearEnds = slab.from.chart() == slab.to.chart() && slab.from.lower() <= slab.to.upper() &&
                        slab.to.lower() <= slab.from.upper();
  if (nearEnds && algebra.compare(slab.from, slab.to) == 0) return {-M_PI, M_PI, true};
  constexpr double kPad = 1e-9;
  const double from = HalfAngle{slab.from.chart(), slab.from.lower()}.radians();
  const double to = HalfAngle{slab.to.chart(), slab.to.upper()}.radians();
  // Nearly round the circle: padded, the ends would pass each other.
  double gap = from - to;
  if (gap < 0) gap += 2 * M_PI;
  if (gap < 4 * kPad) return {-M_PI, M_PI, true};
  return {from - kPad, to + kPad, false};
}

/// The parts of [low, high] (a range of [-pi, pi]) an arc holds: none, one, or two
/// (an arc across theta = pi).
std::vector<std::array<double, 2>> partsWithin(const AngleArc& arc, double low, double high) {
  std::vector<std::array<double, 2>> parts;
  const auto add = [&](double from, double to) {
    from = std::max(from, low);
    to = std::min(to, high);
    if (from <= to) parts.push_back({from, to});
  };
  if (arc.whole) {
    add(low, high);
  } else if (arc.from <= arc.to) {
    add(arc.from, arc.to);
  } else {
    add(-HUGE_VAL, arc.to);
    add(arc.from, HUGE_VAL);
  }
  return parts;
}

/// Cosines and sines enclosing those of every angle of [low, high] (a range of
/// [-pi, pi]; inside a RoundingScope).
slices::SliceIn<Interval> sliceOver(double low, double high) {
  constexpr double kRoom = 1e-15;  // more than the library's error and pi's rounding
  const auto reaches = [&](double angle) { return low <= angle + kRoom && angle - kRoom <= high; };
  double cosineLow = std::min(std::cos(low), std::cos(high)), cosineHigh = std::max(std::cos(low), std::cos(high));
  double sineLow = std::min(std::sin(low), std::sin(high)), sineHigh = std::max(std::sin(low), std::sin(high));
  if (reaches(0)) cosineHigh = 1;
  if (reaches(M_PI) || reaches(-M_PI)) cosineLow = -1;
  if (reaches(M_PI / 2)) sineHigh = 1;
  if (reaches(-M_PI / 2)) sineLow = -1;
  slices::SliceIn<Interval> slice;
  slice.cosine = Interval(std::max(-1.0, cosineLow - kRoom), std::min(1.0, cosineHigh + kRoom));
  slice.sine = Interval(std::max(-1.0, sineLow - kRoom), std::min(1.0, sineHigh + kRoom));
  return slice;
}

}  // namespace

ClearanceBoxes::ClearanceBoxes(const FreeSpace& space, const std::array<double, 2>& low,
                               const std::array<double, 2>& high, double reach, int across)
    : space_(space), reach_(reach), freeSlabs_(space.arrangement().patches.size()) {
  // Its own predicates: the free space's other queries may run meanwhile.
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  const Arrangement& arrangement = space.arrangement();
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    const PatchSubdivision& subdivision = arrangement.subdivisions[patch];
    std::vector<bool> faceBoundsFree(subdivision.faceCount);
    for (std::uint32_t face = 0; face < faceBoundsFree.size(); ++face) {
      faceBoundsFree[face] = space.cellOfSubFace({patch, face}).has_value();
    }
    const auto boundsFree = [&](std::uint32_t face) { return faceBoundsFree[face]; };
    for (std::uint32_t index = 0; index < subdivision.slabs.size(); ++index) {
      const std::vector<std::uint32_t>& faces = subdivision.slabs[index].faces;
      const auto first = std::find_if(faces.begin(), faces.end(), boundsFree);
      if (first == faces.end()) continue;
      const auto last = std::find_if(faces.rbegin(), faces.rend(), boundsFree);
      freeSlabs_[patch].push_back({arcOf(subdivision.slabs[index], algebra), index,
                                   static_cast<std::uint32_t>(first - faces.begin()),
                                   static_cast<std::uint32_t>(faces.rend() - last - 1)});
    }
  }
  const double side = std::max(high[0] - low[0], high[1] - low[1]) / across;
  const int countX = std::max(1, static_cast<int>(std::ceil((high[0] - low[0]) / side)));
  const int countY = std::max(1, static_cast<int>(std::ceil((high[1] - low[1]) / side)));
  // At least four across theta, so that a box's theta range is shorter than half a
  // turn and a motion between two of its configurations stays inside it.
  const int countTheta = std::clamp(static_cast<int>(std::ceil(2 * M_PI * reach / side)), 4, 4 * across);
  rootEdges_ = {edgesBetween(low[0], high[0], countX), edgesBetween(low[1], high[1], countY),
                edgesBetween(-M_PI, M_PI, countTheta)};
  // Column by column in theta (on every core), each box's contact looked for near its
  // neighbour's in the column.
  const std::size_t count = static_cast<std::size_t>(countX) * countY * countTheta;
  for (std::size_t box = 0; box < count; ++box) boxes_.push_back({});
  const auto measureColumn = [&](std::size_t column) {
    const int i = static_cast<int>(column) / countY, j = static_cast<int>(column) % countY;
    for (int k = 0; k < countTheta; ++k) {
      const std::array<double, 3> boxLow{rootEdges_[0][i], rootEdges_[1][j], rootEdges_[2][k]},
          boxHigh{rootEdges_[0][i + 1], rootEdges_[1][j + 1], rootEdges_[2][k + 1]};
      const std::size_t index = column * countTheta + k;
      const double expected = k == 0 ? HUGE_VAL : expectedClearance(boxes_[index - 1], boxLow, boxHigh);
      boxes_[index] = measured(boxLow, boxHigh, expected, std::nullopt);
    }
  };
  const auto always = [] { return true; };
  onEveryCore(static_cast<std::size_t>(countX) * countY, always, measureColumn);
  // Neighbours among the first boxes: those at most one step away along each axis
  // (theta wrapping around).
  for (int i = 0; i < countX; ++i) {
    for (int j = 0; j < countY; ++j) {
      for (int k = 0; k < countTheta; ++k) {
        const std::uint32_t index = (i * countY + j) * countTheta + k;
        for (int di = -1; di <= 1; ++di) {
          for (int dj = -1; dj <= 1; ++dj) {
            for (int dk = -1; dk <= 1; ++dk) {
              const int ni = i + di, nj = j + dj, nk = (k + dk + countTheta) % countTheta;
              if (ni < 0 || ni >= countX || nj < 0 || nj >= countY) continue;
              const std::uint32_t other = (ni * countY + nj) * countTheta + nk;
              auto& list = boxes_[index].neighbours;
              if (other != index && std::find(list.begin(), list.end(), other) == list.end()) list.push_back(other);
            }
          }
        }
      }
    }
  }
  // Each box bounded from its own anchors and its neighbours' (on every core: a box's
  // bound is written to it alone).
  onEveryCore(boxes_.size(), always, [&](std::size_t index) {
    ClearanceBox& box = boxes_[index];
    std::vector<const ClearanceAnchor*> candidates;
    addAnchors(box.own, candidates);
    for (std::uint32_t neighbour : box.neighbours) addAnchors(boxes_[neighbour].own, candidates);
    BoundScratch scratch;
    bound(box, candidates, scratch);
    settleBlocked(box);
  });
}

double ClearanceBoxes::moveBetween(const ClearanceAnchor& centre, const std::array<double, 3>& low,
                                   const std::array<double, 3>& high) const {
  const double turn = turnBetween(0.5 * (low[2] + high[2]), centre.at[2]);
  return std::hypot(0.5 * (low[0] + high[0]) - centre.at[0], 0.5 * (low[1] + high[1]) - centre.at[1]) + reach_ * turn;
}

double ClearanceBoxes::expectedClearance(const ClearanceBox& known, const std::array<double, 3>& low,
                                         const std::array<double, 3>& high) const {
  if (known.own.empty()) return HUGE_VAL;
  return std::fabs(known.own.front().upper) + moveBetween(known.own.front(), low, high);
}

std::optional<Location> ClearanceBoxes::certifiedLocation(const ClearanceBox& known, const std::array<double, 3>& low,
                                                          const std::array<double, 3>& high) const {
  if (!known.centreCell || known.own.empty()) return std::nullopt;
  const ClearanceAnchor& centre = known.own.front();
  // Rounded up, with room for the centres' rounding.
  const double reached =
      moveBetween(centre, low, high) * (1 + 1e-9) + 1e-12 * (1 + std::fabs(centre.at[0]) + std::fabs(centre.at[1]));
  if (!(known.centreLower > reached)) return std::nullopt;
  return Location{true, *known.centreCell};
}

ClearanceBox ClearanceBoxes::measured(const std::array<double, 3>& low, const std::array<double, 3>& high,
                                      double expected, const std::optional<Location>& location) const {
  ClearanceBox box;
  box.low = low;
  box.high = high;
  const Pose2 centre = ClearanceBoxes::centre(box);
  const Clearance clearance = space_.clearance(centre, MotionChecker::kClearanceWidth, expected, location);
  box.centreLower = clearance.lower;
  // The farthest a configuration of the box is from its centre in |dxy| + r |dtheta|,
  // rounded up (with room for the centre's rounding and for the sliver between the
  // doubles nearest -pi and pi).
  const double across = std::hypot(high[0] - low[0], high[1] - low[1]) / 2 * (1 + 1e-12) +
                        reach_ * ((high[2] - low[2]) / 2 * (1 + 1e-12) + 1e-15) +
                        1e-13 * (1 + std::fabs(centre.x) + std::fabs(centre.y));
  box.lower = clearance.lower - across;
  box.upper = HUGE_VAL;
  if (clearance.location.free) box.centreCell = clearance.location.cell;
  const double upper = clearance.upper;
  if (std::isfinite(upper)) {
    box.own.reserve(3);
    box.own.push_back({{centre.x, centre.y, centre.theta}, upper, reach_});
    box.upper = upperBoundFrom(box.own.back(), box);
    if (clearance.contact) {
      // The contact reached: clearance 0 but for the rounding of its position.
      const double rounding = (clearance.upper - clearance.lower) +
                              1e-12 * (1 + std::fabs(upper) + std::fabs(centre.x) + std::fabs(centre.y));
      box.own.push_back({{clearance.nearest[0], clearance.nearest[1], centre.theta},
                         rounding,
                         std::min(reach_, contactLever(clearance, centre.theta, rounding) * (1 + 1e-9) + rounding)});
      // Its whole patch: it bounds the boxes along a wall however far they lie along it.
      if (const std::optional<ClearanceAnchor> segment = contactSegment(clearance, centre.theta)) {
        box.own.push_back(*segment);
      }
    }
  }
  // Free throughout at a positive clearance, no boundary meets it. A blocked box is
  // looked at once bounded (settleBlocked); one free at its centre only when another
  // cell is asked of it (dropOutside): in the cell of a query, whether a boundary meets
  // it changes nothing.
  box.unbroken = box.lower > 0;
  return box;
}

void ClearanceBoxes::settleBlocked(ClearanceBox& box) const {
  // Below the level, the next drop takes the box whether or not a boundary meets it
  // (42,000 tests on the maze otherwise, 40% of them unbroken).
  if (box.centreCell || box.unbroken || box.upper < droppedBelow_) return;
  box.unbroken = !meetsFreeBoundary(box);
  // Blocked throughout: no clearance above 0 anywhere in it (the Lipschitz bound
  // across angles leaves room for pockets that no boundary here could enclose).
  if (box.unbroken) box.upper = std::min(box.upper, 0.0);
}

// Turned about its axis at a fixed (x, y), the robot's point in the contact moves by
// at most its distance from the axis times the angle; translating the robot back by
// that much puts the point where the contact was, touching again. An edge's point
// moves no faster than its farther end (the bound where the crossing is not known
// well: edges nearly parallel).
double ClearanceBoxes::contactLever(const Clearance& clearance, double theta, double slack) const {
  const std::optional<ContactPoint> point = contactPoint(space_, clearance, theta, slack);
  const double known = point ? std::hypot(point->fromAxis[0], point->fromAxis[1]) + point->error : HUGE_VAL;
  if (clearance.contact->kind != ContactKind::EdgeEdge) return known;
  const PerturbedMeshes& meshes = space_.meshes();
  const auto fromAxis = [&](std::uint32_t vertex) {
    const Point3& p = meshes.robot.vertices()[vertex];
    return std::hypot(p.x(), p.y()) / meshes.scale;
  };
  return std::min(known, std::max(fromAxis(clearance.contactVertices[0]), fromAxis(clearance.contactVertices[1])));
}

// A patch's segment at a fixed angle is where its two features touch (docs/design.md
// section 3). Each end is a spiral u + R v (a vertex of one body on an edge of the
// other), v minus the robot's point in the contact; between them the robot's point
// moves along the robot's feature in step with the place along the segment (both
// affine in the fraction along it), so at the fraction t it is minus
// contactFrom + t contactAlong.
std::optional<ClearanceAnchor> ClearanceBoxes::contactSegment(const Clearance& clearance, double theta) const {
  const PatchGeometry& patch = space_.arrangement().patches[clearance.contactPatch];
  const double scale = space_.meshes().scale;
  const RoundingScope rounding;
  slices::SliceIn<Interval> slice;
  HalfAngle::fromRadians(theta).cosSin(slice.cosine, slice.sine);
  std::array<std::array<double, 2>, 2> ends, contacts;
  double error = 0, leverError = 0;
  for (int end = 0; end < 2; ++end) {
    const Spiral<Interval> spiral = spiralOf<Interval>(patch.ends[end]);
    const std::array<Interval, 2> point = slice.end(patch, end), contact{spiral.vx, spiral.vy};
    for (int axis = 0; axis < 2; ++axis) {
      ends[end][axis] = point[axis].midpoint() / scale;
      error = std::max(error, (point[axis].upper() - point[axis].lower()) / scale);
      contacts[end][axis] = contact[axis].midpoint() / scale;
      leverError = std::max(leverError, (contact[axis].upper() - contact[axis].lower()) / scale);
    }
  }
  // (A segment too short to tell its direction is left to the contact's point.)
  const double alongX = ends[1][0] - ends[0][0], alongY = ends[1][1] - ends[0][1];
  if (!(error + leverError < HUGE_VAL) || error > 1e-3 * reach_ || !(std::hypot(alongX, alongY) > 1e-9 * reach_)) {
    return std::nullopt;
  }
  // Every point of the segment between the rounded ends lies within `error` of the
  // patch's (each end within half of it along each axis), and every lever within
  // `leverError` of the true one, which the turn (at most pi) multiplies.
  const double magnitude =
      1 + std::fabs(ends[0][0]) + std::fabs(ends[0][1]) + std::fabs(ends[1][0]) + std::fabs(ends[1][1]) + reach_;
  const double lever = std::max(std::hypot(contacts[0][0], contacts[0][1]), std::hypot(contacts[1][0], contacts[1][1]));
  return ClearanceAnchor{{ends[0][0], ends[0][1], theta},
                         error + 4 * leverError + 1e-12 * magnitude,
                         std::min(reach_, lever * (1 + 1e-9) + leverError),
                         {alongX, alongY},
                         contacts[0],
                         {contacts[1][0] - contacts[0][0], contacts[1][1] - contacts[0][1]}};
}

CornerValues ClearanceBoxes::cornerBounds(const ClearanceAnchor& anchor, const ClearanceBox& box) const {
  // Along theta, the farthest point of the box's range from the anchor's angle round
  // the circle: half a turn when the range holds the opposite angle.
  const double opposite = anchor.at[2] > 0 ? anchor.at[2] - M_PI : anchor.at[2] + M_PI;
  double turn = M_PI;
  if (opposite < box.low[2] || opposite > box.high[2]) {
    turn = std::max(turnBetween(anchor.at[2], box.low[2]), turnBetween(anchor.at[2], box.high[2]));
  }
  // A blocked anchor (upper < 0) bounds the slice at its angle by the signed
  // clearance's Lipschitz bound, but only down to 0: across angles only the free side
  // is Lipschitz (docs/design.md section 7).
  const double rounding = 1e-13 * (1 + std::fabs(anchor.upper) + std::fabs(anchor.at[0]) + std::fabs(anchor.at[1]) +
                                   std::fabs(anchor.along[0]) + std::fabs(anchor.along[1]));
  const double paddedTurn = turn * (1 + 1e-12) + 1e-15;
  if (anchor.along[0] != 0 || anchor.along[1] != 0) {
    // A contact's segment: clearance at most 0 but for its rounding, in `upper`.
    CornerValues values = segmentBounds(anchor, box, paddedTurn);
    for (double& value : values) value = anchor.upper + value * (1 + 1e-12) + rounding;
    return values;
  }
  CornerValues values{};
  int corner = 0;
  for (const double x : {box.low[0], box.high[0]}) {
    for (const double y : {box.low[1], box.high[1]}) {
      const double dx = x - anchor.at[0], dy = y - anchor.at[1];
      const double inSlice = std::max(0.0, anchor.upper + std::sqrt(dx * dx + dy * dy) * (1 + 1e-12));
      values[corner++] = inSlice + anchor.lever * paddedTurn + rounding;
    }
  }
  return values;
}

double ClearanceBoxes::upperBoundFrom(const ClearanceAnchor& anchor, const ClearanceBox& box) const {
  const CornerValues values = cornerBounds(anchor, box);
  return *std::max_element(values.begin(), values.end());
}

void ClearanceBoxes::bound(ClearanceBox& box, const std::vector<const ClearanceAnchor*>& candidates,
                           BoundScratch& scratch) const {
  constexpr std::size_t kAnchorsKept = 6;
  std::vector<CornerValues>& corners = scratch.corners;
  std::vector<std::pair<double, std::uint32_t>>& bounds = scratch.bounds;
  corners.clear();
  bounds.clear();
  box.anchors.clear();
  for (std::uint32_t k = 0; k < candidates.size(); ++k) {
    corners.push_back(cornerBounds(*candidates[k], box));
    bounds.push_back({*std::max_element(corners.back().begin(), corners.back().end()), k});
    // Below the level boxes are dropped below, the next drop takes the box (the level
    // only rises in a path query): its least bound changes nothing.
    if (bounds.back().first < droppedBelow_) {
      box.upper = std::min(box.upper, bounds.back().first);
      return;
    }
  }
  // The best distinct ones (halves share their parent's contact segments), sorted a
  // few more at a time while equal ones fill the places.
  const auto same = [](const ClearanceAnchor& a, const ClearanceAnchor& b) {
    return a.at == b.at && a.along == b.along && a.upper == b.upper;
  };
  box.anchors.reserve(std::min(kAnchorsKept, bounds.size()));
  std::array<std::uint32_t, kAnchorsKept> kept{};
  for (std::size_t k = 0, sorted = 0; k < bounds.size() && box.anchors.size() < kAnchorsKept; ++k) {
    if (k == sorted) {
      sorted = std::min(bounds.size(), k + 2 * kAnchorsKept);
      std::partial_sort(bounds.begin() + static_cast<std::ptrdiff_t>(k),
                        bounds.begin() + static_cast<std::ptrdiff_t>(sorted), bounds.end());
    }
    const ClearanceAnchor& candidate = *candidates[bounds[k].second];
    if (!box.anchors.empty() && same(box.anchors.back(), candidate)) continue;
    kept[box.anchors.size()] = bounds[k].second;
    box.anchors.push_back(candidate);
  }
  if (bounds.empty()) return;
  box.upper = std::min(box.upper, bounds.front().first);
  // Two anchors at once, the best with each other kept: across a passage between two
  // walls, their mix bounds the box by about the passage's clearance however wide it
  // is in (x, y) (mixing every pair took the maze 1.6 s instead of 1.3).
  for (std::size_t k = 1; k < box.anchors.size(); ++k) {
    box.upper = std::min(box.upper, mixedBound(corners[kept[0]], corners[kept[k]]));
  }
}

Pose2 ClearanceBoxes::centre(const ClearanceBox& box) {
  return {0.5 * (box.low[0] + box.high[0]), 0.5 * (box.low[1] + box.high[1]), 0.5 * (box.low[2] + box.high[2])};
}

bool ClearanceBoxes::meetsFreeBoundary(const ClearanceBox& box) const {
  const double scale = space_.meshes().scale;
  // In the construction's coordinates, padded by far more than the rounding.
  PatchBox query;
  for (int axis = 0; axis < 3; ++axis) {
    const double factor = axis < 2 ? scale : 1.0;
    const double pad = 1e-12 * (1 + std::fabs(box.low[axis]) + std::fabs(box.high[axis]));
    query.low[axis] = (box.low[axis] - pad) * factor;
    query.high[axis] = (box.high[axis] + pad) * factor;
  }
  const Arrangement& arrangement = space_.arrangement();
  const RoundingScope rounding;
  for (std::uint32_t patch : arrangement.boxIndex->meeting(query)) {
    // Each slab with such sub-faces over its own part of the box's angles (their
    // union over the slabs is often the whole segment where each slab's is a piece).
    for (const FreeSlab& free : freeSlabs_[patch]) {
      for (const std::array<double, 2>& angles : partsWithin(free.arc, box.low[2], box.high[2])) {
        if (slabMayMeet(patch, free, angles, query, kAngleHalvings)) return true;
      }
    }
  }
  return false;
}

bool ClearanceBoxes::slabMayMeet(std::uint32_t patch, const FreeSlab& free, const std::array<double, 2>& angles,
                                 const PatchBox& query, int halvings) const {
  const Arrangement& arrangement = space_.arrangement();
  const PatchGeometry& geometry = arrangement.patches[patch];
  // The slice at the rational angle nearest the middle of the angles (within about
  // 1e-16 rad of it): the turn to their farther end, padded by far more than that.
  slices::SliceIn<Interval> slice;
  HalfAngle::fromRadians(0.5 * (angles[0] + angles[1])).cosSin(slice.cosine, slice.sine);
  const double turn = 0.5 * (angles[1] - angles[0]) + 1e-12;
  if (!segmentMayMeet(geometry, slice, turn, query, {0, 1})) return false;
  // Along the segment, the sub-faces that bound a free cell lie between the crossings
  // of the slab's curves, which over the angles lie in the intervals found with the
  // angles' cosines and sines in intervals.
  const slices::SliceIn<Interval> range = sliceOver(angles[0], angles[1]);
  const PatchSlab& slab = arrangement.subdivisions[patch].slabs[free.slab];
  const auto crossing = [&](std::uint32_t curve) {
    return range.crossingLambda(geometry, arrangement.patches[arrangement.curves[curve].other(patch)]);
  };
  double low = 0, high = 1;
  bool wide = false;  // a crossing known too loosely to place the piece
  if (free.firstGap > 0) {
    const std::optional<Interval> below = crossing(slab.curves[free.firstGap - 1]);
    if (below && below->lower() > 0) low = below->lower();
    wide = !below || below->upper() - below->lower() > kLooseCrossing;
  }
  if (free.lastGap < slab.curves.size()) {
    const std::optional<Interval> above = crossing(slab.curves[free.lastGap]);
    if (above && above->upper() < 1) high = above->upper();
    wide = wide || !above || above->upper() - above->lower() > kLooseCrossing;
  }
  if (low > high || !segmentMayMeet(geometry, slice, turn, query, {low, high})) return false;
  if (!wide || halvings == 0 || angles[0] == angles[1]) return true;
  // Over half the angles each, the crossings move less.
  const double middle = 0.5 * (angles[0] + angles[1]);
  return slabMayMeet(patch, free, {angles[0], middle}, query, halvings - 1) ||
         slabMayMeet(patch, free, {middle, angles[1]}, query, halvings - 1);
}

void ClearanceBoxes::BoxStore::push_back(ClearanceBox box) {
  if ((size_ & kChunkMask) == 0) chunks_.push_back(std::make_unique<ClearanceBox[]>(kChunkMask + 1));
  (*this)[size_++] = std::move(box);
}

bool ClearanceBoxes::touch(const ClearanceBox& a, const ClearanceBox& b) const {
  if (!closedOverlap(a.low[0], a.high[0], b.low[0], b.high[0])) return false;
  if (!closedOverlap(a.low[1], a.high[1], b.low[1], b.high[1])) return false;
  const double thetaLow = rootEdges_[2].front(), thetaHigh = rootEdges_[2].back();
  return closedOverlap(a.low[2], a.high[2], b.low[2], b.high[2]) || (a.low[2] == thetaLow && b.high[2] == thetaHigh) ||
         (b.low[2] == thetaLow && a.high[2] == thetaHigh);
}

std::uint32_t ClearanceBoxes::leafAt(const Pose2& pose) const {
  const std::array<double, 3> at{pose.x, pose.y, reducedAngle(pose.theta)};
  const std::size_t countY = rootEdges_[1].size() - 1, countTheta = rootEdges_[2].size() - 1;
  std::uint32_t index = static_cast<std::uint32_t>(
      (intervalOf(rootEdges_[0], at[0]) * countY + intervalOf(rootEdges_[1], at[1])) * countTheta +
      intervalOf(rootEdges_[2], at[2]));
  while (boxes_[index].split) {
    const ClearanceBox& box = boxes_[index];
    std::uint32_t child = 0, bit = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(box.splitAxes >> axis & 1)) continue;
      if (at[axis] > 0.5 * (box.low[axis] + box.high[axis])) child |= 1u << bit;
      ++bit;
    }
    index = box.firstChild + child;
  }
  return index;
}

void ClearanceBoxes::split(std::uint32_t index, std::uint8_t axes) {
  boundHalves(index, attach(index, axes, halves(index, axes)));
  forgetAnchors(index);
}

std::size_t ClearanceBoxes::splitEach(const std::vector<std::uint32_t>& boxes, const std::function<bool()>& keepGoing) {
  std::vector<std::uint8_t> axes(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) axes[k] = axesToSplit(boxes[k]);
  // A box's halves depend on it alone (its centre's clearance, cell and bounds), so
  // they are measured on every core, then attached in order, as split() would one
  // after another, and bounded on every core (a box's halves' bounds depend on the
  // neighbours it had when attached, and are written to its halves alone).
  std::vector<std::vector<ClearanceBox>> halved(boxes.size());
  onEveryCore(boxes.size(), keepGoing, [&](std::size_t k) { halved[k] = halves(boxes[k], axes[k]); });
  // Those measured before `keepGoing` said stop (a box halved after one left whole is
  // left whole too).
  std::size_t done = 0;
  while (done < boxes.size() && !halved[done].empty()) ++done;
  std::vector<std::vector<std::uint32_t>> neighbours(done);
  for (std::size_t k = 0; k < done; ++k) neighbours[k] = attach(boxes[k], axes[k], std::move(halved[k]));
  const auto always = [] { return true; };
  onEveryCore(done, always, [&](std::size_t k) { boundHalves(boxes[k], neighbours[k]); });
  for (std::size_t k = 0; k < done; ++k) forgetAnchors(boxes[k]);
  return done;
}

std::vector<ClearanceBox> ClearanceBoxes::halves(std::uint32_t index, std::uint8_t axes) const {
  const ClearanceBox& box = boxes_[index];
  std::vector<ClearanceBox> parts;
  parts.reserve(partCount(axes));
  for (std::uint32_t part = 0; part < partCount(axes); ++part) {
    std::array<double, 3> low = box.low, high = box.high;
    for (int axis = 0, bit = 0; axis < 3; ++axis) {
      if (!(axes >> axis & 1)) continue;
      const double middle = 0.5 * (low[axis] + high[axis]);
      (part >> bit & 1 ? low : high)[axis] = middle;
      ++bit;
    }
    parts.push_back(measured(low, high, expectedClearance(box, low, high), certifiedLocation(box, low, high)));
  }
  return parts;
}

std::vector<std::uint32_t> ClearanceBoxes::attach(std::uint32_t index, std::uint8_t axes,
                                                  std::vector<ClearanceBox> halves) {
  const std::uint32_t first = static_cast<std::uint32_t>(boxes_.size());
  const std::uint32_t parts = static_cast<std::uint32_t>(halves.size());
  for (ClearanceBox& half : halves) boxes_.push_back(std::move(half));
  boxes_[index].split = true;
  changed_.push_back(index);
  boxes_[index].splitAxes = axes;
  boxes_[index].firstChild = first;
  // The halves touch one another (they share the centre) and each of the box's
  // neighbours (not split, not dropped) they touch, both ways.
  std::vector<std::uint32_t> neighbours = std::move(boxes_[index].neighbours);
  boxes_[index].neighbours = {};
  neighbours.erase(std::remove_if(neighbours.begin(), neighbours.end(),
                                  [&](std::uint32_t other) { return boxes_[other].split || boxes_[other].dropped; }),
                   neighbours.end());
  const std::uint32_t end = first + parts;
  for (std::uint32_t child = first; child < end; ++child) {
    for (std::uint32_t sibling = first; sibling < end; ++sibling) {
      if (sibling != child) boxes_[child].neighbours.push_back(sibling);
    }
  }
  for (std::uint32_t neighbour : neighbours) {
    // Its list loses the box split (and any other split or dropped since): the
    // searches over chains walk these lists every round.
    std::vector<std::uint32_t>& list = boxes_[neighbour].neighbours;
    list.erase(std::remove_if(list.begin(), list.end(),
                              [&](std::uint32_t other) { return boxes_[other].split || boxes_[other].dropped; }),
               list.end());
    for (std::uint32_t child = first; child < end; ++child) {
      if (!touch(boxes_[child], boxes_[neighbour])) continue;
      boxes_[child].neighbours.push_back(neighbour);
      boxes_[neighbour].neighbours.push_back(child);
    }
  }
  return neighbours;
}

void ClearanceBoxes::boundHalves(std::uint32_t index, const std::vector<std::uint32_t>& neighbours) {
  const ClearanceBox& box = boxes_[index];
  const std::uint32_t first = box.firstChild, end = first + partCount(box.splitAxes);
  // Each half is bounded by the best of the box's anchors and the halves' and
  // neighbours' own.
  std::vector<const ClearanceAnchor*> candidates;
  addAnchors(box.anchors, candidates);
  for (std::uint32_t child = first; child < end; ++child) addAnchors(boxes_[child].own, candidates);
  for (std::uint32_t neighbour : neighbours) addAnchors(boxes_[neighbour].own, candidates);
  BoundScratch scratch;
  for (std::uint32_t child = first; child < end; ++child) {
    bound(boxes_[child], candidates, scratch);
    // The box's bound holds in its halves: bounds only fall (UpperSearch relies on it).
    boxes_[child].upper = std::min(boxes_[child].upper, box.upper);
    settleBlocked(boxes_[child]);
  }
}

void ClearanceBoxes::forgetAnchors(std::uint32_t index) {
  std::vector<ClearanceAnchor>().swap(boxes_[index].own);
  std::vector<ClearanceAnchor>().swap(boxes_[index].anchors);
}

std::uint8_t ClearanceBoxes::axesToSplit(std::uint32_t index) const {
  const ClearanceBox& box = boxes_[index];
  if (box.centreCell || box.own.empty()) return kEveryAxis;
  const double halfDiagonal = std::hypot(box.high[0] - box.low[0], box.high[1] - box.low[1]) / 2;
  return box.own.front().upper + halfDiagonal < 0 ? kThetaAxis : kEveryAxis;
}

void ClearanceBoxes::drop(std::uint32_t index) {
  boxes_[index].dropped = true;
  changed_.push_back(index);
  // Nothing bounds or halves from it again, and its anchors' memory serves the boxes
  // halved next instead of new pages (half of a query's page faults on the maze).
  forgetAnchors(index);
}

template <typename Droppable>
void ClearanceBoxes::dropLiveFrom(std::size_t& seen, Droppable droppable) {
  for (std::size_t index = std::exchange(seen, boxes_.size()); index < boxes_.size(); ++index) {
    ClearanceBox& box = boxes_[index];
    if (!box.split && !box.dropped && droppable(box)) drop(static_cast<std::uint32_t>(index));
  }
}

void ClearanceBoxes::dropBelow(double level) {
  // Every box before seenByDropBelow_ was looked at with a level at least the last one.
  if (level > droppedBelow_) seenByDropBelow_ = 0;
  droppedBelow_ = level;
  dropLiveFrom(seenByDropBelow_, [&](const ClearanceBox& box) { return box.upper < level; });
}

void ClearanceBoxes::dropOutside(std::uint32_t cell) {
  if (droppedOutside_ != cell) seenByDropOutside_ = 0;
  droppedOutside_ = cell;
  dropLiveFrom(seenByDropOutside_, [&](ClearanceBox& box) {
    if (!box.centreCell || *box.centreCell == cell) return false;
    box.unbroken = box.unbroken || !meetsFreeBoundary(box);
    return box.unbroken;
  });
}

namespace {

/// A box reached: its chain's bottleneck, its own bound, its index.
using BoxReached = std::tuple<double, double, std::uint32_t>;
using BoxQueue = std::priority_queue<BoxReached>;

/// Dijkstra's method with the bottleneck for length (breadth by `boundOf`, through the
/// boxes `usable` accepts), from the boxes in `open` with their bottlenecks in
/// `widest`, until `stop` says so of a box reached (with its bottleneck; boxes are
/// reached widest first, and of equal bottlenecks, widest themselves first: past the
/// bottleneck, where every box ties, chains keep to the widest boxes instead of
/// wandering along walls): each box's bottleneck and predecessor, final (and marked
/// so) for the boxes reached before.
template <typename Boxes, typename BoundOf, typename Usable, typename Stop>
void widestChains(const Boxes& boxes, BoxQueue& open, BoundOf boundOf, Usable usable, Stop stop,
                  std::vector<double>& widest, std::vector<std::uint32_t>& previous, std::vector<char>& final) {
  while (!open.empty()) {
    const auto [width, own, index] = open.top();
    open.pop();
    if (width < widest[index] || final[index]) continue;
    if (stop(index, width)) break;
    final[index] = 1;
    for (std::uint32_t neighbour : boxes[index].neighbours) {
      if (!usable(neighbour)) continue;
      const double bound = boundOf(neighbour), through = std::min(width, bound);
      if (through <= widest[neighbour]) continue;
      widest[neighbour] = through;
      previous[neighbour] = index;
      open.push({through, bound, neighbour});
    }
  }
}

/// The chain a search's tree of predecessors gives from its box to `to`, with `to`'s
/// bottleneck (empty when the search did not reach `to`).
ClearanceBoxes::Chain chainAlong(const std::vector<double>& widest, const std::vector<std::uint32_t>& previous,
                                 std::uint32_t to) {
  ClearanceBoxes::Chain chain;
  if (widest[to] == -HUGE_VAL) return chain;
  chain.bottleneck = widest[to];
  for (std::uint32_t index = to; index != UINT32_MAX; index = previous[index]) chain.boxes.push_back(index);
  std::reverse(chain.boxes.begin(), chain.boxes.end());
  return chain;
}

}  // namespace

ClearanceBoxes::Chain ClearanceBoxes::widestChain(std::uint32_t from, std::uint32_t to, Bound bound,
                                                  double upperAtLeast, std::optional<std::uint32_t> centreCell) const {
  ChainRoom room;
  return widestChain(from, to, bound, upperAtLeast, centreCell, room);
}

ClearanceBoxes::Chain ClearanceBoxes::widestChain(std::uint32_t from, std::uint32_t to, Bound bound,
                                                  double upperAtLeast, std::optional<std::uint32_t> centreCell,
                                                  ChainRoom& room) const {
  const auto boundOf = [&](std::uint32_t index) {
    return bound == Bound::Lower ? boxes_[index].lower : boxes_[index].upper;
  };
  std::vector<double>& widest = room.widest;
  std::vector<std::uint32_t>& previous = room.previous;
  std::vector<char>& final = room.final;
  widest.assign(boxes_.size(), -HUGE_VAL);
  previous.assign(boxes_.size(), UINT32_MAX);
  final.assign(boxes_.size(), 0);
  widest[from] = boundOf(from);
  BoxQueue open;
  open.push({widest[from], widest[from], from});
  widestChains(
      boxes_, open, boundOf,
      [&](std::uint32_t index) {
        const ClearanceBox& box = boxes_[index];
        return !box.split && !box.dropped && box.upper >= upperAtLeast && (!centreCell || box.centreCell == centreCell);
      },
      [&](std::uint32_t index, double) { return index == to; }, widest, previous, final);
  return chainAlong(widest, previous, to);
}

std::vector<double> ClearanceBoxes::widestUpperFrom(std::uint32_t from, std::uint32_t to, double ratio,
                                                    double cap) const {
  UpperSearch search;
  return widestUpperFrom(from, to, ratio, cap, search);
}

void ClearanceBoxes::markReset(UpperSearch& search) const {
  const std::size_t known = search.widest.size();
  std::vector<char>& reset = search.reset;
  reset.assign(boxes_.size(), 1);
  if (search.from == UINT32_MAX) return;
  std::fill(reset.begin(), reset.begin() + static_cast<std::ptrdiff_t>(known), 0);
  // Boxes added since the last search have no place in its tree.
  std::vector<std::uint32_t> stack;
  for (std::size_t k = search.changesSeen; k < changed_.size(); ++k) {
    if (changed_[k] < known) stack.push_back(changed_[k]);
  }
  for (std::uint32_t index : stack) reset[index] = 1;
  // And every box whose chain passes one of those: down the tree of predecessors.
  std::vector<std::uint32_t>& firstSuccessor = search.firstSuccessor;
  firstSuccessor.assign(known + 1, 0);
  for (std::size_t index = 0; index < known; ++index) {
    if (search.previous[index] != UINT32_MAX) ++firstSuccessor[search.previous[index] + 1];
  }
  for (std::size_t index = 0; index < known; ++index) firstSuccessor[index + 1] += firstSuccessor[index];
  std::vector<std::uint32_t>& successors = search.successors;
  std::vector<std::uint32_t>& nextSuccessor = search.nextSuccessor;
  successors.resize(firstSuccessor[known]);
  nextSuccessor.assign(firstSuccessor.begin(), firstSuccessor.end() - 1);
  for (std::size_t index = 0; index < known; ++index) {
    if (search.previous[index] != UINT32_MAX) successors[nextSuccessor[search.previous[index]]++] = index;
  }
  while (!stack.empty()) {
    const std::uint32_t parent = stack.back();
    stack.pop_back();
    for (std::uint32_t k = firstSuccessor[parent]; k < firstSuccessor[parent + 1]; ++k) {
      if (!reset[successors[k]]) {
        reset[successors[k]] = 1;
        stack.push_back(successors[k]);
      }
    }
  }
}

const std::vector<double>& ClearanceBoxes::widestUpperFrom(std::uint32_t from, std::uint32_t to, double ratio,
                                                           double cap, UpperSearch& search) const {
  const bool fresh = search.from != from;
  if (fresh) search = UpperSearch{};
  markReset(search);
  const std::vector<char>& reset = search.reset;
  search.from = from;
  search.changesSeen = changed_.size();
  search.widest.resize(boxes_.size(), -HUGE_VAL);
  search.previous.resize(boxes_.size(), UINT32_MAX);
  search.final.resize(boxes_.size(), 0);
  std::vector<double>& widest = search.widest;
  const auto usable = [&](std::uint32_t index) { return !boxes_[index].split && !boxes_[index].dropped; };
  // Boxes reset start from their kept final neighbours; kept boxes the last search
  // left below its level keep what its final boxes gave them (their best).
  std::vector<BoxReached> seeds;
  for (std::uint32_t index = 0; index < boxes_.size(); ++index) {
    if (reset[index]) {
      widest[index] = index == from ? boxes_[index].upper : -HUGE_VAL;
      search.previous[index] = UINT32_MAX;
      search.final[index] = 0;
      if (!fresh && index != from && usable(index)) {
        for (std::uint32_t neighbour : boxes_[index].neighbours) {
          if (reset[neighbour] || !search.final[neighbour]) continue;
          const double through = std::min(widest[neighbour], boxes_[index].upper);
          if (through > widest[index]) {
            widest[index] = through;
            search.previous[index] = neighbour;
          }
        }
      }
    }
    if (!search.final[index] && widest[index] > -HUGE_VAL) {
      seeds.push_back({widest[index], boxes_[index].upper, index});
    }
  }
  BoxQueue open(std::less<BoxReached>(), std::move(seeds));
  // Stopped below the level (known once `to` is final).
  double level = search.final[to] ? ratio * std::min(cap, widest[to]) : -HUGE_VAL;
  widestChains(
      boxes_, open, [&](std::uint32_t index) { return boxes_[index].upper; }, usable,
      [&](std::uint32_t index, double width) {
        if (index == to) level = ratio * std::min(cap, width);
        return width < level;
      },
      widest, search.previous, search.final);
  return widest;
}

std::vector<char> ClearanceBoxes::reachedAbove(std::uint32_t from, double level) const {
  std::vector<char> reached(boxes_.size(), 0);
  const auto passable = [&](std::uint32_t index) {
    const ClearanceBox& box = boxes_[index];
    return !box.split && !box.dropped && box.upper > level;
  };
  if (!passable(from)) return reached;
  std::vector<std::uint32_t> open{from};
  reached[from] = 1;
  while (!open.empty()) {
    const std::uint32_t index = open.back();
    open.pop_back();
    for (std::uint32_t neighbour : boxes_[index].neighbours) {
      if (reached[neighbour] || !passable(neighbour)) continue;
      reached[neighbour] = 1;
      open.push_back(neighbour);
    }
  }
  return reached;
}

ClearanceBoxes::Chain ClearanceBoxes::chainTo(const UpperSearch& search, std::uint32_t to) {
  return chainAlong(search.widest, search.previous, to);
}

Pose2 ClearanceBoxes::meeting(std::uint32_t index, std::uint32_t nextIndex) const {
  const ClearanceBox &box = boxes_[index], &next = boxes_[nextIndex];
  const auto middleOfCommon = [&](int axis) {
    return 0.5 * (std::max(box.low[axis], next.low[axis]) + std::min(box.high[axis], next.high[axis]));
  };
  double theta;
  if (closedOverlap(box.low[2], box.high[2], next.low[2], next.high[2])) {
    theta = middleOfCommon(2);
  } else {
    theta = box.low[2] == rootEdges_[2].front() ? box.low[2] : box.high[2];
  }
  return {middleOfCommon(0), middleOfCommon(1), theta};
}

}  // namespace freespace
