#include "freespace/topology/slice_faces.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "freespace/topology/slice_pieces.h"
#include "gluing_parts.h"
#include "slice_loops.h"

namespace freespace {

namespace {

using cellgraph::IntervalLoops;
using cellgraph::Piece;

/// The free pieces at the angle: for every patch whose range holds it, the gaps of
/// the slab holding it whose sub-faces bound a free cell.
IntervalLoops piecesAt(const Arrangement& arrangement, const CellGraph& graph, const CellGraph::CellOfFace& cellOf,
                       const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  IntervalLoops loops;
  loops.sample = angle;
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    if (!algebra.contains(arrangement.patches[patch].patch.range, angle)) continue;
    const PatchSubdivision& subdivision = arrangement.subdivisions[patch];
    const PatchSlab* slab = slabAt(subdivision, angle, algebra);
    if (!slab) throw std::invalid_argument("SliceFaces: the angle is critical");
    const auto slabIndex = static_cast<std::uint32_t>(slab - subdivision.slabs.data());
    bool free = false;
    for (std::uint32_t gap = 0; gap < slab->faces.size(); ++gap) {
      if (!cellOf({patch, slab->faces[gap]})) continue;
      loops.pieces.push_back({patch, slabIndex, gap});
      loops.pieceIndices.push_back(graph.pieceIndex(patch, slabIndex, gap));
      free = true;
    }
    if (free) loops.slabs.push_back({patch, slabIndex});
  }
  return loops;
}

/// A piece's end rounded to doubles, and how far it may lie from the exact end.
struct RoundedEnd {
  std::array<double, 2> point;
  double error;
};

/// End `end` of a piece at the angle (0: low lambda, 1: high): the middle of its
/// enclosure, within the enclosure's half width (and the middle's rounding) of the
/// exact end; infinitely far when a crossing is uncertain (the segment's end then
/// stands for it).
RoundedEnd endOf(const Arrangement& arrangement, const slices::IntervalSlice& slice, const Piece& piece, int end) {
  const RoundingScope rounding;
  const PatchGeometry& geometry = arrangement.patches[piece.patch];
  const auto lambdas =
      slice.pieceOf(arrangement, piece.patch, arrangement.subdivisions[piece.patch].slabs[piece.slab], piece.gap);
  const Interval lambda = lambdas ? (end == 0 ? lambdas->first : lambdas->second) : Interval(end);
  const std::array<Interval, 2> enclosure = slice.pointOn(geometry, lambda);
  RoundedEnd rounded{{enclosure[0].midpoint(), enclosure[1].midpoint()}, lambdas ? 0.0 : HUGE_VAL};
  // Rounded upward: each axis's distance to the farther end of its enclosure, summed.
  for (int axis : {0, 1}) {
    rounded.error +=
        std::max(rounded.point[axis] - enclosure[axis].lower(), enclosure[axis].upper() - rounded.point[axis]);
  }
  return rounded;
}

/// One loop from a piece, walked from end to end: each piece is entered at the end
/// its predecessor's crossing reached, and left by its other end.
std::vector<std::size_t> walkLoop(const cellgraph::PieceNeighbours& neighbours, const IntervalLoops& loops,
                                  const cellgraph::SpiralEnds& spiralEnds, std::size_t first, std::vector<char>& seen,
                                  std::vector<int>& entry) {
  std::vector<std::size_t> loop;
  std::size_t at = first;
  int enteredBy = 0;
  while (!seen[at]) {
    seen[at] = 1;
    entry[at] = enteredBy;
    loop.push_back(at);
    const std::optional<cellgraph::PieceNeighbours::Crossing> next =
        neighbours.across(loops, spiralEnds, at, 1 - enteredBy);
    if (!next) throw std::logic_error("SliceFaces: a loop does not close");
    enteredBy = next->end;
    at = next->piece;
  }
  return loop;
}

/// A free slab's intervals between critical angles: runs of them that do not wrap
/// around (first, last), and the critical angle where it ends (none for a whole circle).
struct SlabIntervals {
  std::vector<std::array<std::uint32_t, 2>> runs;
  std::optional<std::uint32_t> end;
};

/// A slab and the critical angle where it ends.
struct PlacedSlab {
  const PatchSlab* slab;
  std::uint32_t end;
};

/// The intervals of a free slab. `before`: the slab placed last, whose end is this
/// slab's start when the two angles are the same (one comparison, not a search).
SlabIntervals intervalsOfSlab(const CellGraph& graph, const PatchSlab& slab, const std::optional<PlacedSlab>& before,
                              AngleAlgebra& algebra) {
  const auto last = static_cast<std::uint32_t>(graph.intervalCount() - 1);
  // A slab without events, or from an event once around back to it, holds every interval.
  if (graph.criticalAngles().empty() || algebra.compare(slab.from, slab.to) == 0) return {{{0, last}}, std::nullopt};
  // Otherwise its ends are critical angles (those of the slabs of free cells' patches).
  const std::uint32_t from =
      before && algebra.compare(before->slab->to, slab.from) == 0 ? before->end : graph.intervalOf(slab.from, algebra);
  const std::uint32_t to = graph.intervalOf(slab.to, algebra);
  if (from < to) return {{{from, to - 1}}, to};
  if (to == 0) return {{{from, last}}, to};
  return {{{0, to - 1}, {from, last}}, to};
}

}  // namespace

SliceFaces::SliceFaces(const Arrangement& arrangement, const CellGraph& graph, CellGraph::CellOfFace cellOf,
                       AngleAlgebra& algebra)
    : arrangement_(arrangement),
      graph_(graph),
      cellOf_(std::move(cellOf)),
      neighbours_(std::make_unique<cellgraph::PieceNeighbours>(arrangement, graph)),
      piecesOfNode_(graph.nodes().size()) {
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    const std::vector<PatchSlab>& slabs = arrangement.subdivisions[patch].slabs;
    std::optional<PlacedSlab> lastPlaced;
    for (std::uint32_t slab = 0; slab < slabs.size(); ++slab) {
      std::optional<SlabIntervals> intervals;  // found for a slab with free pieces
      for (std::uint32_t gap = 0; gap < slabs[slab].faces.size(); ++gap) {
        if (graph.parts().runsOfPiece[graph.pieceIndex(patch, slab, gap)].empty()) continue;
        if (!intervals) intervals = intervalsOfSlab(graph, slabs[slab], lastPlaced, algebra);
        tablePiece({patch, slab, gap}, intervals->runs);
      }
      lastPlaced.reset();
      if (intervals && intervals->end) lastPlaced = PlacedSlab{&slabs[slab], *intervals->end};
    }
  }
}

void SliceFaces::tablePiece(const PieceId& piece, const std::vector<std::array<std::uint32_t, 2>>& slabIntervals) {
  const std::size_t index = graph_.pieceIndex(piece[0], piece[1], piece[2]);
  const std::vector<CellGraph::NodeRun>& runs = graph_.parts().runsOfPiece[index];
  // Over each run of the slab's intervals, the piece's node from the run's start on,
  // changing where the piece's runs say.
  for (const auto& [first, last] : slabIntervals) {
    std::optional<std::uint32_t> node = graph_.nodeOfPiece(index, first);
    std::uint32_t from = first;
    for (const CellGraph::NodeRun& run : runs) {
      if (run.interval <= first || run.interval > last) continue;
      if (node) piecesOfNode_[*node].push_back({piece, from, run.interval - 1});
      node = run.node;
      from = run.interval;
    }
    if (node) piecesOfNode_[*node].push_back({piece, from, last});
  }
}

SliceFaces::~SliceFaces() = default;

std::map<std::uint32_t, SliceFace> SliceFaces::facesOf(const IntervalLoops& loops, std::uint32_t interval) const {
  const slices::IntervalSlice slice = *slices::IntervalSlice::at(loops.sample);
  std::map<std::uint32_t, SliceFace> faces;
  if (const std::optional<std::uint32_t> node = graph_.unboundedNode(interval)) {
    faces[*node] = SliceFace{*node, 0, true, {}};
  }
  const cellgraph::SpiralEnds spiralEnds = neighbours_->spiralEnds(loops);
  std::vector<char> seen(loops.pieces.size(), 0);
  std::vector<int> entry(loops.pieces.size(), 0);
  for (std::size_t first = 0; first < loops.pieces.size(); ++first) {
    if (seen[first]) continue;
    const std::vector<std::size_t> members = walkLoop(*neighbours_, loops, spiralEnds, first, seen, entry);
    const std::optional<std::uint32_t> node = graph_.nodeOfPiece(loops.pieceIndices[first], interval);
    if (!node) throw std::logic_error("SliceFaces: a free piece has no node");
    SliceLoop loop;
    double cornerError = 0;
    for (std::size_t member : members) {
      const RoundedEnd corner = endOf(arrangement_, slice, loops.pieces[member], entry[member]);
      loop.corners.push_back(corner.point);
      cornerError = std::max(cornerError, corner.error);
    }
    SliceFace& face = faces[*node];
    face.cornerError = std::max(face.cornerError, cornerError);
    face.node = *node;
    face.cell = graph_.nodes()[*node].cell;
    face.loops.push_back(std::move(loop));
  }
  return faces;
}

std::vector<SliceFace> SliceFaces::at(const AlgebraicAngle& rationalAngle, AngleAlgebra& algebra) const {
  const IntervalLoops loops = piecesAt(arrangement_, graph_, cellOf_, rationalAngle, algebra);
  std::vector<SliceFace> result;
  for (auto& [node, face] : facesOf(loops, graph_.intervalOf(rationalAngle, algebra)))
    result.push_back(std::move(face));
  return result;
}

std::optional<SliceFace> SliceFaces::faceOf(std::uint32_t node, const AlgebraicAngle& rationalAngle,
                                            AngleAlgebra& algebra) const {
  const std::uint32_t interval = graph_.intervalOf(rationalAngle, algebra);
  const std::vector<AlgebraicAngle>& critical = graph_.criticalAngles();
  if (!critical.empty() && algebra.compare(critical[interval], rationalAngle) == 0) {
    throw std::invalid_argument("SliceFaces: the angle is critical");
  }
  if (!graph_.runHolds(graph_.nodes()[node], interval)) return std::nullopt;
  // The node's pieces over the angle's interval.
  IntervalLoops loops;
  loops.sample = rationalAngle;
  for (const NodePiece& entry : piecesOfNode_[node]) {
    if (interval < entry.firstInterval || interval > entry.lastInterval) continue;
    const auto& [patch, slab, gap] = entry.piece;
    if (loops.slabs.empty() || loops.slabs.back().first != patch) loops.slabs.push_back({patch, slab});
    loops.pieces.push_back({patch, slab, gap});
    loops.pieceIndices.push_back(graph_.pieceIndex(patch, slab, gap));
  }
  std::map<std::uint32_t, SliceFace> faces = facesOf(loops, interval);
  const auto found = faces.find(node);
  if (found == faces.end()) throw std::logic_error("SliceFaces: a node's run holds an angle where it has no face");
  return std::move(found->second);
}

}  // namespace freespace
