#include "freespace/topology/free_cells.h"

#include <boost/pending/disjoint_sets.hpp>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <unordered_map>

#include "slice_nesting.h"

namespace freespace {

namespace {

using slices::Point;

/// The leftmost point of a shell's slice at one angle.
struct Leftmost {
  AlgebraicAngle angle;
  Point point;
};

using slices::leftOf;

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

  /// The leftmost point of the shell's slice at a rational angle, if it has one.
  /// Sub-faces come by the left end of their patches' boxes: none past the leftmost
  /// end found so far need be looked at.
  std::optional<Point> leftmostAt(std::uint32_t shell, const AlgebraicAngle& angle) const {
    slices::LeftmostEnd leftmost(arrangement_, angle);
    for (const auto& [face, lowestX] : members_[shell]) {
      if (!leftmost.worthOffering(lowestX)) break;
      if (!algebra_.contains(arrangement_.patches[face.patch].patch.range, angle)) continue;
      const PatchSlab* slab = slabAt(arrangement_.subdivisions[face.patch], angle, algebra_);
      if (!slab) throw std::logic_error("FreeCells: a shell's angle is an event of one of its patches");
      for (std::size_t gap = 0; gap < slab->faces.size(); ++gap) {
        if (slab->faces[gap] == face.face) leftmost.offer(face.patch, *slab, gap);
      }
    }
    return leftmost.exact();
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

  /// What a ray toward +x from just left of a shell's leftmost point meets: the
  /// shell itself from its free side (the shell is a hole in its cell), or a blocked
  /// side (the shell is its cell's outer shell).
  slices::Outside outsideSeen(std::uint32_t shell, const RayHit& hit) const {
    if (hit.kind != RayHit::Kind::SubFace) return slices::Outside::Unknown;
    const std::uint32_t seen = arrangement_.shells.shellOf(hit.face);
    if (!hit.fromPositiveSide || sides_[seen] != ShellSide::Free) return slices::Outside::Outer;
    return seen == shell ? slices::Outside::Hole : slices::Outside::Unknown;
  }

  /// The ray of one shell from just left of its leftmost point (slices::lookLeftOf):
  /// a hole's ray toward -x joins it to the shell it meets, whose angle set grows by
  /// the ray's angle if it did not hold it (that shell is returned, to shoot again).
  std::optional<std::uint32_t> shoot(std::uint32_t shell) {
    const Leftmost from = leftmost(shell);
    const slices::LeftOfLeftmost look = slices::lookLeftOf(
        rays_, from.angle, from.point, [&](const RayHit& hit) { return outsideSeen(shell, hit); });
    if (!look.hole) return std::nullopt;
    if (look.leftward.kind == RayHit::Kind::Nothing) {
      sets_.union_set(std::size_t{shell}, sides_.size());
      return std::nullopt;
    }
    const std::uint32_t other = arrangement_.shells.shellOf(look.leftward.face);
    if (!look.leftward.fromPositiveSide || sides_[other] != ShellSide::Free) {
      throw std::logic_error("FreeCells: a ray in free space meets a shell that bounds no free cell");
    }
    sets_.union_set(std::size_t{shell}, std::size_t{other});
    const bool known = std::any_of(angles_[other].begin(), angles_[other].end(),
                                   [&](const AlgebraicAngle& a) { return algebra_.compare(a, from.angle) == 0; });
    if (known) return std::nullopt;
    angles_[other].push_back(from.angle);
    return other;
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
