#include "slice_loops.h"

#include <unordered_map>

namespace freespace::cellgraph {

namespace {

std::uint64_t codeOf(SubFaceId face) { return (std::uint64_t(face.patch) << 32) | face.face; }

/// A segment end (a spiral) as one number: vertex, edge and which body the vertex is of.
struct SpiralHash {
  std::size_t operator()(const SegmentEnd& end) const {
    std::size_t hash = std::hash<std::uint64_t>()((std::uint64_t(end.vertex) << 1) | end.robotVertex);
    hash ^= std::hash<std::uint64_t>()((std::uint64_t(end.edge[0]) << 32) | end.edge[1]) + 0x9e3779b97f4a7c15ULL +
            (hash << 6) + (hash >> 2);
    return hash;
  }
};

}  // namespace

PieceNeighbours::PieceNeighbours(const Arrangement& arrangement, const CellGraph& numbering)
    : arrangement_(arrangement), numbering_(numbering) {
  for (const SubFaceGlue& glue : arrangement.aroundSpirals.glues) {
    spiralGlues_.insert({codeOf(glue.first), codeOf(glue.second)});
  }
  // Spirals are numbered once, by the segment ends that share them.
  std::unordered_map<SegmentEnd, std::uint32_t, SpiralHash> numbers;
  for (const PatchGeometry& patch : arrangement.patches) {
    std::array<std::uint32_t, 2> ends{};
    for (int end : {0, 1}) {
      ends[end] = numbers.emplace(patch.segment.ends[end], static_cast<std::uint32_t>(numbers.size())).first->second;
    }
    spiralOfEnd_.push_back(ends);
  }
  patchesAtSpiral_.resize(numbers.size());
  for (std::uint32_t patch = 0; patch < spiralOfEnd_.size(); ++patch) {
    for (int end : {0, 1}) patchesAtSpiral_[spiralOfEnd_[patch][end]].push_back({patch, end});
  }
}

SpiralEnds PieceNeighbours::spiralEnds(const IntervalLoops& loops) const {
  SpiralEnds ends;
  for (std::size_t id = 0; id < loops.pieces.size(); ++id) {
    const Piece& piece = loops.pieces[id];
    // A piece ending at a spiral is its slab's first gap (low end) or last (high end).
    if (piece.gap == 0) ends.push_back({spiralOf(piece.patch, 0), id});
    if (piece.gap + 1 == slabOf(piece).faces.size()) ends.push_back({spiralOf(piece.patch, 1), id});
  }
  std::sort(ends.begin(), ends.end());
  return ends;
}

std::optional<PieceNeighbours::Crossing> PieceNeighbours::across(const IntervalLoops& loops, const SpiralEnds& ends,
                                                                 std::size_t id, std::size_t end) const {
  if (const std::optional<Crossing> next = acrossCurve(loops, id, end)) return next;
  const std::uint32_t spiral = spiralOf(loops.piece(id).patch, static_cast<int>(end));
  SpiralEndPieces ending;
  const auto first = std::lower_bound(ends.begin(), ends.end(), std::pair(spiral, std::size_t{0}));
  for (auto at = first; at != ends.end() && at->first == spiral; ++at) ending.push_back(at->second);
  return aroundSpiral(loops, id, spiral, ending);
}

bool PieceNeighbours::gluedAroundSpiral(const Piece& a, const Piece& b) const {
  const std::uint64_t first = codeOf(faceOf(a)), second = codeOf(faceOf(b));
  return spiralGlues_.count({first, second}) != 0 || spiralGlues_.count({second, first}) != 0;
}

}  // namespace freespace::cellgraph
