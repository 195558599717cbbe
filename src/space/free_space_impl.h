#pragma once

// The parts of a FreeSpace, built (free_space.cpp) or read back (free_space_file.cpp).

#include <memory>
#include <vector>

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/space/free_space.h"
#include "freespace/topology/cell_graph.h"
#include "freespace/topology/free_cells.h"
#include "freespace/topology/slice_boundary_distance.h"

namespace freespace {

struct FreeSpace::Impl {
  PredicateStatistics statistics;
  mutable AngleAlgebra algebra{statistics};
  std::vector<StageTime> stageTimes;
  PerturbedMeshes meshes;
  Arrangement arrangement;
  std::unique_ptr<SliceRays> rays;
  std::unique_ptr<SliceBoundaryDistance> boundary;
  std::unique_ptr<ExactCollisionChecker> collision;
  std::vector<ShellSide> sides;
  std::unique_ptr<FreeCells> cells;
  /// Built on first use (FreeSpace::cellGraph), announced to `progress` and
  /// stopped by `cancellation` (those the construction was given).
  std::unique_ptr<CellGraph> graph;
  /// Built on first use (FreeSpace::sliceFaces).
  std::unique_ptr<SliceFaces> sliceFaces;
  std::function<void(const std::string& stage)> progress;
  Cancellation cancellation;

  /// Builds everything from the meshes.
  Impl(const Mesh& robot, const Mesh& world, const FreeSpaceOptions& options);
  /// Empty: its parts are set by the reader of a saved free space, then finish().
  Impl() = default;
  /// The rays, the boundary distances and the collision test over the parts (the
  /// distances ask `cells`, set after this).
  void finish() {
    rays = std::make_unique<SliceRays>(arrangement, algebra);
    boundary = std::make_unique<SliceBoundaryDistance>(arrangement, algebra, [this](SubFaceId face) {
      return cells->cellOfShell(arrangement.shells.shellOf(face)).has_value();
    });
    collision = std::make_unique<ExactCollisionChecker>(meshes.robot, meshes.world);
  }

  RayHit firstHit(const Pose2& pose, const AlgebraicAngle& at) const;
  /// Where a configuration (`from`, exactly in the construction's coordinates, at
  /// angle `at`) lies, from the first sub-face met on a short way toward
  /// `boundaryPoint`, its nearest point of the boundary: far cheaper than the ray of
  /// firstHit, which decides when this way meets nothing or is degenerate.
  Location locationToward(const Pose2& pose, const std::array<Rational, 2>& from, const AlgebraicAngle& at,
                          const std::array<double, 2>& boundaryPoint) const;

  /// Free (with its cell) or blocked, from the first sub-face a ray meets: a point
  /// sees a sub-face's positive side across free space only if that side is free,
  /// i.e. its shell is free (a closed shell's sides are all free or all blocked, and
  /// an open shell bounds no free cell).
  Location locationOf(const RayHit& hit) const {
    if (hit.kind == RayHit::Kind::Nothing) return {true, FreeCells::kUnbounded};
    if (hit.kind == RayHit::Kind::OnSegment || !hit.fromPositiveSide) return {false, 0};
    const std::optional<std::uint32_t> cell = cells->cellOfShell(arrangement.shells.shellOf(hit.face));
    if (!cell) return {false, 0};
    return {true, *cell};
  }
};

}  // namespace freespace
