#include "freespace/topology/free_cells.h"

#include <boost/pending/disjoint_sets.hpp>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <unordered_map>

#include "freespace/topology/slice_pieces.h"

namespace freespace {

namespace {

using slices::Point;

/// The leftmost point of a shell's slice at one angle.
struct Leftmost {
  AlgebraicAngle angle;
  Point point;
};

/// The distances tried from a shell's leftmost point, relative to its size.
const Rational kLargest = powerOfHalf(24);
const Rational kSmallest = powerOfHalf(200);

bool leftOf(const Point& a, const Point& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); }

/// Nests the free closed shells (see FreeCells).
class Nesting {
 public:
  Nesting(const Arrangement& arrangement, const SliceRays& rays, const std::vector<ShellSide>& sides,
          AngleAlgebra& algebra)
      : arrangement_(arrangement), rays_(rays), sides_(sides), algebra_(algebra),
        members_(arrangement.shells.count()), angles_(arrangement.shells.count()),
        leftmost_(arrangement.shells.count()), rank_(arrangement.shells.count() + 1),
        parent_(arrangement.shells.count() + 1), sets_(rank_.data(), parent_.data()) {
    for (std::size_t i = 0; i < parent_.size(); ++i) sets_.make_set(i);
    std::vector<double> lowestX(arrangement.patches.size(), HUGE_VAL);
    for (const auto& [box, patch] : arrangement.boxIndex->boxes()) lowestX[patch] = std::min(lowestX[patch], box.low[0]);
    for (std::uint32_t patch = 0; patch < arrangement.subdivisions.size(); ++patch) {
      for (std::uint32_t face = 0; face < arrangement.subdivisions[patch].faceCount; ++face) {
        members_[arrangement.shells.shellOf({patch, face})].push_back({{patch, face}, lowestX[patch]});
      }
    }
    for (auto& members : members_) {
      std::sort(members.begin(), members.end(), [](const Member& a, const Member& b) { return a.lowestX < b.lowestX; });
    }
  }

  /// Shoots every free shell's ray until no angle set grows; returns the component
  /// of each shell (the unbounded cell's node is the last).
  std::vector<std::size_t> run(const Cancellation& cancellation) {
    std::deque<std::uint32_t> work;
    for (std::uint32_t shell = 0; shell < sides_.size(); ++shell) {
      if (sides_[shell] != ShellSide::Free) continue;
      angles_[shell].push_back(firstSample(shell));
      work.push_back(shell);
    }
    while (!work.empty()) {
      cancellation.check();
      const std::uint32_t shell = work.front();
      work.pop_front();
      if (const std::optional<std::uint32_t> grown = shoot(shell)) work.push_back(*grown);
    }
    std::vector<std::size_t> components;
    for (std::size_t node = 0; node < parent_.size(); ++node) components.push_back(sets_.find_set(node));
    return components;
  }

 private:
  /// A rational angle where the shell has a slice: the sample of one of its
  /// sub-faces' slabs.
  AlgebraicAngle firstSample(std::uint32_t shell) const {
    for (const auto& [face, lowestX] : members_[shell]) {
      for (const PatchSlab& slab : arrangement_.subdivisions[face.patch].slabs) {
        if (std::find(slab.faces.begin(), slab.faces.end(), face.face) != slab.faces.end()) return slab.sample;
      }
    }
    throw std::logic_error("FreeCells: a free shell has no slab");
  }

  /// The leftmost point of the shell's slice at a rational angle, if it has one:
  /// the ends of its sub-faces' pieces are first bounded in double intervals, and
  /// only those that may be leftmost are computed exactly. Sub-faces come by the
  /// left end of their patches' boxes: none past the leftmost end found so far
  /// need be looked at.
  std::optional<Point> leftmostAt(std::uint32_t shell, const AlgebraicAngle& angle) const {
    struct PieceEnd {
      SubFaceId face;
      const PatchSlab* slab;
      std::size_t gap;
      double lowestX;
    };
    std::vector<PieceEnd> ends;
    double leftmostX = HUGE_VAL;  // no piece end lies right of every point left of this
    {
      RoundingScope rounding;
      const slices::IntervalSlice slice(angle);
      for (const auto& [face, lowestX] : members_[shell]) {
        if (lowestX > leftmostX) break;
        if (!algebra_.contains(arrangement_.patches[face.patch].patch.range, angle)) continue;
        const PatchSlab* slab = slabAt(arrangement_.subdivisions[face.patch], angle, algebra_);
        if (!slab) throw std::logic_error("FreeCells: a shell's angle is an event of one of its patches");
        const PatchGeometry& patch = arrangement_.patches[face.patch];
        const std::array<Interval, 2> end0 = slice.end(patch, 0), end1 = slice.end(patch, 1);
        for (std::size_t gap = 0; gap < slab->faces.size(); ++gap) {
          if (slab->faces[gap] != face.face) continue;
          const auto piece = slice.pieceOf(arrangement_, face.patch, *slab, gap);
          Interval x(-HUGE_VAL, HUGE_VAL);
          if (piece) {
            const Interval low = end0[0] + piece->first * (end1[0] - end0[0]);
            const Interval high = end0[0] + piece->second * (end1[0] - end0[0]);
            x = Interval(std::min(low.lower(), high.lower()), std::min(low.upper(), high.upper()));
          }
          ends.push_back({face, slab, gap, x.lower()});
          leftmostX = std::min(leftmostX, x.upper());
        }
      }
    }
    std::optional<Point> best;
    const auto [cosine, sine] = exactCosSin(angle);
    for (const PieceEnd& end : ends) {
      if (end.lowestX > leftmostX) continue;
      const slices::ExactSegment segment = slices::segmentAt(arrangement_.patches[end.face.patch], cosine, sine);
      const auto [low, high] =
          slices::pieceOf(arrangement_, end.face.patch, *end.slab, end.gap, segment, cosine, sine).value();
      for (const Rational& lambda : {low, high}) {
        const Point point = segment.at(lambda);
        if (!best || leftOf(point, *best)) best = point;
      }
    }
    return best;
  }

  /// The leftmost point over the shell's angles; each angle is looked at once, the
  /// best so far kept as angles are added.
  Leftmost leftmost(std::uint32_t shell) {
    LeftmostSoFar& known = leftmost_[shell];
    for (; known.angles < angles_[shell].size(); ++known.angles) {
      const AlgebraicAngle& angle = angles_[shell][known.angles];
      const std::optional<Point> point = leftmostAt(shell, angle);
      if (point && (!known.best || leftOf(*point, known.best->point))) known.best = Leftmost{angle, *point};
    }
    if (!known.best) throw std::logic_error("FreeCells: a shell has no slice at its angles");
    return *known.best;
  }

  /// Which side of a shell a point just outside it near its leftmost point lies on,
  /// by the first sub-face a ray from it toward +x meets: the shell itself from its
  /// free side (the point is in the shell's cell: the shell is a hole in it), or a
  /// blocked side (the point is blocked: the shell is its cell's outer shell).
  enum class Outside { Hole, Outer, Unknown };

  Outside outsideAt(std::uint32_t shell, const AlgebraicAngle& angle, const Point& start) const {
    const RayHit back = rays_.cast(angle, start, +1);
    if (back.kind != RayHit::Kind::SubFace) return Outside::Unknown;
    const std::uint32_t seen = arrangement_.shells.shellOf(back.face);
    if (!back.fromPositiveSide || sides_[seen] != ShellSide::Free) return Outside::Outer;
    return seen == shell ? Outside::Hole : Outside::Unknown;
  }

  /// The ray of one shell from a point q up-left (or down-left) of its leftmost point
  /// p, outside the shell (left of its whole slice): near p the outside is the free
  /// cell when the shell is a hole in it and blocked when it is its cell's outer
  /// shell. The answer is taken once two points at distances d and d / 2^16 from p
  /// agree (far points may see other obstacles), d shrinking from 2^-24 of the
  /// shell's size. A hole's ray toward -x from the nearer point joins it to the shell
  /// it meets, whose angle set grows by the ray's angle if it did not hold it (that
  /// shell is returned, to shoot again).
  std::optional<std::uint32_t> shoot(std::uint32_t shell) {
    const Leftmost from = leftmost(shell);
    const Rational scale = 1 + abs(from.point[0]) + abs(from.point[1]);
    const auto near = [&](const Rational& distance, int up) {
      return Point{from.point[0] - distance, from.point[1] + up * distance};
    };
    for (Rational distance = scale * kLargest; distance > scale * kSmallest; distance /= 256) {
      for (int up : {1, -1}) {
        const Outside far = outsideAt(shell, from.angle, near(distance, up));
        const Point start = near(distance / 65536, up);
        if (far == Outside::Unknown || outsideAt(shell, from.angle, start) != far) continue;
        if (far == Outside::Outer) return std::nullopt;
        const RayHit hit = rays_.cast(from.angle, start, -1);
        if (hit.kind == RayHit::Kind::Nothing) {
          sets_.union_set(std::size_t{shell}, sides_.size());
          return std::nullopt;
        }
        if (hit.kind != RayHit::Kind::SubFace) continue;
        const std::uint32_t other = arrangement_.shells.shellOf(hit.face);
        if (!hit.fromPositiveSide || sides_[other] != ShellSide::Free) {
          throw std::logic_error("FreeCells: a ray in free space meets a shell that bounds no free cell");
        }
        sets_.union_set(std::size_t{shell}, std::size_t{other});
        const bool known = std::any_of(angles_[other].begin(), angles_[other].end(),
                                       [&](const AlgebraicAngle& a) { return algebra_.compare(a, from.angle) == 0; });
        if (known) return std::nullopt;
        angles_[other].push_back(from.angle);
        return other;
      }
    }
    throw std::runtime_error("FreeCells: no ray could be shot from a shell's leftmost point");
  }

  const Arrangement& arrangement_;
  const SliceRays& rays_;
  const std::vector<ShellSide>& sides_;
  AngleAlgebra& algebra_;
  /// A sub-face of a shell with the left end of its patch's boxes.
  struct Member {
    SubFaceId face;
    double lowestX;
  };
  /// The leftmost point over a shell's first `angles` angles.
  struct LeftmostSoFar {
    std::size_t angles = 0;
    std::optional<Leftmost> best;
  };

  std::vector<std::vector<Member>> members_;
  std::vector<std::vector<AlgebraicAngle>> angles_;
  std::vector<LeftmostSoFar> leftmost_;
  std::vector<std::size_t> rank_, parent_;
  boost::disjoint_sets<std::size_t*, std::size_t*> sets_;
};

}  // namespace

FreeCells::FreeCells(const Arrangement& arrangement, const SliceRays& rays, const std::vector<ShellSide>& sides,
                     AngleAlgebra& algebra, const Cancellation& cancellation)
    : cellOfShell_(sides.size()) {
  const std::vector<std::size_t> components = Nesting(arrangement, rays, sides, algebra).run(cancellation);
  std::unordered_map<std::size_t, std::uint32_t> cellOfComponent{{components.back(), kUnbounded}};
  for (std::uint32_t shell = 0; shell < sides.size(); ++shell) {
    if (sides[shell] != ShellSide::Free) continue;
    const auto found = cellOfComponent.emplace(components[shell], static_cast<std::uint32_t>(cellOfComponent.size()));
    cellOfShell_[shell] = found.first->second;
  }
  count_ = cellOfComponent.size();
}

std::optional<std::uint32_t> FreeCells::cellOfShell(std::uint32_t shell) const { return cellOfShell_[shell]; }

}  // namespace freespace
