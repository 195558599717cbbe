#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/geometry/perturbed_meshes.h"
#include "freespace/geometry/stage_clock.h"
#include "freespace/numbers/predicate_statistics.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/topology/arrangement.h"
#include "freespace/topology/cell_graph.h"
#include "freespace/topology/slice_faces.h"

namespace freespace {

struct FreeSpaceOptions {
  PerturbationSettings perturbation;
  /// Names the input in errors (the construction needs every vertex height distinct
  /// after perturbation: an InputError naming it otherwise).
  std::string sourceName = "scene";
  /// Called as each construction stage starts, with the stage's name.
  std::function<void(const std::string& stage)> progress;
  /// Polled throughout the construction: once it asks, the constructor throws
  /// Cancelled (within a fraction of a second).
  Cancellation cancellation;
  /// The memory the construction may need, in bytes (0: the machine's physical
  /// memory). A scene that needs more by a lower-bound estimate made before any patch
  /// is built is an InputError naming sourceName, with the estimate.
  double memoryLimitBytes = 0;
};

/// Where a configuration lies: in a free cell (0 is the unbounded one), or blocked
/// (the robot touches or overlaps the environment).
struct Location {
  bool free = false;
  std::uint32_t cell = 0;
};

/// Where a configuration lies, with its node of the cell graph when it is free.
struct NodeLocation {
  Location location;
  std::optional<std::uint32_t> node;
};

/// The clearance of a configuration (docs/design.md section 7): how far the robot can
/// slide horizontally, in any direction, before it touches the environment; for a
/// blocked configuration minus the shortest horizontal slide that frees it.
struct Clearance {
  Location location;
  /// The clearance lies in [lower, upper] (certified); 0 when touching; both
  /// infinite when nothing can be touched at the configuration's angle.
  double lower = 0, upper = 0;
  /// The witness: the contact met by sliding the robot by |clearance| along
  /// `direction` (a unit vector; zero when touching), to (x, y) = `nearest`: its
  /// kind, its features (as in Contact) and their vertices (ContactPoints::vertices:
  /// VF robot vertex, then the environment triangle's; FV environment vertex, then
  /// the robot triangle's; EE the robot edge's two, then the environment edge's).
  std::optional<Contact> contact;
  std::array<std::uint32_t, 4> contactVertices{};
  /// The witness's patch, with `contact` (its index in FreeSpace::arrangement().patches).
  std::uint32_t contactPatch = 0;
  std::array<double, 2> direction{};
  std::array<double, 2> nearest{};
};

/// The largest resident memory of this process so far, in megabytes (for the
/// statistics of a construction).
double peakMemoryMegabytes();

/// The exact free space of a robot translating and turning among a fixed
/// environment (docs/design.md sections 3 to 6), built once from the two meshes: the
/// perturbed meshes, the patches and their arrangement, its shells classified by
/// exact collision tests and nested into free cells. Its queries (locate, clearance,
/// nodeOf, locateNode, cellGraph, sliceFaces and the accessors of its parts) may be
/// asked from several threads at once, each with its own predicates; algebra() and
/// statistics() are the construction's, which also build the graph on first use:
/// one thread, not while the graph is first built (SliceFaces and CellGraph queries
/// take an AngleAlgebra: one per thread).
class FreeSpace {
 public:
  FreeSpace(const Mesh& robot, const Mesh& world, const FreeSpaceOptions& options = {});
  ~FreeSpace();
  FreeSpace(const FreeSpace&) = delete;
  FreeSpace& operator=(const FreeSpace&) = delete;

  /// Saves the built structure (perturbed meshes, arrangement, shells' sides, cells)
  /// to a versioned file with a checksum (a Boost.Serialization binary archive
  /// inside: for machines of one architecture).
  /// Refuses (InputError) to replace an existing file unless `overwrite`.
  void save(const std::string& path, bool overwrite = false) const;
  /// How much of a saved free space `load` checks before it returns.
  enum class LoadCheck {
    /// Everything but the functions' exact coefficients, which are decoded and checked
    /// when a query first needs them (most never are): a file altered behind a valid
    /// checksum can then be refused by that query (InputError naming the file).
    Structure,
    /// Everything, the exact coefficients too (slower).
    Everything,
  };
  /// Reads a saved free space back, without rebuilding; its statistics are empty. A
  /// file that is not one, of another format version, damaged or inconsistent is an
  /// InputError naming it.
  static std::unique_ptr<FreeSpace> load(const std::string& path, LoadCheck check = LoadCheck::Structure);

  /// From the arrangement alone, exactly: the first sub-face a ray at the
  /// configuration's angle meets (toward -x, or +x when that ray passes exactly
  /// through a vertex of the slice) tells free and the cell when the ray arrives
  /// from its positive side and its shell is free; blocked otherwise (a
  /// configuration on a segment touches the environment). A ray that meets nothing
  /// starts in the unbounded cell. Configurations are of the perturbed meshes, in
  /// the input's coordinates (as every answer of this class but the internal
  /// structures arrangement() and meshes(), which are scaled by meshes().scale).
  Location locate(const Pose2& pose) const;

  /// The clearance of a configuration, from the nearest point of the free space's
  /// boundary in its slice (pieces of sub-faces that bound free cells), certified to
  /// `relativeWidth` (exact arithmetic where double intervals are wider; they rarely
  /// are wider than 1e-11). `expected`, when known, is about how far that point lies
  /// (|clearance|, or a bound on it): a hint that makes the search look at fewer of
  /// the boundary's pieces and changes no answer. `location`, when given, is where the
  /// configuration lies, certified by the caller (as the clearance's Lipschitz bound
  /// certifies it near a free configuration of known clearance, docs/design.md
  /// section 7): the ray that would place it is not cast.
  Clearance clearance(const Pose2& pose, double relativeWidth = 1e-13, double expected = HUGE_VAL,
                      const std::optional<Location>& location = std::nullopt) const;

  /// The free cell graph (docs/design.md section 7), built on first use (announced
  /// and cancellable as the construction was), in the construction's coordinates
  /// (as arrangement()).
  const CellGraph& cellGraph() const;
  /// The faces of the slices over the cell graph (SliceFaces: what a path query's
  /// route walks), built on first use after the graph.
  const SliceFaces& sliceFaces() const;
  /// The node of the cell graph whose face holds a configuration; none when it is
  /// blocked.
  std::optional<std::uint32_t> nodeOf(const Pose2& pose) const;
  /// locate and nodeOf from one ray.
  NodeLocation locateNode(const Pose2& pose) const;

  /// The number of free cells, the unbounded one included.
  std::size_t cellCount() const;
  /// A box in (x, y, theta) holding each bounded free cell: the union of the boxes
  /// of the patches its boundary lies on (patchBoxes); none for the unbounded cell.
  /// Found with sliceFaces (path queries need both) or on first use; the reference
  /// lasts as long as the free space.
  const std::vector<std::optional<PatchBox>>& cellBoxes() const;
  std::size_t shellCount() const;
  std::size_t freeShellCount() const;
  /// The arrangement, in the construction's coordinates (the input's times meshes().scale).
  const Arrangement& arrangement() const;
  /// The free cell a shell bounds (its positive side), if it bounds one.
  std::optional<std::uint32_t> cellOfShell(std::uint32_t shell) const;
  /// The free cell a sub-face bounds (its positive side), if it bounds one.
  std::optional<std::uint32_t> cellOfSubFace(SubFaceId face) const;
  /// The exact predicates the structure was built with (for reading it further):
  /// they memoize and count, so one thread at a time (queries borrow their own).
  AngleAlgebra& algebra() const;
  /// The perturbed meshes, in the construction's coordinates (the input's times their scale).
  const PerturbedMeshes& meshes() const;
  const std::vector<StageTime>& stageTimes() const;
  /// The construction's predicate counts (and the graph's, once built); queries
  /// count in their own.
  const PredicateStatistics& statistics() const;

 private:
  struct Impl;
  explicit FreeSpace(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace freespace
