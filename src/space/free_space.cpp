#include "freespace/space/free_space.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "free_space_impl.h"
#include "freespace/geometry/mesh_topology.h"
#include "freespace/geometry/patch_candidates.h"
#include "freespace/geometry/patch_segment.h"
#include "freespace/input_error.h"

namespace freespace {

namespace {

// Measured on the bundled and generated scenes, the construction's peak memory grows
// by 2.2 to 15 kB per patch candidate (2.4 kB on floor plans of 10,000 to 35,000
// triangles, more where patches cross often): 2 kB each is a lower bound.
constexpr double kLeastBytesPerCandidate = 2048;

// The memory the process holds now (its resident set, /proc/self/statm), in bytes;
// 0 where that cannot be read (the estimate stays a lower bound). Not the peak so
// far: loading may have held more than it keeps.
double residentBytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0;
  return resident * static_cast<double>(sysconf(_SC_PAGE_SIZE));
}

double physicalMemoryBytes() {
  return static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
}

// Refuses, before any patch is built, a scene whose construction needs more memory
// than the limit by the lower bound above: a clear error at once, not a machine
// that runs out of memory minutes later.
void requireMemoryFor(std::size_t candidates, const FreeSpaceOptions& options) {
  const double limit = options.memoryLimitBytes > 0 ? options.memoryLimitBytes : physicalMemoryBytes();
  const double needed = residentBytes() + kLeastBytesPerCandidate * static_cast<double>(candidates);
  if (needed <= limit) return;
  std::ostringstream problem;
  problem.precision(3);
  problem << "the construction needs at least " << needed / 1e9 << " GB (" << candidates
          << " candidate contacts of robot and environment features at 2 kB or more each), more than "
          << (options.memoryLimitBytes > 0 ? "the memory limit of " : "this machine's memory, ") << limit / 1e9
          << " GB";
  throw InputError(options.sourceName, problem.str());
}

}  // namespace

FreeSpace::Impl::Impl(const Mesh& robot, const Mesh& world, const FreeSpaceOptions& options)
    : progress(options.progress), cancellation(options.cancellation) {
  StageClock clock(options.progress, options.cancellation);
  meshes = clock.run("perturb", [&] {
    PerturbedMeshes perturbed = perturbMeshes(robot, world, options.perturbation);
    requireDistinctHeights(perturbed.robot, perturbed.world, options.sourceName);
    return perturbed;
  });
  const Cancellation& cancellation = options.cancellation;
  std::vector<PatchGeometry> geometries = clock.run("patches", [&] {
    const MeshTopology robotTopology(meshes.robot, statistics), worldTopology(meshes.world, statistics);
    requireMemoryFor(countPatchCandidates(meshes.robot, robotTopology, meshes.world, worldTopology), options);
    std::vector<Patch> patches =
        vertexFacetPatches(meshes.robot, robotTopology, meshes.world, worldTopology, algebra, cancellation);
    const std::vector<Patch> edgeEdge =
        edgeEdgePatches(meshes.robot, robotTopology, meshes.world, worldTopology, algebra, cancellation);
    patches.insert(patches.end(), edgeEdge.begin(), edgeEdge.end());
    return patchGeometries(patches, meshes.robot, robotTopology, meshes.world, worldTopology, statistics, cancellation);
  });
  arrangement = buildArrangement(std::move(geometries), algebra, clock);
  sides = clock.run("classification", [&] {
    finish();
    return classifyShells(arrangement, *rays, *collision, cancellation);
  });
  cells = clock.run("cells", [&] {
    return std::make_unique<FreeCells>(arrangement, *rays, sides, algebra, cancellation);
  });
  stageTimes = clock.times();
}

double peakMemoryMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in kilobytes on Linux
}

FreeSpace::FreeSpace(const Mesh& robot, const Mesh& world, const FreeSpaceOptions& options)
    : impl_(std::make_unique<Impl>(robot, world, options)) {}

FreeSpace::FreeSpace(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

FreeSpace::~FreeSpace() = default;

FreeSpace::Impl::QueryTools::QueryTools(const Impl& impl)
    : rays(impl.arrangement, algebra),
      boundary(impl.arrangement, algebra, [&impl](SubFaceId face) { return impl.cellOfSubFace(face).has_value(); }) {}

FreeSpace::Impl::~Impl() {
  for (IdleSlot& slot : idleSlots) delete slot.tools.exchange(nullptr);
}

FreeSpace::Impl::BorrowedTools::~BorrowedTools() {
  for (IdleSlot& slot : impl_.idleSlots) {
    QueryTools* empty = nullptr;
    if (slot.tools.compare_exchange_strong(empty, tools_.get(), std::memory_order_release)) {
      tools_.release();
      return;
    }
  }
  const std::lock_guard lock(impl_.idleToolsMutex);
  impl_.idleTools.push_back(std::move(tools_));
}

FreeSpace::Impl::BorrowedTools FreeSpace::Impl::borrowQueryTools() const {
  for (IdleSlot& slot : idleSlots) {
    if (slot.tools.load(std::memory_order_relaxed) == nullptr) continue;
    if (QueryTools* tools = slot.tools.exchange(nullptr, std::memory_order_acquire)) {
      return BorrowedTools(*this, std::unique_ptr<QueryTools>(tools));
    }
  }
  {
    const std::lock_guard lock(idleToolsMutex);
    if (!idleTools.empty()) {
      std::unique_ptr<QueryTools> tools = std::move(idleTools.back());
      idleTools.pop_back();
      return BorrowedTools(*this, std::move(tools));
    }
  }
  return BorrowedTools(*this, std::make_unique<QueryTools>(*this));
}

/// The first sub-face a ray from the configuration meets (toward -x, or +x when
/// that ray passes exactly through a vertex of the slice), at its rational angle.
RayHit FreeSpace::Impl::firstHit(const SliceRays& queryRays, const Pose2& pose, const AlgebraicAngle& at) const {
  // Exactly in the construction's coordinates.
  const Rational x = timesPowerOfTwo(pose.x, meshes.scale), y = timesPowerOfTwo(pose.y, meshes.scale);
  for (int direction : {-1, 1}) {
    const RayHit hit = queryRays.cast(at, {x, y}, direction);
    if (hit.kind != RayHit::Kind::Degenerate) return hit;
  }
  throw std::runtime_error("FreeSpace::locate: both rays from the configuration pass through vertices of its slice");
}

Location FreeSpace::Impl::locationToward(const SliceRays& queryRays, const Pose2& pose,
                                         const std::array<Rational, 2>& from, const AlgebraicAngle& at,
                                         const std::array<double, 2>& boundaryPoint) const {
  // The way's end may be any point (only its start is the configuration, exactly):
  // aimed in doubles about a thousandth of a radian beside the nearest point (often a
  // corner of the slice, where a ray through it cannot be decided in intervals) and
  // half as far again, to meet the piece there or its neighbour.
  const double x = pose.x * meshes.scale, y = pose.y * meshes.scale;
  const double towardX = boundaryPoint[0] - x, towardY = boundaryPoint[1] - y, skew = 1.0 / 1024;
  const std::array<double, 2> end{x + (towardX - skew * towardY) * 1.5, y + (towardY + skew * towardX) * 1.5};
  if (end[0] != x || end[1] != y) {
    const RayHit hit = queryRays.castTo(at, from, {Rational(end[0]), Rational(end[1])});
    if (hit.kind == RayHit::Kind::SubFace || hit.kind == RayHit::Kind::OnSegment) return locationOf(hit);
  }
  return locationOf(firstHit(queryRays, pose, at));
}

Location FreeSpace::locate(const Pose2& pose) const {
  const AlgebraicAngle at = AlgebraicAngle::rational(HalfAngle::fromRadians(pose.theta));
  const Impl::BorrowedTools tools = impl_->borrowQueryTools();
  return impl_->locationOf(impl_->firstHit(tools->rays, pose, at));
}

const CellGraph& FreeSpace::cellGraph() const {
  const std::lock_guard lock(impl_->firstUse);
  if (!impl_->graph) {
    if (impl_->progress) impl_->progress("cell graph");
    impl_->graph = std::make_unique<CellGraph>(
        impl_->arrangement, *impl_->rays, [this](SubFaceId face) { return cellOfSubFace(face); }, impl_->algebra,
        impl_->cancellation);
  }
  return *impl_->graph;
}

const SliceFaces& FreeSpace::sliceFaces() const {
  const CellGraph& graph = cellGraph();
  const std::lock_guard lock(impl_->firstUse);
  if (!impl_->sliceFaces) {
    impl_->sliceFaces = std::make_unique<SliceFaces>(
        impl_->arrangement, graph, [this](SubFaceId face) { return cellOfSubFace(face); }, impl_->algebra);
    // Every path query asks for its cell's box: found with what its walk needs.
    if (!impl_->cellBoxes) impl_->cellBoxes = impl_->findCellBoxes();
  }
  return *impl_->sliceFaces;
}

std::optional<std::uint32_t> FreeSpace::nodeOf(const Pose2& pose) const { return locateNode(pose).node; }

NodeLocation FreeSpace::locateNode(const Pose2& pose) const {
  const CellGraph& graph = cellGraph();
  const AlgebraicAngle at = AlgebraicAngle::rational(HalfAngle::fromRadians(pose.theta));
  const Impl::BorrowedTools tools = impl_->borrowQueryTools();
  const RayHit hit = impl_->firstHit(tools->rays, pose, at);
  NodeLocation answer{impl_->locationOf(hit), std::nullopt};
  if (answer.location.free) answer.node = graph.nodeOf(hit, at, tools->algebra);
  return answer;
}

Clearance FreeSpace::clearance(const Pose2& pose, double relativeWidth, double expected,
                               const std::optional<Location>& location) const {
  Clearance result;
  const AlgebraicAngle at = AlgebraicAngle::rational(HalfAngle::fromRadians(pose.theta));
  const double scale = impl_->meshes.scale;
  const Rational x = timesPowerOfTwo(pose.x, scale), y = timesPowerOfTwo(pose.y, scale);
  const Impl::BorrowedTools tools = impl_->borrowQueryTools();
  const std::optional<BoundaryDistance> found = tools->boundary.nearest(at, {x, y}, relativeWidth, expected * scale);
  if (location) {
    result.location = *location;
  } else if (found && found->fromPositiveSide.has_value()) {
    // Its way to the nearest point meets that sub-face first.
    result.location = impl_->locationSeeing(found->face, *found->fromPositiveSide);
  } else if (found) {
    result.location = impl_->locationToward(tools->rays, pose, {x, y}, at, found->nearest);
  } else {
    result.location = impl_->locationOf(impl_->firstHit(tools->rays, pose, at));
  }
  if (!found) {
    const double unbounded = result.location.free ? HUGE_VAL : -HUGE_VAL;
    result.lower = result.upper = unbounded;
    return result;
  }
  // Back in the input's units: dividing by a power of two keeps the bounds exact.
  const double low = found->distance.lower() / scale, high = found->distance.upper() / scale;
  result.lower = result.location.free ? low : -high;
  result.upper = result.location.free ? high : -low;
  result.nearest = {found->nearest[0] / scale, found->nearest[1] / scale};
  const double dx = result.nearest[0] - pose.x, dy = result.nearest[1] - pose.y, norm = std::hypot(dx, dy);
  if (high > 0 && norm > 0) result.direction = {dx / norm, dy / norm};
  const PatchGeometry& patch = impl_->arrangement.patches[found->face.patch];
  result.contact = patch.patch.contact;
  result.contactVertices = patch.line.vertices;
  result.contactPatch = found->face.patch;
  return result;
}

std::size_t FreeSpace::cellCount() const { return impl_->cells->count(); }

std::vector<std::optional<PatchBox>> FreeSpace::Impl::findCellBoxes() const {
  // The bounded free cells that each patch's sub-faces bound.
  std::vector<std::vector<std::uint32_t>> cellsOfPatch(arrangement.patches.size());
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    for (std::uint32_t face = 0; face < arrangement.subdivisions[patch].faceCount; ++face) {
      const std::optional<std::uint32_t> cell = cellOfSubFace({patch, face});
      if (cell && *cell != FreeCells::kUnbounded) cellsOfPatch[patch].push_back(*cell);
    }
  }
  // Each cell's box holds the boxes (those of the index) of the patches bounding it.
  std::vector<std::optional<PatchBox>> boxes(cells->count());
  for (const auto& [box, patch] : arrangement.boxIndex->boxes()) {
    for (std::uint32_t cell : cellsOfPatch[patch]) {
      if (!boxes[cell]) {
        boxes[cell] = box;
        continue;
      }
      for (int axis = 0; axis < 3; ++axis) {
        boxes[cell]->low[axis] = std::min(boxes[cell]->low[axis], box.low[axis]);
        boxes[cell]->high[axis] = std::max(boxes[cell]->high[axis], box.high[axis]);
      }
    }
  }
  // In the input's coordinates.
  for (std::optional<PatchBox>& box : boxes) {
    if (!box) continue;
    for (int axis = 0; axis < 2; ++axis) {
      box->low[axis] /= meshes.scale;
      box->high[axis] /= meshes.scale;
    }
  }
  return boxes;
}

const std::vector<std::optional<PatchBox>>& FreeSpace::cellBoxes() const {
  const std::lock_guard lock(impl_->firstUse);
  if (!impl_->cellBoxes) impl_->cellBoxes = impl_->findCellBoxes();
  return *impl_->cellBoxes;
}

std::size_t FreeSpace::shellCount() const { return impl_->arrangement.shells.count(); }
std::size_t FreeSpace::freeShellCount() const {
  return static_cast<std::size_t>(std::count(impl_->sides.begin(), impl_->sides.end(), ShellSide::Free));
}
const Arrangement& FreeSpace::arrangement() const { return impl_->arrangement; }
std::optional<std::uint32_t> FreeSpace::cellOfShell(std::uint32_t shell) const {
  return impl_->cells->cellOfShell(shell);
}
std::optional<std::uint32_t> FreeSpace::cellOfSubFace(SubFaceId face) const {
  return impl_->cellOfSubFace(face);
}
AngleAlgebra& FreeSpace::algebra() const { return impl_->algebra; }
const PerturbedMeshes& FreeSpace::meshes() const { return impl_->meshes; }
const std::vector<StageTime>& FreeSpace::stageTimes() const { return impl_->stageTimes; }
const PredicateStatistics& FreeSpace::statistics() const { return impl_->statistics; }

}  // namespace freespace
