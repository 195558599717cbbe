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

}  // namespace

SliceFaces::SliceFaces(const Arrangement& arrangement, const CellGraph& graph, CellGraph::CellOfFace cellOf)
    : arrangement_(arrangement),
      graph_(graph),
      cellOf_(std::move(cellOf)),
      neighbours_(std::make_unique<cellgraph::PieceNeighbours>(arrangement, graph)),
      piecesOfNode_(graph.nodes().size()) {
  const std::vector<std::vector<CellGraph::NodeRun>>& runs = graph.parts().runsOfPiece;
  for (std::uint32_t patch = 0; patch < arrangement.patches.size(); ++patch) {
    const std::vector<PatchSlab>& slabs = arrangement.subdivisions[patch].slabs;
    for (std::uint32_t slab = 0; slab < slabs.size(); ++slab) {
      for (std::uint32_t gap = 0; gap < slabs[slab].faces.size(); ++gap) {
        for (const CellGraph::NodeRun& run : runs[graph.pieceIndex(patch, slab, gap)]) {
          std::vector<PieceId>& pieces = piecesOfNode_[run.node];
          if (pieces.empty() || pieces.back() != PieceId{patch, slab, gap}) pieces.push_back({patch, slab, gap});
        }
      }
    }
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
  // The node's pieces whose slab holds the angle and which bound its face over this
  // interval: of each of the node's patches whose range holds the angle, the slab
  // holding it (slabAt: a bisection among the patch's slabs, not a test of each of the
  // node's slabs, which may be thousands along its run).
  IntervalLoops loops;
  loops.sample = rationalAngle;
  const std::vector<PieceId>& pieces = piecesOfNode_[node];  // by patch, slab, gap
  for (auto first = pieces.begin(); first != pieces.end();) {
    const std::uint32_t patch = (*first)[0];
    const auto last = std::find_if(first, pieces.end(), [&](const PieceId& piece) { return piece[0] != patch; });
    const PatchSubdivision& subdivision = arrangement_.subdivisions[patch];
    const PatchSlab* slab = algebra.contains(arrangement_.patches[patch].patch.range, rationalAngle)
                                ? slabAt(subdivision, rationalAngle, algebra)
                                : nullptr;
    if (slab) {
      const auto slabIndex = static_cast<std::uint32_t>(slab - subdivision.slabs.data());
      auto piece = std::lower_bound(first, last, PieceId{patch, slabIndex, 0});
      if (piece != last && (*piece)[1] == slabIndex) loops.slabs.push_back({patch, slabIndex});
      for (; piece != last && (*piece)[1] == slabIndex; ++piece) {
        const std::size_t index = graph_.pieceIndex(patch, slabIndex, (*piece)[2]);
        if (graph_.nodeOfPiece(index, interval) != node) continue;
        loops.pieces.push_back({patch, slabIndex, (*piece)[2]});
        loops.pieceIndices.push_back(index);
      }
    }
    first = last;
  }
  std::map<std::uint32_t, SliceFace> faces = facesOf(loops, interval);
  const auto found = faces.find(node);
  if (found == faces.end()) throw std::logic_error("SliceFaces: a node's run holds an angle where it has no face");
  return std::move(found->second);
}

}  // namespace freespace
