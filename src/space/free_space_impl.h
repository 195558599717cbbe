#pragma once

// The parts of a FreeSpace, built (free_space.cpp) or read back (free_space_file.cpp).

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/space/free_space.h"
#include "freespace/topology/cell_graph.h"
#include "freespace/topology/free_cells.h"
#include "freespace/topology/slice_boundary_distance.h"

namespace freespace {

struct FreeSpace::Impl {
  /// What a query needs of its own: an AngleAlgebra memoizes and counts, so each
  /// thread that queries at once borrows one (with the rays and boundary distances
  /// over it) from a pool (borrowQueryTools).
  struct QueryTools {
    PredicateStatistics statistics;
    AngleAlgebra algebra{statistics};
    SliceRays rays;
    SliceBoundaryDistance boundary;
    QueryTools(const Impl& impl);
  };
  /// A QueryTools borrowed for one query: given back to the pool when it goes.
  class BorrowedTools {
   public:
    BorrowedTools(const Impl& impl, std::unique_ptr<QueryTools> tools) : impl_(impl), tools_(std::move(tools)) {}
    BorrowedTools(const BorrowedTools&) = delete;
    BorrowedTools& operator=(const BorrowedTools&) = delete;
    ~BorrowedTools();
    QueryTools* operator->() const { return tools_.get(); }

   private:
    const Impl& impl_;
    std::unique_ptr<QueryTools> tools_;
  };
  BorrowedTools borrowQueryTools() const;

  PredicateStatistics statistics;
  /// The construction's (and the lazy graph's): one thread at a time.
  mutable AngleAlgebra algebra{statistics};
  std::vector<StageTime> stageTimes;
  PerturbedMeshes meshes;
  Arrangement arrangement;
  /// Over `algebra`, for the construction and the graph.
  std::unique_ptr<SliceRays> rays;
  std::unique_ptr<ExactCollisionChecker> collision;
  std::vector<ShellSide> sides;
  std::unique_ptr<FreeCells> cells;
  /// Built on first use (FreeSpace::cellGraph), announced to `progress` and
  /// stopped by `cancellation` (those the construction was given).
  std::unique_ptr<CellGraph> graph;
  /// Built on first use (FreeSpace::sliceFaces).
  std::unique_ptr<SliceFaces> sliceFaces;
  /// Found with the slice faces or on first use (FreeSpace::cellBoxes).
  std::optional<std::vector<std::optional<PatchBox>>> cellBoxes;
  /// Guards the graph's, the slice faces' and the cell boxes' making on first use.
  mutable std::mutex firstUse;
  /// The query tools not borrowed now: most in slots taken and given back without a
  /// lock (a path query's halvings ask for clearances on every core, a lock shared by
  /// them took a seventh of each clearance's time), the rest under one.
  struct alignas(64) IdleSlot {
    std::atomic<QueryTools*> tools{nullptr};
  };
  static constexpr std::size_t kIdleSlots = 8;
  mutable std::array<IdleSlot, kIdleSlots> idleSlots;
  mutable std::mutex idleToolsMutex;
  mutable std::vector<std::unique_ptr<QueryTools>> idleTools;
  std::function<void(const std::string& stage)> progress;
  Cancellation cancellation;

  /// Builds everything from the meshes.
  Impl(const Mesh& robot, const Mesh& world, const FreeSpaceOptions& options);
  /// Empty: its parts are set by the reader of a saved free space, then finish().
  Impl() = default;
  /// Deletes the query tools in the idle slots.
  ~Impl();
  /// The rays and the collision test over the parts.
  void finish() {
    rays = std::make_unique<SliceRays>(arrangement, algebra);
    collision = std::make_unique<ExactCollisionChecker>(meshes.robot, meshes.world);
  }

  /// Each free cell's box (FreeSpace::cellBoxes).
  std::vector<std::optional<PatchBox>> findCellBoxes() const;
  RayHit firstHit(const SliceRays& queryRays, const Pose2& pose, const AlgebraicAngle& at) const;
  /// Where a configuration (`from`, exactly in the construction's coordinates, at
  /// angle `at`) lies, from the first sub-face met on a short way toward
  /// `boundaryPoint`, its nearest point of the boundary: far cheaper than the ray of
  /// firstHit, which decides when this way meets nothing or is degenerate.
  Location locationToward(const SliceRays& queryRays, const Pose2& pose, const std::array<Rational, 2>& from,
                          const AlgebraicAngle& at, const std::array<double, 2>& boundaryPoint) const;

  /// The free cell a sub-face bounds (its positive side), if it bounds one.
  std::optional<std::uint32_t> cellOfSubFace(SubFaceId face) const {
    return cells->cellOfShell(arrangement.shells.shellOf(face));
  }
  /// Free (with its cell) or blocked, from the first sub-face a ray meets: a point
  /// sees a sub-face's positive side across free space only if that side is free,
  /// i.e. its shell is free (a closed shell's sides are all free or all blocked, and
  /// an open shell bounds no free cell).
  Location locationOf(const RayHit& hit) const {
    if (hit.kind == RayHit::Kind::Nothing) return {true, FreeCells::kUnbounded};
    if (hit.kind == RayHit::Kind::OnSegment) return {false, 0};
    return locationSeeing(hit.face, hit.fromPositiveSide);
  }
  /// Where a point lies that sees a sub-face first, from its positive side or not (as
  /// locationOf).
  Location locationSeeing(SubFaceId face, bool fromPositiveSide) const {
    if (!fromPositiveSide) return {false, 0};
    const std::optional<std::uint32_t> cell = cellOfSubFace(face);
    if (!cell) return {false, 0};
    return {true, *cell};
  }
};

}  // namespace freespace
