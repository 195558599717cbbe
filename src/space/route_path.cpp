#include "route_path.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

#include "freespace/numbers/angle_reduction.h"
#include "freespace/numbers/half_angle.h"
#include "freespace/space/face_path.h"
#include "freespace/space/motion_checker.h"
#include "freespace/topology/slice_faces.h"
#include "every_core.h"
#include "lazy_ranking.h"

namespace freespace {

namespace {

/// At most this many turning steps along a whole route.
constexpr int kMostSteps = 20000;
/// At most this many crossings of edges that failed, before giving up.
constexpr std::size_t kMostFailedCrossings = 200;
/// The share of a crossing's clearance that the way to it should keep, by estimate,
/// before crossing points whose ways keep less are tried.
constexpr double kLeastTravelShare = 1e-4;
/// At most this many clearances to certify one step of a turn in place.
constexpr std::size_t kTurnQueryLimit = 4096;
/// At most this many faces kept for reuse.
constexpr std::size_t kFacesKept = 256;
/// At most this many faces' triangulations kept for reuse.
constexpr std::size_t kTriangulationsKept = 64;
/// The relative width of the certified clearances the walk asks for.
constexpr double kWidth = MotionChecker::kClearanceWidth;

/// A face of the walk, with the distances to its loops (the walk asks the clearance
/// at thousands of points of some faces).
struct WalkFace : SliceFace {
  explicit WalkFace(SliceFace&& face) : SliceFace(std::move(face)), boundary(*this) {}
  BoundaryDistances boundary;
};

class RouteWalker {
 public:
  RouteWalker(const FreeSpace& space, std::chrono::steady_clock::time_point deadline, const Cancellation& cancellation)
      : space_(space),
        graph_(space.cellGraph()),
        sliceFaces_(space.sliceFaces()),
        checker_(space),
        scale_(space.meshes().scale),
        deadline_(deadline),
        cancellation_(cancellation) {}

  /// The walk from `from`, in node `first`, to `to`, in node `last`.
  std::optional<RoutedPath> walk(const Pose2& from, std::uint32_t first, const Pose2& to, std::uint32_t last) {
    waypoints_ = {from};
    certified_.clear();
    // Where a crossing fails, the route is planned again from the node reached,
    // without that edge.
    std::set<std::pair<std::uint32_t, std::uint32_t>> failed;
    const auto usable = [&](std::uint32_t a, std::uint32_t b) { return !failed.count(std::minmax(a, b)); };
    for (std::uint32_t node = first; failed.size() < kMostFailedCrossings;) {
      const std::optional<std::vector<std::uint32_t>> route = graph_.route(node, last, usable);
      if (!route) return std::nullopt;
      std::size_t at = 0;
      for (std::optional<std::size_t> reached; at + 1 < route->size(); at = *reached) {
        reached = crossFrom(*route, at);
        if (!reached) break;
      }
      if (at + 1 == route->size()) {
        if (!arriveAt(route->back(), to)) return std::nullopt;
        return RoutedPath{waypoints_, certified_};
      }
      failed.insert(std::minmax((*route)[at], (*route)[at + 1]));
      node = (*route)[at];
    }
    return std::nullopt;
  }

 private:
  const Pose2& current() const { return waypoints_.back(); }
  /// Adds a waypoint, with the certified lower bound on the clearance of the motion to
  /// it when that is known.
  void append(const Pose2& pose, std::optional<double> certified = std::nullopt) {
    waypoints_.push_back(pose);
    certified_.push_back(certified);
  }
  /// Goes back to the first `count` waypoints.
  void truncate(std::size_t count) {
    waypoints_.resize(count);
    certified_.resize(count - 1);
  }
  std::array<double, 2> scaled(const Pose2& pose) const { return {pose.x * scale_, pose.y * scale_}; }

  /// The node's face in the slice at theta (none at a critical angle, or outside the
  /// node's angles). Faces are kept (up to kFacesKept): a travel estimates an angle's
  /// translation, then makes it. Each is made with an AngleAlgebra of its own: a walk's
  /// angles are all different, and one kept for the walk, whose memo grew, was 10-15%
  /// slower.
  std::shared_ptr<const WalkFace> faceAt(std::uint32_t node, double theta) const {
    auto kept = faces_.find({theta, node});
    if (kept == faces_.end()) {
      if (faces_.size() >= kFacesKept) faces_.clear();
      std::shared_ptr<const WalkFace> face;
      try {
        PredicateStatistics statistics;
        AngleAlgebra algebra(statistics);
        std::optional<SliceFace> made =
            sliceFaces_.faceOf(node, AlgebraicAngle::rational(HalfAngle::fromRadians(theta)), algebra);
        if (made) face = std::make_shared<const WalkFace>(std::move(*made));
      } catch (const std::invalid_argument&) {
        // A critical angle: no faces.
      }
      kept = faces_.emplace(std::pair(theta, node), std::move(face)).first;
    }
    return kept->second;
  }

  /// The triangulation of the node's face at theta (faceAt's), with `points` inside
  /// its box; kept (up to kTriangulationsKept) and made again only around points
  /// outside the kept one's box.
  std::shared_ptr<const FaceTriangulation> triangulationAt(std::uint32_t node, double theta, const SliceFace& face,
                                                           const std::vector<std::array<double, 2>>& points) const {
    auto kept = triangulations_.find({theta, node});
    if (kept == triangulations_.end()) {
      if (triangulations_.size() >= kTriangulationsKept) triangulations_.clear();
      kept = triangulations_.emplace(std::pair(theta, node), nullptr).first;
    }
    const auto boxed = [&](const std::array<double, 2>& point) { return kept->second->boxHolds(point); };
    if (!kept->second || !std::all_of(points.begin(), points.end(), boxed))
      kept->second = std::make_shared<const FaceTriangulation>(face, points);
    return kept->second;
  }

  /// The clearance of a point inside the face (construction coordinates) at the face's
  /// angle, estimated from the face's loops (nearestOnBoundary, by the face's
  /// BoundaryDistances; in the input's units).
  double estimatedClearance(const WalkFace& face, const std::array<double, 2>& point) const {
    return face.boundary.nearest(point).distance / scale_;
  }
  double estimatedClearance(const WalkFace& face, const Pose2& pose) const {
    return estimatedClearance(face, scaled(pose));
  }

  /// Translations at the current angle to `target` (construction coordinates) inside
  /// the face (the current angle's) by its triangulation; with `keeping` (> 0), only
  /// when each keeps that much clearance (certified, with few clearances each).
  bool translateTo(const WalkFace& face, const FaceTriangulation& triangulation, const std::array<double, 2>& target,
                   double keeping = 0) {
    const std::optional<std::vector<std::array<double, 2>>> path = triangulation.path(scaled(current()), target);
    if (!path) return false;
    const double theta = current().theta;
    std::vector<Pose2> poses{current()};
    double fromClearance = estimatedClearance(face, current());
    for (std::size_t k = 1; k < path->size(); ++k) {
      const Pose2 to{(*path)[k][0] / scale_, (*path)[k][1] / scale_, theta};
      const double toClearance = estimatedClearance(face, to);
      appendRoomier(face, triangulation, poses.back(), fromClearance, to, toClearance, 0, poses);
      fromClearance = toClearance;
    }
    std::vector<std::optional<double>> certified(poses.size());
    for (std::size_t k = 1; k < poses.size(); ++k) {
      certified[k] = certifiedTranslation(face, poses[k - 1], poses[k]);
      if (keeping > 0 && !(certified[k] && *certified[k] >= keeping) &&
          !checker_.keepsClearance(poses[k - 1], poses[k], keeping, 64)) {
        return false;
      }
    }
    for (std::size_t k = 1; k < poses.size(); ++k) append(poses[k], certified[k]);
    return true;
  }

  /// A certified lower bound on the clearance along a translation inside the face (at
  /// its angle), from the face's loops (certifiedClearanceAlong); none when they do not
  /// certify it.
  std::optional<double> certifiedTranslation(const WalkFace& face, const Pose2& from, const Pose2& to) const {
    const std::optional<double> along = face.boundary.certifiedClearanceAlong(scaled(from), scaled(to));
    if (!along) return std::nullopt;
    const double least = *along / scale_ - MotionChecker::interpolationRounding(from, to);
    return least > 0 ? std::optional<double>(least) : std::nullopt;
  }

  /// A certified lower bound on the clearance along a turn at a fixed point inside the
  /// node, from the clearances its faces certify at the turn's ends (by the Lipschitz
  /// bound in theta); none when they do not certify it.
  std::optional<double> certifiedTurn(std::uint32_t node, const Pose2& from, const Pose2& to) const {
    const auto clearanceAt = [&](const Pose2& pose) -> std::optional<double> {
      const std::shared_ptr<const WalkFace> face = faceAt(node, pose.theta);
      if (!face) return std::nullopt;
      const std::optional<double> at = face->boundary.certifiedClearanceAlong(scaled(pose), scaled(pose));
      if (!at) return std::nullopt;
      return *at / scale_;
    };
    const std::optional<double> clearanceFrom = clearanceAt(from);
    if (!clearanceFrom) return std::nullopt;
    const std::optional<double> clearanceTo = clearanceAt(to);
    if (!clearanceTo) return std::nullopt;
    return checker_.leastClearanceBetween(from, to, *clearanceFrom, *clearanceTo);
  }

  /// Appends the translation from `from` to `to` (at one angle), by a point pushed
  /// away from its contact where the leg is much tighter than at its ends (a leg
  /// cutting a corner between the middles of the triangulation's edges): its tightest
  /// of seven points, pushed as far as the ends' smaller clearance asks, while that
  /// leaves it roomier and in the face (by its triangulation: the translations are
  /// certified later); up to four times per leg (a retraction towards the medial
  /// axis). The ends' clearances are given (each point's is estimated once, from the
  /// face's loops).
  void appendRoomier(const WalkFace& face, const FaceTriangulation& triangulation, const Pose2& from,
                     double fromClearance, const Pose2& to, double toClearance, int depth,
                     std::vector<Pose2>& poses) const {
    const double wanted = std::min(fromClearance, toClearance);
    std::optional<std::pair<Pose2, BoundaryPoint>> tightest;
    for (int k = 1; depth < 4 && k < 8; ++k) {
      const Pose2 at{from.x + (to.x - from.x) * k / 8, from.y + (to.y - from.y) * k / 8, from.theta};
      const BoundaryPoint nearest = face.boundary.nearest(scaled(at));
      if (!tightest || nearest.distance < tightest->second.distance) tightest = {at, nearest};
    }
    if (tightest && tightest->second.distance > 0 && tightest->second.distance / scale_ < 0.9 * wanted) {
      const auto& [at, contact] = *tightest;
      const std::array<double, 2> point = scaled(at);
      const double push = wanted * scale_ - contact.distance;
      const double away[2] = {(point[0] - contact.point[0]) / contact.distance,
                              (point[1] - contact.point[1]) / contact.distance};
      const Pose2 pushed{(point[0] + away[0] * push) / scale_, (point[1] + away[1] * push) / scale_, from.theta};
      const double pushedClearance = estimatedClearance(face, pushed);
      if (pushedClearance * scale_ > contact.distance && triangulation.contains(scaled(pushed))) {
        appendRoomier(face, triangulation, from, fromClearance, pushed, pushedClearance, depth + 1, poses);
        appendRoomier(face, triangulation, pushed, pushedClearance, to, toClearance, depth + 1, poses);
        return;
      }
    }
    poses.push_back(to);
  }

  /// Moves to where the node's face at the current angle is roomier: the middle of the
  /// face's widest triangle when that has more than four times the clearance and the
  /// way there keeps half the current clearance (where the robot must turn around, the
  /// room to do so may lie across the face), otherwise the middle of the triangle
  /// holding the current point (a short move). Returns the clearance where it leaves
  /// the robot, estimated from the face's loops (none when the point lies outside it).
  std::optional<double> recentre(std::uint32_t node) {
    const std::shared_ptr<const WalkFace> face = faceAt(node, current().theta);
    if (!face || face->loops.empty()) return std::nullopt;
    const std::shared_ptr<const FaceTriangulation> triangulation =
        triangulationAt(node, current().theta, *face, {scaled(current())});
    const std::optional<std::array<double, 2>> middle = triangulation->incentreAt(scaled(current()));
    if (!middle) return std::nullopt;  // outside the face
    const double here = estimatedClearance(*face, current());
    const std::vector<std::array<double, 2>> roomy = triangulation->roomyPoints();
    const bool moved = (here > 0 && !roomy.empty() && estimatedClearance(*face, roomy.front()) > 4 * here &&
                        translateTo(*face, *triangulation, roomy.front(), 0.5 * here)) ||
                       (estimatedClearance(*face, *middle) > here && translateTo(*face, *triangulation, *middle));
    return moved ? estimatedClearance(*face, current()) : here;
  }

  /// The signed turn from angle `from` to `to` staying inside the node's arc of
  /// angles (the shorter one when the node holds every angle).
  double turnInside(const CellGraphNode& node, double from, double to) const {
    const auto [arcStart, width] = graph_.arc(node.firstInterval, node.lastInterval);
    if (width == 2 * M_PI) return MotionChecker::shorterTurn(from, to);
    const auto along = [&](double angle) {
      const double u = std::fmod(angle - arcStart, 2 * M_PI);
      return u < 0 ? u + 2 * M_PI : u;
    };
    return along(to) - along(from);
  }

  /// Whether the node seems to let the robot turn at `point` (construction
  /// coordinates) from angle `from` to `to`: the point lies in the node's face at
  /// angles an eighth of a half turn apart along the way (by its rounded loops: an
  /// estimate, to try likelier turns first; certifying a turn that fails takes as
  /// long as one that does not).
  bool turnLooksFree(std::uint32_t node, const std::array<double, 2>& point, double from, double to) const {
    const double turn = turnInside(graph_.nodes()[node], from, to);
    const int steps = static_cast<int>(std::ceil(std::fabs(turn) / (M_PI / 8)));
    for (int k = 1; k < steps; ++k) {
      const std::shared_ptr<const WalkFace> face = faceAt(node, reducedAngle(from + turn * k / steps));
      if (face && !face->boundary.liesInside(point)) return false;
    }
    return true;
  }

  /// The clearance at the current point, estimated from the node's face at its angle
  /// (the exact one at a critical angle, where the node has no face, or where the point
  /// lies outside the face by its rounded loops).
  double clearanceHere(std::uint32_t node) const {
    if (const std::shared_ptr<const WalkFace> face = faceAt(node, current().theta)) {
      if (face->boundary.liesInside(scaled(current()))) return estimatedClearance(*face, current());
    }
    return space_.clearance(current(), kWidth).lower;
  }

  /// Turns to `theta` inside the node by steps of half the current clearance's
  /// allowance, moving to the middle of the face's triangle after each.
  bool turnTo(std::uint32_t node, double theta) {
    const CellGraphNode& graphNode = graph_.nodes()[node];
    std::optional<double> estimate;  // the current point's clearance, as the last recentring left it
    for (;;) {
      cancellation_.check();
      if (++steps_ > kMostSteps || std::chrono::steady_clock::now() > deadline_) return false;
      const double remaining = turnInside(graphNode, current().theta, theta);
      if (remaining == 0) return true;
      const double clearance = estimate ? *estimate : clearanceHere(node);
      if (!(clearance > 0)) return false;
      const double step = 0.5 * clearance / checker_.reach();
      if (step >= std::fabs(remaining)) {
        const Pose2 turned{current().x, current().y, theta};
        append(turned, certifiedTurn(node, current(), turned));
        return true;
      }
      const Pose2 turned{current().x, current().y, reducedAngle(current().theta + std::copysign(step, remaining))};
      append(turned, certifiedTurn(node, current(), turned));
      estimate = recentre(node);
    }
  }

  /// Turns at the current point to `theta` inside the node, in steps shorter than a
  /// quarter turn, each certified free (no recentring: the point is where a crossing
  /// or the goal needs it): a single step by the faces at its ends (certifiedTurn)
  /// when they can, otherwise by the motion checker.
  bool turnInPlace(std::uint32_t node, double theta) {
    const double turn = turnInside(graph_.nodes()[node], current().theta, theta);
    const int steps = static_cast<int>(std::ceil(std::fabs(turn) / (M_PI / 2) * (1 + 1e-9)));
    const Pose2 from = current();
    for (int k = 1; k <= steps; ++k) {
      const Pose2 next{from.x, from.y, k == steps ? theta : reducedAngle(from.theta + turn * k / steps)};
      const std::optional<double> certified = steps == 1 ? certifiedTurn(node, current(), next) : std::nullopt;
      if (certified) {
        append(next, certified);
        continue;
      }
      const MotionCheck check = checker_.check(current(), next, 1, kTurnQueryLimit);
      if (!check.free) return false;
      append(next, check.minClearance);
    }
    return true;
  }

  /// Angles of the node's run to translate at: the middles of its intervals (of at
  /// most eight of them, spread along the run), the current angle and `arrival`.
  std::vector<double> travelAngleCandidates(std::uint32_t node, double arrival) const {
    std::vector<double> angles{arrival, current().theta};
    const std::vector<AlgebraicAngle>& critical = graph_.criticalAngles();
    if (critical.empty()) {
      for (int k = 0; k < 8; ++k) angles.push_back(reducedAngle(-M_PI + M_PI * k / 4));
      return angles;
    }
    const std::uint32_t count = graph_.intervalCount();
    const CellGraphNode& run = graph_.nodes()[node];
    const std::uint32_t length = (run.lastInterval + count - run.firstInterval) % count + 1;
    const std::uint32_t stride = (length + 7) / 8;
    for (std::uint32_t k = 0; k < length; k += stride) {
      const std::uint32_t interval = (run.firstInterval + k) % count;
      const auto [low, width] = graph_.arc(interval, interval);
      if (width >= 1e-9) angles.push_back(reducedAngle(low + width / 2));
    }
    return angles;
  }

  /// The translation from the current point to `point` in the node's face at `theta`,
  /// and the least clearance at its corners and the middles of its legs (an estimate,
  /// not certified); none when the face does not hold both.
  std::optional<double> estimatedTravel(std::uint32_t node, const std::array<double, 2>& point, double theta) const {
    const std::shared_ptr<const WalkFace> face = faceAt(node, theta);
    if (!face) return std::nullopt;
    const std::array<double, 2> here = scaled(current());
    const std::optional<std::vector<std::array<double, 2>>> way =
        face->loops.empty() ? std::optional<std::vector<std::array<double, 2>>>({here, point})
                            : triangulationAt(node, theta, *face, {here, point})->path(here, point);
    if (!way) return std::nullopt;
    double least = estimatedClearance(*face, way->front());
    for (std::size_t k = 1; k < way->size(); ++k) {
      const std::array<double, 2>&a = (*way)[k - 1], &b = (*way)[k];
      least = std::min({least, estimatedClearance(*face, b),
                        estimatedClearance(*face, std::array<double, 2>{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2})});
    }
    return least;
  }

  /// An upper bound on estimatedTravel at theta (the estimated clearances at the
  /// travel's ends, without its way); none where the node has no face.
  std::optional<double> travelBound(std::uint32_t node, const std::array<double, 2>& point, double theta) const {
    const std::shared_ptr<const WalkFace> face = faceAt(node, theta);
    if (!face) return std::nullopt;
    return std::min(estimatedClearance(*face, scaled(current())), estimatedClearance(*face, point));
  }

  /// Travels inside the node to `point` (construction coordinates), arriving at angle
  /// `arrival`: turns to the angle of its run where the translation there is roomiest
  /// (a passage a node opens at one of its critical angles is narrowest next to it),
  /// translates, and turns back at `point`; the next roomiest angle when a step fails;
  /// only angles whose estimate exceeds `leastEstimate`. Estimates are made only as
  /// the ranking needs them (LazyRanking).
  bool travelTo(std::uint32_t node, const std::array<double, 2>& point, double arrival, double leastEstimate = 0) {
    std::vector<double> candidates = travelAngleCandidates(node, arrival);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::vector<std::pair<double, double>> bounded;  // angle, bound on its estimate
    for (double theta : candidates) {
      if (std::chrono::steady_clock::now() > deadline_) return false;
      if (const std::optional<double> bound = travelBound(node, point, theta)) bounded.push_back({theta, *bound});
    }
    LazyRanking ranking(bounded, leastEstimate);
    const auto estimate = [&](double theta) {
      return std::chrono::steady_clock::now() > deadline_ ? std::nullopt : estimatedTravel(node, point, theta);
    };
    const std::size_t mark = waypoints_.size();
    const auto travelAt = [&](double theta) {
      if (turnTo(node, theta) && translateInNode(node, point) && turnInPlace(node, arrival)) return true;
      truncate(mark);
      return false;
    };
    std::vector<double> blocked;  // angles from which the turn back to `arrival` looks blocked: tried last
    for (std::optional<double> next = ranking.next(estimate); next; next = ranking.next(estimate)) {
      const double theta = *next;
      if (!turnLooksFree(node, point, theta, arrival)) {
        blocked.push_back(theta);
      } else if (travelAt(theta)) {
        return true;
      }
    }
    return std::any_of(blocked.begin(), blocked.end(), travelAt);
  }

  /// Translates at the current angle to `point` inside the node's face.
  bool translateInNode(std::uint32_t node, const std::array<double, 2>& point) {
    const double theta = current().theta;
    const std::shared_ptr<const WalkFace> face = faceAt(node, theta);
    if (!face) return false;
    if (face->loops.empty()) {
      append({point[0] / scale_, point[1] / scale_, theta});
      return true;
    }
    return translateTo(*face, *triangulationAt(node, theta, *face, {scaled(current()), point}), point);
  }

  /// An angle of the node's run near critical angle `index`, before it or after it:
  /// in the first interval of the run from there on at least 1e-9 wide (the slices of
  /// thinner ones are too close to the critical ones: faces pinched to rounding), at
  /// most 1e-4 inside it.
  std::optional<double> nextToCritical(std::uint32_t index, bool before, std::uint32_t node) const {
    const std::vector<AlgebraicAngle>& critical = graph_.criticalAngles();
    const std::uint32_t count = graph_.intervalCount();
    const CellGraphNode& run = graph_.nodes()[node];
    for (std::uint32_t step = 0; step < count; ++step) {
      // The interval `step` away from the critical angle, and its end nearer to it.
      const std::uint32_t interval = before ? (index + 2 * count - 1 - step) % count : (index + step) % count;
      if (!graph_.runHolds(run, interval)) return std::nullopt;
      const auto [low, width] = graph_.arc(interval, interval);
      if (width < 1e-9) continue;
      const double inside = std::min(1e-4, width / 2);
      return reducedAngle(before ? critical[(interval + 1) % count].radians() - inside : low + inside);
    }
    return std::nullopt;
  }

  /// Crosses from route[at] to the next node through one of the edges joining them:
  /// turns to the critical angle's side in the node, moves to a point whose turn
  /// through it lands in the next node, and turns there. A next node without an
  /// interval 1e-9 wide (see nextToCritical), or whose arc is thinner than CellGraph::kThinArc
  /// (where its faces may be joined only through passages pinched to rounding), is
  /// turned through, to the node after it, where the route goes on through its other
  /// end.
  /// The index of the route's node reached; none when no crossing is found.
  std::optional<std::size_t> crossFrom(const std::vector<std::uint32_t>& route, std::size_t at) {
    for (const std::uint32_t index : graph_.edgesAt(route[at])) {
      const CellGraphEdge& edge = graph_.edges()[index];
      if (!joins(edge, route[at], route[at + 1])) continue;
      const std::optional<bool> upward = crossesUpward(route[at], route[at + 1], edge.angle);
      if (!upward) continue;
      const std::optional<double> exit = nextToCritical(edge.angle, *upward, route[at]);
      if (!exit) continue;
      // The entry, past nodes without an interval wide enough.
      std::size_t reached = at + 1;
      std::optional<double> entry = nextToCritical(edge.angle, !*upward, route[reached]);
      while ((!entry || graph_.arcWidth(route[reached]) < CellGraph::kThinArc) && reached + 1 < route.size()) {
        const CellGraphNode& thin = graph_.nodes()[route[reached]];
        const std::uint32_t end = *upward ? (thin.lastInterval + 1) % graph_.intervalCount() : thin.firstInterval;
        const CellGraph::EdgeIndices edges = graph_.edgesAt(route[reached]);
        if (!std::any_of(edges.begin(), edges.end(), [&](std::uint32_t other) {
              const CellGraphEdge& e = graph_.edges()[other];
              return e.angle == end && joins(e, route[reached], route[reached + 1]);
            })) {
          break;
        }
        ++reached;
        entry = nextToCritical(end, !*upward, route[reached]);
      }
      if (!entry || !turnTo(route[at], *exit)) continue;
      if (turnThroughAt(route[at], *exit, *entry, route[reached])) return reached;
    }
    return std::nullopt;
  }

  static bool joins(const CellGraphEdge& edge, std::uint32_t a, std::uint32_t b) {
    return (edge.from == a && edge.to == b) || (edge.from == b && edge.to == a);
  }

  /// Whether an edge at a critical angle is crossed upward (counterclockwise: `node`
  /// holds the interval before the angle and `next` the one after it) or downward;
  /// none when neither.
  std::optional<bool> crossesUpward(std::uint32_t node, std::uint32_t next, std::uint32_t angle) const {
    const std::uint32_t count = graph_.intervalCount();
    const std::uint32_t before = (angle + count - 1) % count, after = angle;
    const CellGraphNode &from = graph_.nodes()[node], &to = graph_.nodes()[next];
    if (graph_.runHolds(from, before) && graph_.runHolds(to, after)) return true;
    if (graph_.runHolds(from, after) && graph_.runHolds(to, before)) return false;
    return std::nullopt;
  }

  /// Whether `there` lies in `node` and `turned` in `next`, by the exact rays.
  bool inBothNodes(std::uint32_t node, const Pose2& there, std::uint32_t next, const Pose2& turned) const {
    return space_.nodeOf(turned) == next && space_.nodeOf(there) == node;
  }

  /// Points where the robot might turn from angle `exit` in `node` (whose face there is
  /// given) to `entry` in `next`, with their estimated clearances, the roomiest first
  /// (a crossing point near a contact makes the translations to it and from it
  /// tight): the current point, then the middles of the triangles of the faces at both
  /// angles that lie in both faces; where none does (the faces may overlap only a
  /// little), those of the triangles of both faces' loops together (each lies inside
  /// or outside each face). In both faces by their triangulations (by the exact rays
  /// when a face has no loops; confirmed by them before a turn from there is tried).
  /// Those found before the deadline.
  std::vector<std::pair<double, std::array<double, 2>>> crossingPoints(std::uint32_t node, double exit,
                                                                       const WalkFace& face, std::uint32_t next,
                                                                       double entry) const {
    const std::array<double, 2> here = scaled(current());
    const std::shared_ptr<const WalkFace> nextFace = faceAt(next, entry);
    std::shared_ptr<const FaceTriangulation> exitTriangulation, entryTriangulation;  // faces with loops
    if (nextFace && !face.loops.empty() && !nextFace->loops.empty()) {
      exitTriangulation = triangulationAt(node, exit, face, {here});
      entryTriangulation = triangulationAt(next, entry, *nextFace, {here});
    }
    std::vector<std::pair<double, std::array<double, 2>>> usable;
    const auto consider = [&](const std::vector<std::array<double, 2>>& points) {
      for (const std::array<double, 2>& point : points) {
        cancellation_.check();
        if (std::chrono::steady_clock::now() > deadline_) return;
        const Pose2 there{point[0] / scale_, point[1] / scale_, exit}, turned{there.x, there.y, entry};
        const bool inBothFaces = entryTriangulation
                                     ? exitTriangulation->contains(point) && entryTriangulation->contains(point)
                                     : inBothNodes(node, there, next, turned);
        if (!inBothFaces) continue;
        const double turnedClearance =
            nextFace ? estimatedClearance(*nextFace, turned) : space_.clearance(turned, kWidth).lower;
        usable.push_back({std::min(estimatedClearance(face, there), turnedClearance), point});
      }
    };
    consider({here});
    const std::size_t besideHere = usable.size();
    if (entryTriangulation) {
      consider(exitTriangulation->roomyPoints());
      consider(entryTriangulation->roomyPoints());
    }
    if (nextFace && usable.size() == besideHere) {
      SliceFace both = face;
      both.loops.insert(both.loops.end(), nextFace->loops.begin(), nextFace->loops.end());
      consider(FaceTriangulation(both).roomyPoints(true));
    }
    std::stable_sort(usable.begin(), usable.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    return usable;
  }

  /// Moves, at angle `exit` in `node`, to a point (of crossingPoints', the roomiest
  /// first) where turning to `entry` is certified free and lands in `next`, and turns
  /// there.
  bool turnThroughAt(std::uint32_t node, double exit, double entry, std::uint32_t next) {
    const std::shared_ptr<const WalkFace> face = faceAt(node, exit);
    if (!face) return false;
    const std::vector<std::pair<double, std::array<double, 2>>> usable = crossingPoints(node, exit, *face, next, entry);
    const std::array<double, 2> here = scaled(current());
    // First only where the way there keeps a share of the crossing's clearance (a far
    // crossing point may be reached only through a face pinched to rounding), then
    // anywhere.
    std::vector<std::optional<MotionCheck>> turns(usable.size());
    std::vector<std::optional<bool>> confirmed(usable.size());
    for (const double share : {kLeastTravelShare, 0.0}) {
      for (std::size_t k = 0; k < usable.size(); ++k) {
        if (std::chrono::steady_clock::now() > deadline_) return false;
        const auto& [clearance, point] = usable[k];
        const Pose2 there{point[0] / scale_, point[1] / scale_, exit}, turned{there.x, there.y, entry};
        if (!confirmed[k]) confirmed[k] = inBothNodes(node, there, next, turned);
        if (!*confirmed[k]) continue;
        if (!turns[k]) turns[k] = checker_.check(there, turned);
        if (!turns[k]->free) continue;
        if (point != here && !travelTo(node, point, exit, share * clearance)) continue;
        const Pose2& at = current();
        const bool checkedHere = at.x == there.x && at.y == there.y && at.theta == there.theta;
        append(turned, checkedHere ? std::optional<double>(turns[k]->minClearance) : std::nullopt);
        return true;
      }
    }
    return false;
  }

  /// Turns to the goal's angle (beside it, if that angle is critical) inside its node,
  /// translates to it, and turns onto its angle.
  bool arriveAt(std::uint32_t node, const Pose2& goal) {
    double theta = reducedAngle(goal.theta);
    std::shared_ptr<const WalkFace> face = faceAt(node, theta);
    for (double offset = 1e-9; !face && offset < 1e-3; offset *= 4) {
      theta = reducedAngle(goal.theta + offset);
      face = faceAt(node, theta);
    }
    if (!face || !travelTo(node, scaled(goal), theta)) return false;
    waypoints_.back() = goal;
    if (!certified_.empty()) certified_.back() = std::nullopt;
    return true;
  }

  const FreeSpace& space_;
  const CellGraph& graph_;
  const SliceFaces& sliceFaces_;
  const MotionChecker checker_;
  const double scale_;
  const std::chrono::steady_clock::time_point deadline_;
  const Cancellation& cancellation_;
  std::vector<Pose2> waypoints_;
  std::vector<std::optional<double>> certified_;  // per motion between waypoints
  int steps_ = 0;
  // Kept faces (null: none) and triangulations, by angle and node.
  mutable std::map<std::pair<double, std::uint32_t>, std::shared_ptr<const WalkFace>> faces_;
  mutable std::map<std::pair<double, std::uint32_t>, std::shared_ptr<const FaceTriangulation>> triangulations_;
};

/// A configuration well inside the node, where the parts of a split walk meet: the
/// middle of the roomiest triangle of the node's face at the middle of its widest
/// interval; none when the exact rays do not place it in the node.
std::optional<Pose2> junctionIn(const FreeSpace& space, std::uint32_t node) {
  const CellGraph& graph = space.cellGraph();
  const CellGraphNode& run = graph.nodes()[node];
  const std::size_t count = graph.intervalCount();
  double widest = 0, middle = 0;
  for (std::uint32_t interval = run.firstInterval;; interval = static_cast<std::uint32_t>((interval + 1) % count)) {
    const auto [low, width] = graph.arc(interval, interval);
    if (width > widest) {
      widest = width;
      middle = reducedAngle(low + width / 2);
    }
    if (interval == run.lastInterval) break;
  }
  if (widest < 1e-9) return std::nullopt;  // faces pinched to rounding (see nextToCritical)
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  std::optional<SliceFace> face;
  try {
    face = space.sliceFaces().faceOf(node, AlgebraicAngle::rational(HalfAngle::fromRadians(middle)), algebra);
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a critical angle after all
  }
  if (!face || face->loops.empty()) return std::nullopt;
  const std::vector<std::array<double, 2>> roomy = FaceTriangulation(*face).roomyPoints();
  if (roomy.empty()) return std::nullopt;
  const double scale = space.meshes().scale;
  const Pose2 junction{roomy.front()[0] / scale, roomy.front()[1] / scale, middle};
  if (space.nodeOf(junction) != node) return std::nullopt;
  return junction;
}

/// At most this many nodes are tried for a junction (each costs a face and its
/// triangulation).
constexpr std::size_t kJunctionTries = 4;

/// A junction (junctionIn) in a node of the route near index `middle`, with its node:
/// within a quarter of a part's nodes (of `parts`) of it, but neither end, the node
/// with the widest arc first (routes pass nodes only a rounding wide, with faces
/// pinched to rounding), of the kJunctionTries widest.
std::optional<std::pair<Pose2, std::uint32_t>> junctionNear(const FreeSpace& space,
                                                            const std::vector<std::uint32_t>& route, std::size_t middle,
                                                            std::size_t parts) {
  const std::size_t reach = std::max<std::size_t>(1, route.size() / (4 * parts));
  std::vector<std::uint32_t> near(route.begin() + std::max<std::size_t>(1, middle - std::min(middle, reach)),
                                  route.begin() + std::min(route.size() - 1, middle + reach + 1));
  const CellGraph& graph = space.cellGraph();
  std::stable_sort(near.begin(), near.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return graph.arcWidth(a) > graph.arcWidth(b); });
  near.resize(std::min(near.size(), kJunctionTries));
  for (std::uint32_t node : near) {
    if (const std::optional<Pose2> junction = junctionIn(space, node)) return std::pair(*junction, node);
  }
  return std::nullopt;
}

/// Routes of fewer nodes than this per part are walked whole.
constexpr std::size_t kLeastNodesPerPart = 4;
/// At most this many parts: cut in four, the maze had a part whose junction took 10.8
/// ms to reach, more than the whole walk.
constexpr std::size_t kMostParts = 2;

/// The walk from `from` (in node `first`) to `to` (in node `last`) split in parts (up
/// to kMostParts, one per core), walked at once (docs/design.md section 7): the cell
/// graph's route is cut where the arcs of its nodes before make up a part's share of
/// them all (a walk's time goes mostly to turning inside nodes), at a junction in a
/// node near there (junctionNear), and each part is walked from one junction to the
/// next. None when there is one core, the route is short, a junction is not found or
/// a part's walk fails.
std::optional<RoutedPath> walkInParts(const FreeSpace& space, const Pose2& from, std::uint32_t first, const Pose2& to,
                                      std::uint32_t last, std::chrono::steady_clock::time_point deadline,
                                      const Cancellation& cancellation) {
  if (coreCount() < 2) return std::nullopt;
  const CellGraph& graph = space.cellGraph();
  const std::optional<std::vector<std::uint32_t>> route = graph.route(first, last);
  if (!route) return std::nullopt;
  const std::size_t parts = std::min({std::size_t{coreCount()}, kMostParts, route->size() / kLeastNodesPerPart});
  if (parts < 2) return std::nullopt;
  std::vector<double> arcsBefore{0};
  for (std::uint32_t node : *route) arcsBefore.push_back(arcsBefore.back() + graph.arcWidth(node));
  if (!(arcsBefore.back() > 0)) return std::nullopt;
  std::vector<Pose2> ends{from};
  std::vector<std::uint32_t> nodes{first};
  for (std::size_t part = 1; part < parts; ++part) {
    const double share = arcsBefore.back() * part / parts;
    const std::size_t middle = std::lower_bound(arcsBefore.begin(), arcsBefore.end(), share) - arcsBefore.begin() - 1;
    const std::optional<std::pair<Pose2, std::uint32_t>> junction = junctionNear(space, *route, middle, parts);
    if (!junction) return std::nullopt;
    ends.push_back(junction->first);
    nodes.push_back(junction->second);
  }
  ends.push_back(to);
  nodes.push_back(last);
  std::vector<std::optional<RoutedPath>> walked(parts);
  onEveryCore(
      parts, [] { return true; },
      [&](std::size_t part) {
        walked[part] =
            RouteWalker(space, deadline, cancellation).walk(ends[part], nodes[part], ends[part + 1], nodes[part + 1]);
      });
  RoutedPath joined{{from}, {}};
  for (const std::optional<RoutedPath>& part : walked) {
    if (!part) return std::nullopt;
    joined.waypoints.insert(joined.waypoints.end(), part->waypoints.begin() + 1, part->waypoints.end());
    joined.certified.insert(joined.certified.end(), part->certified.begin(), part->certified.end());
  }
  return joined;
}

}  // namespace

std::optional<RoutedPath> routePath(const FreeSpace& space, const Pose2& from, const Pose2& to,
                                    std::chrono::steady_clock::time_point deadline, const Cancellation& cancellation) {
  const std::optional<std::uint32_t> first = space.nodeOf(from), last = space.nodeOf(to);
  if (!first || !last) return std::nullopt;
  if (std::optional<RoutedPath> split = walkInParts(space, from, *first, to, *last, deadline, cancellation)) {
    return split;
  }
  return RouteWalker(space, deadline, cancellation).walk(from, *first, to, *last);
}

std::optional<RoutedPath> routePathInParts(const FreeSpace& space, const Pose2& from, const Pose2& to,
                                           std::chrono::steady_clock::time_point deadline,
                                           const Cancellation& cancellation) {
  const std::optional<std::uint32_t> first = space.nodeOf(from), last = space.nodeOf(to);
  if (!first || !last) return std::nullopt;
  return walkInParts(space, from, *first, to, *last, deadline, cancellation);
}

}  // namespace freespace
