#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "freespace/topology/slice_ray.h"

namespace freespace {

/// A node of the free cell graph (docs/design.md section 7): one connected face of
/// the slice of a free cell over a run of consecutive open intervals between
/// critical angles, along which the slice's boundary loops neither appear, vanish,
/// split nor merge (so the face keeps its loops and its holes).
struct CellGraphNode {
  std::uint32_t cell = 0;
  /// Its angles: the intervals firstInterval .. lastInterval, i.e. the open arc from
  /// CellGraph::criticalAngles()[firstInterval] to the critical angle after
  /// lastInterval (counterclockwise; the last interval wraps around to the first
  /// critical angle).
  std::uint32_t firstInterval = 0;
  std::uint32_t lastInterval = 0;
  /// A rational angle inside its first interval, and a point of the face at that
  /// angle (rounded to doubles from an exact point between two boundary pieces).
  AlgebraicAngle sample = AlgebraicAngle::rational(0, 0.0);
  std::array<double, 2> point{};
  /// The (x, y) box of the face's outer loop at `sample` (low x, low y, high x,
  /// high y; rounded outward); infinite for the unbounded face.
  std::array<double, 4> box{};
};

/// Faces that overlap at the critical angle between the last interval of `from` and
/// the first interval of `to`.
struct CellGraphEdge {
  std::uint32_t from = 0;
  std::uint32_t to = 0;
  /// Index of that critical angle in CellGraph::criticalAngles().
  std::uint32_t angle = 0;
};

/// The free cell graph: the free cells cut into faces of their slices over angle
/// intervals (nodes), joined where faces of neighbouring intervals overlap (edges).
///
/// Critical angles are the ends of the slabs of the patches that bound free cells
/// (where a piece of the slices' boundary appears, vanishes or changes its
/// neighbours). Over each open interval between consecutive critical angles the
/// boundary pieces are fixed, each joined to the next across a curve or a spiral;
/// the loops they form are nested at a rational angle inside by rays
/// (slices::lookLeftOf), which gives the faces. Where every loop continues (through
/// pieces of the same sub-faces) into exactly one loop of the next interval and
/// back, the faces continue too and their nodes grow; elsewhere the next interval's
/// faces are new nodes, joined to the previous ones by the loops they share pieces
/// with (or sub-faces glued across a horizontal edge at that angle). Unbounded faces
/// of neighbouring intervals always overlap. Start and goal of a problem are in one
/// cell iff their nodes are joined by a path of edges.
class CellGraph {
 public:
  /// The cell a sub-face bounds (its positive side), if it bounds one.
  using CellOfFace = std::function<std::optional<std::uint32_t>(SubFaceId)>;

  /// The node of a piece's face from an interval on.
  struct NodeRun {
    std::uint32_t interval;
    std::uint32_t node;
  };

  /// What a graph holds besides the arrangement (as saved with a free space).
  struct Parts {
    /// Increasing in AngleAlgebra::compare; none when no free cell's slice ever
    /// changes (then one interval holds every angle).
    std::vector<AlgebraicAngle> criticalAngles;
    std::vector<CellGraphNode> nodes;
    std::vector<CellGraphEdge> edges;
    /// For every piece (gap of a slab; patch by patch, slab by slab), the node of its
    /// face from each interval on where that changes (none for pieces of no free
    /// cell); the same for the unbounded face.
    std::vector<std::vector<NodeRun>> runsOfPiece;
    std::vector<NodeRun> unboundedRuns;
  };

  CellGraph(const Arrangement& arrangement, const SliceRays& rays, const CellOfFace& cellOf, AngleAlgebra& algebra,
            const Cancellation& cancellation = {});
  /// A graph read back, its parts checked against the arrangement and the number of
  /// cells: std::invalid_argument naming the part that does not fit.
  CellGraph(const Arrangement& arrangement, Parts parts, std::size_t cellCount, AngleAlgebra& algebra);

  const Parts& parts() const { return parts_; }
  const std::vector<AlgebraicAngle>& criticalAngles() const { return parts_.criticalAngles; }
  std::size_t intervalCount() const { return std::max<std::size_t>(1, parts_.criticalAngles.size()); }
  const std::vector<CellGraphNode>& nodes() const { return parts_.nodes; }
  const std::vector<CellGraphEdge>& edges() const { return parts_.edges; }
  /// The edges at a node: indices into edges(), increasing.
  struct EdgeIndices {
    const std::uint32_t* first;
    const std::uint32_t* last;
    const std::uint32_t* begin() const { return first; }
    const std::uint32_t* end() const { return last; }
  };
  EdgeIndices edgesAt(std::uint32_t node) const {
    return {edgesByNode_.data() + firstEdgeOfNode_[node], edgesByNode_.data() + firstEdgeOfNode_[node + 1]};
  }

  /// The nodes from `from` to `to` joined by edges (both included) of least cost:
  /// each edge costs 1, and leaving a node thinner than kThinArc (arcWidth) through the
  /// critical angle it was entered by costs kThinNodeCost over its arcWidth more (such
  /// a node joins its neighbours only through faces pinched to a sliver of angles;
  /// passing it from one end of its arc to the other is harmless); none when no path
  /// of edges joins them (then they lie in different cells). With `usable`, through
  /// the edges it accepts (given their two nodes) only.
  std::optional<std::vector<std::uint32_t>> route(
      std::uint32_t from, std::uint32_t to,
      const std::function<bool(std::uint32_t, std::uint32_t)>& usable = {}) const;
  static constexpr double kThinArc = 1e-4;
  static constexpr double kThinNodeCost = 0.01;

  /// The arc of angles from the start of interval `first` to the end of interval
  /// `last`, counterclockwise: its start in radians and its length (2 pi when it
  /// holds every angle).
  std::pair<double, double> arc(std::uint32_t first, std::uint32_t last) const;
  /// The length in radians of a node's arc of angles (2 pi for every angle).
  double arcWidth(std::uint32_t node) const;
  /// Whether an interval lies in a node's run of intervals (theta wrapping around).
  bool runHolds(const CellGraphNode& node, std::uint32_t interval) const;

  /// The interval whose open arc holds an angle; a critical angle gets the interval
  /// it starts.
  std::uint32_t intervalOf(const AlgebraicAngle& angle, AngleAlgebra& algebra) const;

  /// The node of a free configuration at a rational angle, from the first piece a ray
  /// from it meets (a SubFace hit from the free side) or from meeting nothing (the
  /// unbounded face); none for other hits.
  std::optional<std::uint32_t> nodeOf(const RayHit& hit, const AlgebraicAngle& rationalAngle,
                                      AngleAlgebra& algebra) const;

  /// The node of the face a piece bounds over an interval (the piece's slab holding
  /// it), and of the unbounded face; none for a piece of no free cell.
  std::optional<std::uint32_t> nodeOfPiece(std::size_t piece, std::uint32_t interval) const {
    return nodeAtRun(parts_.runsOfPiece[piece], interval);
  }
  std::optional<std::uint32_t> unboundedNode(std::uint32_t interval) const {
    return nodeAtRun(parts_.unboundedRuns, interval);
  }

  /// The number of a piece of a slice: the gap `gap` of the slab `slab` of `patch`,
  /// numbered patch by patch, slab by slab (as Parts::runsOfPiece).
  std::size_t pieceIndex(std::uint32_t patch, std::uint32_t slab, std::uint32_t gap) const {
    return firstGapOfSlab_[firstSlabOfPatch_[patch] + slab] + gap;
  }

 private:
  friend class CellGraphSweep;

  void numberPieces(const Arrangement& arrangement);
  void checkParts(std::size_t cellCount, AngleAlgebra& algebra) const;
  void indexEdges();
  std::optional<std::uint32_t> nodeAtRun(const std::vector<NodeRun>& runs, std::uint32_t interval) const;

  Parts parts_;
  std::vector<std::uint32_t> firstSlabOfPatch_;
  std::vector<std::uint32_t> firstGapOfSlab_;
  std::size_t pieceCount_ = 0;
  // edgesAt: the edges of node n are edgesByNode_[firstEdgeOfNode_[n] .. firstEdgeOfNode_[n + 1]).
  std::vector<std::uint32_t> firstEdgeOfNode_;
  std::vector<std::uint32_t> edgesByNode_;
};

}  // namespace freespace
