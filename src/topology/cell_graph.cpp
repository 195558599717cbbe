#include "freespace/topology/cell_graph.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "../geometry/disjoint_sets.h"
#include "slice_nesting.h"

namespace freespace {

namespace {

using slices::Point;

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

/// A free piece of the slices' boundary over an interval: a gap of a slab.
struct Piece {
  std::uint32_t patch;
  std::uint32_t slab;
  std::uint32_t gap;
};

/// The boundary of the free slices over one interval: its pieces, the loops they
/// form, and (once known) the node of each loop's face.
struct IntervalLoops {
  std::uint32_t interval = 0;
  AlgebraicAngle sample = AlgebraicAngle::rational(0, 0.0);
  std::vector<Piece> pieces;
  std::vector<std::uint32_t> loopOf;
  std::uint32_t loopCount = 0;
  /// (patch, slab) for each patch with free pieces here, by patch.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> slabs;
  /// CellGraph::pieceIndex of each piece, increasing.
  std::vector<std::size_t> pieceIndices;

  std::optional<std::uint32_t> slabOf(std::uint32_t patch) const {
    const auto found = std::lower_bound(slabs.begin(), slabs.end(), std::pair(patch, std::uint32_t{0}));
    if (found == slabs.end() || found->first != patch) return std::nullopt;
    return found->second;
  }
  /// The piece with a CellGraph::pieceIndex, if it is one here.
  std::optional<std::uint32_t> pieceAt(std::size_t index) const {
    const auto found = std::lower_bound(pieceIndices.begin(), pieceIndices.end(), index);
    if (found == pieceIndices.end() || *found != index) return std::nullopt;
    return static_cast<std::uint32_t>(found - pieceIndices.begin());
  }
  std::vector<std::uint32_t> nodeOfLoop;
  std::uint32_t unboundedNode = 0;
};

/// Pairs (loop before, loop after) that share boundary across a critical angle.
using LoopLinks = std::set<std::pair<std::uint32_t, std::uint32_t>>;

}  // namespace

/// Builds a CellGraph interval after interval (see CellGraph).
class CellGraphSweep {
 public:
  CellGraphSweep(CellGraph& graph, const Arrangement& arrangement, const SliceRays& rays,
                 const CellGraph::CellOfFace& cellOf, AngleAlgebra& algebra)
      : graph_(graph), arrangement_(arrangement), rays_(rays), cellOf_(cellOf), algebra_(algebra) {
    numberPieces();
    findCriticalAngles();
    indexHorizontalGlues();
    for (const SubFaceGlue& glue : arrangement.aroundSpirals.glues) {
      spiralGlues_.insert({codeOf(glue.first), codeOf(glue.second)});
    }
    numberSpirals();
  }

  void run(const Cancellation& cancellation) {
    const std::uint32_t count = static_cast<std::uint32_t>(graph_.intervalCount());
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> starting(count), ending(count);
    std::map<std::uint32_t, std::uint32_t> active = slabsCovering(starting, ending);
    IntervalLoops first, previous;
    for (std::uint32_t interval = 0; interval < count; ++interval) {
      cancellation.check();
      SlabChanges changes;
      for (const auto& [patch, slab] : ending[interval]) {
        const auto found = active.find(patch);
        if (found == active.end() || found->second != slab) continue;
        active.erase(found);
        changes.removed.push_back({patch, slab});
      }
      for (const auto& [patch, slab] : starting[interval]) {
        active[patch] = slab;
        changes.added.push_back({patch, slab});
      }
      if (interval == 0) {
        previous = loopsOver(interval, active);
        assignFaces(nullptr, previous);
        recordRuns(previous);
        first = previous;
        continue;
      }
      std::sort(changes.removed.begin(), changes.removed.end());
      std::sort(changes.added.begin(), changes.added.end());
      Step step = nextLoops(previous, changes, interval);
      if (!step.full && inheritFaces(previous, step)) {
        recordRuns(step.loops, step.added);
      } else {
        if (step.full) step.loops = loopsOver(interval, active);
        for (std::uint32_t node : nodesOf(previous)) graph_.parts_.nodes[node].lastInterval = interval - 1;
        assignFaces(&previous, step.loops);
        recordRuns(step.loops);
      }
      previous = std::move(step.loops);
    }
    for (std::uint32_t node : nodesOf(previous)) graph_.parts_.nodes[node].lastInterval = count - 1;
    if (!graph_.parts_.criticalAngles.empty()) {
      LoopLinks links = continuingLoops(previous, first);
      addGluedLoops(previous, first, links);
      addEdges(previous, first, links);
    }
  }

 private:
  // --- Pieces and critical angles -------------------------------------------------

  void numberPieces() {
    graph_.numberPieces(arrangement_);
    graph_.parts_.runsOfPiece.resize(graph_.pieceCount_);
    cellOfPiece_.assign(graph_.pieceCount_, kNotFree);
    for (std::uint32_t patch = 0; patch < arrangement_.subdivisions.size(); ++patch) {
      const auto& slabsOfPatch = arrangement_.subdivisions[patch].slabs;
      for (std::uint32_t slab = 0; slab < slabsOfPatch.size(); ++slab) {
        for (std::uint32_t gap = 0; gap < slabsOfPatch[slab].faces.size(); ++gap) {
          if (const auto cell = cellOf_({patch, slabsOfPatch[slab].faces[gap]})) {
            cellOfPiece_[graph_.pieceIndex(patch, slab, gap)] = *cell;
          }
        }
      }
    }
  }

  /// Numbers the spirals (segment ends shared by patches) once.
  void numberSpirals() {
    std::unordered_map<SegmentEnd, std::uint32_t, SpiralHash> numbers;
    for (const PatchGeometry& patch : arrangement_.patches) {
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

  bool hasFreePiece(std::uint32_t patch, std::uint32_t slab) const {
    const std::size_t first = graph_.pieceIndex(patch, slab, 0);
    const std::size_t gaps = arrangement_.subdivisions[patch].slabs[slab].faces.size();
    return std::any_of(cellOfPiece_.begin() + first, cellOfPiece_.begin() + first + gaps,
                       [](std::uint32_t cell) { return cell != kNotFree; });
  }

  /// A slab over the whole circle: from an event back to it, or without events.
  bool wholeCircle(const PatchSlab& slab) { return algebra_.compare(slab.from, slab.to) == 0; }

  void findCriticalAngles() {
    std::vector<AlgebraicAngle>& angles = graph_.parts_.criticalAngles;
    forEachFreeSlab([&](std::uint32_t, std::uint32_t, const PatchSlab& slab) {
      if (algebra_.compare(slab.from, slab.sample) == 0) return;  // a whole circle without events
      angles.push_back(slab.from);
      angles.push_back(slab.to);
    });
    std::sort(angles.begin(), angles.end(),
              [&](const AlgebraicAngle& a, const AlgebraicAngle& b) { return algebra_.compare(a, b) < 0; });
    angles.erase(std::unique(angles.begin(), angles.end(),
                             [&](const AlgebraicAngle& a, const AlgebraicAngle& b) {
                               return algebra_.compare(a, b) == 0;
                             }),
                 angles.end());
    samples_.clear();
    const std::size_t count = angles.size();
    for (std::size_t i = 0; i < graph_.intervalCount(); ++i) {
      if (count == 0) {
        samples_.push_back(AlgebraicAngle::rational(0, 0.0));
      } else if (count == 1) {
        samples_.push_back(AlgebraicAngle::rational(1 - angles[0].chart(), 0.0));
      } else {
        samples_.push_back(algebra_.rationalBetween(angles[i], angles[(i + 1) % count]));
      }
    }
  }

  template <class Visit>
  void forEachFreeSlab(const Visit& visit) {
    for (std::uint32_t patch = 0; patch < arrangement_.subdivisions.size(); ++patch) {
      const auto& slabs = arrangement_.subdivisions[patch].slabs;
      for (std::uint32_t slab = 0; slab < slabs.size(); ++slab) {
        if (hasFreePiece(patch, slab)) visit(patch, slab, slabs[slab]);
      }
    }
  }

  /// The index of a critical angle (which `angle` must be).
  std::uint32_t criticalIndex(const AlgebraicAngle& angle) {
    const std::vector<AlgebraicAngle>& angles = graph_.parts_.criticalAngles;
    const auto found = std::lower_bound(angles.begin(), angles.end(), angle, [&](const auto& a, const auto& b) {
      return algebra_.compare(a, b) < 0;
    });
    if (found == angles.end() || algebra_.compare(*found, angle) != 0) {
      throw std::logic_error("CellGraph: a slab's end is not a critical angle");
    }
    return static_cast<std::uint32_t>(found - angles.begin());
  }

  /// The slabs with free pieces starting and ending at each interval (by the index of
  /// their first interval and of the first interval after them); returns those
  /// covering interval 0 (whole circles and slabs across the last critical angle).
  std::map<std::uint32_t, std::uint32_t> slabsCovering(
      std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>>& starting,
      std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>>& ending) {
    std::map<std::uint32_t, std::uint32_t> covering;
    forEachFreeSlab([&](std::uint32_t patch, std::uint32_t slab, const PatchSlab& geometry) {
      if (wholeCircle(geometry)) {
        covering[patch] = slab;
        return;
      }
      const std::uint32_t from = criticalIndex(geometry.from), to = criticalIndex(geometry.to);
      starting[from].push_back({patch, slab});
      if (to != 0) ending[to].push_back({patch, slab});
      if (from > to && to != 0) covering[patch] = slab;
    });
    return covering;
  }

  void indexHorizontalGlues() {
    horizontalGluesAt_.resize(graph_.parts_.criticalAngles.size());
    for (const SubFaceGlue& glue : arrangement_.acrossHorizontalEdges.glues) {
      if (!cellOf_(glue.first) || !cellOf_(glue.second)) continue;
      horizontalGluesAt_[criticalIndex(glue.at)].push_back(glue);
    }
  }

  // --- Loops over one interval ------------------------------------------------------

  /// Every loop over an interval, from scratch.
  IntervalLoops loopsOver(std::uint32_t interval, const std::map<std::uint32_t, std::uint32_t>& active) {
    IntervalLoops loops;
    loops.interval = interval;
    loops.sample = samples_[interval];
    loops.slabs.assign(active.begin(), active.end());
    for (const auto& [patch, slab] : loops.slabs) appendFreePieces(loops, patch, slab);
    std::vector<std::uint32_t> all(loops.pieces.size());
    std::iota(all.begin(), all.end(), 0);
    const std::vector<char> everywhere(loops.pieces.size(), 1);
    detail::DisjointSets sets(loops.pieces.size());
    if (!joinAcrossCurves(loops, all, everywhere, sets) || !joinAroundSpirals(loops, all, everywhere, sets)) {
      throw std::logic_error("CellGraph: loops do not close");
    }
    std::unordered_map<std::uint32_t, std::uint32_t> numberOfRoot;
    for (std::uint32_t piece = 0; piece < loops.pieces.size(); ++piece) {
      const auto found = numberOfRoot.emplace(sets.find(piece), static_cast<std::uint32_t>(numberOfRoot.size()));
      loops.loopOf.push_back(found.first->second);
    }
    loops.loopCount = static_cast<std::uint32_t>(numberOfRoot.size());
    return loops;
  }

  void appendFreePieces(IntervalLoops& loops, std::uint32_t patch, std::uint32_t slab) const {
    const std::size_t gaps = arrangement_.subdivisions[patch].slabs[slab].faces.size();
    for (std::uint32_t gap = 0; gap < gaps; ++gap) {
      const std::size_t index = graph_.pieceIndex(patch, slab, gap);
      if (cellOfPiece_[index] == kNotFree) continue;
      loops.pieceIndices.push_back(index);
      loops.pieces.push_back({patch, slab, gap});
    }
  }

  /// The slabs with free pieces that end and start at a critical angle, by patch.
  struct SlabChanges {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> removed, added;
  };

  /// The loops over an interval from those over the previous one, when only the
  /// loops through pieces of the changed slabs (or their neighbours) can change:
  /// `loops` keeps every other loop with its number, `links` joins the changed loops
  /// (`before`) to the loops that replace them (`after`). `full` when the changed
  /// pieces do not close up into loops among themselves (then nothing else is set).
  struct Step {
    IntervalLoops loops;
    LoopLinks links;
    std::vector<std::uint32_t> before, after;
    /// The pieces of added slabs.
    std::vector<std::uint32_t> added;
    bool full = false;
  };

  Step nextLoops(const IntervalLoops& previous, const SlabChanges& changes, std::uint32_t interval) {
    Step step;
    IntervalLoops& loops = step.loops;
    loops.interval = interval;
    loops.sample = samples_[interval];
    const std::vector<std::int64_t> previousIndex = mergePieces(previous, changes, loops);
    if (replacesChains(previous, changes, previousIndex, loops)) {
      for (std::uint32_t piece = 0; piece < loops.pieces.size(); ++piece) {
        if (previousIndex[piece] < 0) step.added.push_back(piece);
      }
      return step;
    }
    // Loops that may change: through a removed piece, or next to an added one.
    std::vector<char> changed(previous.loopCount, 0);
    const auto touch = [&](std::uint32_t piece) {
      if (previousIndex[piece] >= 0) changed[previous.loopOf[previousIndex[piece]]] = 1;
    };
    for (const auto& [patch, slab] : changes.removed) {
      for (std::uint32_t piece : piecesOfSlab(previous, patch, slab)) changed[previous.loopOf[piece]] = 1;
    }
    std::vector<std::uint32_t> spirals;
    for (const auto* list : {&changes.removed, &changes.added}) {
      for (const auto& [patch, slab] : *list) spirals.insert(spirals.end(), spiralOfEnd_[patch].begin(), spiralOfEnd_[patch].end());
    }
    for (std::uint32_t spiral : spirals) {
      for (std::uint32_t piece : endPiecesAt(loops, spiral)) touch(piece);
    }
    for (const auto& [patch, slab] : changes.added) {
      for (std::uint32_t piece : piecesOfSlab(loops, patch, slab)) {
        for (const std::size_t end : {0, 1}) {
          if (const auto next = curveNeighbour(loops, piece, end)) touch(*next);
        }
      }
    }
    std::vector<std::uint32_t> subset;
    std::vector<char> inSubset(loops.pieces.size(), 0);
    for (std::uint32_t piece = 0; piece < loops.pieces.size(); ++piece) {
      if (previousIndex[piece] < 0) step.added.push_back(piece);
      if (previousIndex[piece] < 0 || changed[previous.loopOf[previousIndex[piece]]]) {
        subset.push_back(piece);
        inSubset[piece] = 1;
      }
    }
    detail::DisjointSets sets(loops.pieces.size());
    if (!joinAcrossCurves(loops, subset, inSubset, sets) || !joinAroundSpirals(loops, subset, inSubset, sets)) {
      step.full = true;
      return step;
    }
    numberChangedLoops(previous, previousIndex, changed, subset, sets, step);
    return step;
  }

  /// Where the changed pieces only replace chains between the same kept pieces (the
  /// usual case), no loop changes but for those pieces: every chain of removed
  /// pieces between two kept ones is matched by a chain of added pieces between the
  /// same two, and no chain closes on itself. Then the added pieces take the loops of
  /// the pieces they hang from, every other piece keeps its loop, and true.
  bool replacesChains(const IntervalLoops& previous, const SlabChanges& changes,
                      const std::vector<std::int64_t>& previousIndex, IntervalLoops& loops) const {
    std::vector<std::uint32_t> removedPieces, addedPieces;
    for (const auto& [patch, slab] : changes.removed) {
      const std::vector<std::uint32_t> pieces = piecesOfSlab(previous, patch, slab);
      removedPieces.insert(removedPieces.end(), pieces.begin(), pieces.end());
    }
    for (std::uint32_t piece = 0; piece < loops.pieces.size(); ++piece) {
      if (previousIndex[piece] < 0) addedPieces.push_back(piece);
    }
    std::sort(removedPieces.begin(), removedPieces.end());
    std::vector<std::pair<std::size_t, std::size_t>> before, after;
    std::vector<std::uint32_t> hangsFrom(addedPieces.size());
    if (!chainEnds(previous, removedPieces, before, nullptr) || !chainEnds(loops, addedPieces, after, &hangsFrom)) {
      return false;
    }
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    if (before != after) return false;
    loops.loopOf.resize(loops.pieces.size());
    for (std::uint32_t piece = 0; piece < loops.pieces.size(); ++piece) {
      if (previousIndex[piece] >= 0) loops.loopOf[piece] = previous.loopOf[previousIndex[piece]];
    }
    for (std::size_t i = 0; i < addedPieces.size(); ++i) {
      loops.loopOf[addedPieces[i]] = previous.loopOf[previous.pieceAt(loops.pieceIndices[hangsFrom[i]]).value()];
    }
    loops.loopCount = previous.loopCount;
    loops.nodeOfLoop = previous.nodeOfLoop;
    loops.unboundedNode = previous.unboundedNode;
    return true;
  }

  /// The chains the pieces (increasing) form, each as the pair of pieces (by
  /// pieceIndex) it hangs between; false when one closes on itself or a neighbour
  /// is unclear. With `hangsFrom`, for each of the pieces the index in `loops` of
  /// the first piece its chain hangs from.
  bool chainEnds(const IntervalLoops& loops, const std::vector<std::uint32_t>& pieces,
                 std::vector<std::pair<std::size_t, std::size_t>>& ends, std::vector<std::uint32_t>* hangsFrom) const {
    const auto position = [&](std::uint32_t piece) -> std::optional<std::size_t> {
      const auto found = std::lower_bound(pieces.begin(), pieces.end(), piece);
      if (found == pieces.end() || *found != piece) return std::nullopt;
      return static_cast<std::size_t>(found - pieces.begin());
    };
    std::vector<char> seen(pieces.size(), 0);
    for (std::size_t first = 0; first < pieces.size(); ++first) {
      if (seen[first]) continue;
      std::vector<std::size_t> chain{first};
      std::vector<std::uint32_t> outside;
      seen[first] = 1;
      for (std::size_t at = 0; at < chain.size(); ++at) {
        for (const std::size_t end : {0, 1}) {
          const std::optional<std::uint32_t> next = neighbour(loops, pieces[chain[at]], end);
          if (!next) return false;
          const std::optional<std::size_t> inChain = position(*next);
          if (!inChain) {
            outside.push_back(*next);
          } else if (!seen[*inChain]) {
            seen[*inChain] = 1;
            chain.push_back(*inChain);
          }
        }
      }
      if (outside.size() != 2) return false;
      const std::size_t a = loops.pieceIndices[outside[0]], b = loops.pieceIndices[outside[1]];
      ends.push_back({std::min(a, b), std::max(a, b)});
      if (hangsFrom) {
        for (std::size_t at : chain) (*hangsFrom)[at] = outside[0];
      }
    }
    return true;
  }

  /// The piece across a piece's low (0) or high (1) end: across a curve, or the one
  /// glued to it around the spiral there; none when that is unclear.
  std::optional<std::uint32_t> neighbour(const IntervalLoops& loops, std::uint32_t index, std::size_t end) const {
    if (const std::optional<std::uint32_t> next = curveNeighbour(loops, index, end)) return next;
    const Piece& piece = loops.pieces[index];
    const std::vector<std::uint32_t> ending = endPiecesAt(loops, spiralOfEnd_[piece.patch][end]);
    std::optional<std::uint32_t> found;
    for (std::uint32_t other : ending) {
      if (other == index) continue;
      if (ending.size() > 2 && !gluedAroundSpiral(faceOf(piece), faceOf(loops.pieces[other]))) continue;
      if (found) return std::nullopt;
      found = other;
    }
    return found;
  }

  /// The pieces over the interval: the previous ones but those of removed slabs, and
  /// those of added slabs, in order; returns the previous index of each (-1: added).
  std::vector<std::int64_t> mergePieces(const IntervalLoops& previous, const SlabChanges& changes,
                                        IntervalLoops& loops) const {
    std::set_difference(previous.slabs.begin(), previous.slabs.end(), changes.removed.begin(), changes.removed.end(),
                        std::back_inserter(loops.slabs));
    std::vector<std::pair<std::uint32_t, std::uint32_t>> kept;
    kept.swap(loops.slabs);
    std::merge(kept.begin(), kept.end(), changes.added.begin(), changes.added.end(), std::back_inserter(loops.slabs));
    IntervalLoops added;
    for (const auto& [patch, slab] : changes.added) appendFreePieces(added, patch, slab);
    std::vector<std::int64_t> previousIndex;
    std::size_t i = 0, j = 0;
    const auto removed = [&](const Piece& piece) {
      return std::binary_search(changes.removed.begin(), changes.removed.end(), std::pair(piece.patch, piece.slab));
    };
    while (i < previous.pieces.size() || j < added.pieces.size()) {
      if (i < previous.pieces.size() && removed(previous.pieces[i])) {
        ++i;
      } else if (j == added.pieces.size() ||
                 (i < previous.pieces.size() && previous.pieceIndices[i] < added.pieceIndices[j])) {
        loops.pieces.push_back(previous.pieces[i]);
        loops.pieceIndices.push_back(previous.pieceIndices[i]);
        previousIndex.push_back(static_cast<std::int64_t>(i++));
      } else {
        loops.pieces.push_back(added.pieces[j]);
        loops.pieceIndices.push_back(added.pieceIndices[j++]);
        previousIndex.push_back(-1);
      }
    }
    return previousIndex;
  }

  /// Numbers the loops the changed pieces form (reusing the numbers of the loops
  /// they replace), keeps every other loop's number, and links old to new.
  void numberChangedLoops(const IntervalLoops& previous, const std::vector<std::int64_t>& previousIndex,
                          const std::vector<char>& changed, const std::vector<std::uint32_t>& subset,
                          detail::DisjointSets& sets, Step& step) const {
    IntervalLoops& loops = step.loops;
    for (std::uint32_t loop = 0; loop < previous.loopCount; ++loop) {
      if (changed[loop]) step.before.push_back(loop);
    }
    std::size_t reused = 0;
    std::uint32_t next = previous.loopCount;
    std::unordered_map<std::uint32_t, std::uint32_t> numberOfRoot;
    loops.loopOf.resize(loops.pieces.size());
    for (std::uint32_t piece = 0; piece < loops.pieces.size(); ++piece) {
      if (previousIndex[piece] >= 0) loops.loopOf[piece] = previous.loopOf[previousIndex[piece]];
    }
    for (std::uint32_t piece : subset) {
      auto found = numberOfRoot.find(sets.find(piece));
      if (found == numberOfRoot.end()) {
        const std::uint32_t number = reused < step.before.size() ? step.before[reused++] : next++;
        found = numberOfRoot.emplace(sets.find(piece), number).first;
        step.after.push_back(number);
      }
      loops.loopOf[piece] = found->second;
      if (previousIndex[piece] >= 0) step.links.insert({previous.loopOf[previousIndex[piece]], found->second});
    }
    loops.loopCount = next;
    for (const auto& [patch, slab] : loops.slabs) {
      const std::optional<std::uint32_t> earlier = previous.slabOf(patch);
      if (!earlier || *earlier == slab) continue;
      for (const auto& [from, to] : piecesOfSubFaces(previous, loops, patch, slab)) {
        step.links.insert({previous.loopOf[from], loops.loopOf[to]});
      }
    }
  }

  /// When the changed loops continue one to one, every face goes on with its node.
  bool inheritFaces(const IntervalLoops& previous, Step& step) const {
    if (step.before.size() != step.after.size() || step.links.size() != step.before.size()) return false;
    std::set<std::uint32_t> from, to;
    for (const auto& [before, after] : step.links) from.insert(before), to.insert(after);
    if (from.size() != step.before.size() || to.size() != step.after.size()) return false;
    IntervalLoops& loops = step.loops;
    loops.nodeOfLoop = previous.nodeOfLoop;
    loops.nodeOfLoop.resize(loops.loopCount);
    for (const auto& [before, after] : step.links) loops.nodeOfLoop[after] = previous.nodeOfLoop[before];
    loops.unboundedNode = previous.unboundedNode;
    return true;
  }

  /// The nodes of the faces over an interval.
  std::set<std::uint32_t> nodesOf(const IntervalLoops& loops) const {
    std::set<std::uint32_t> nodes{loops.unboundedNode};
    for (std::uint32_t loop : loops.loopOf) nodes.insert(loops.nodeOfLoop[loop]);
    return nodes;
  }

  /// The free pieces of a slab over an interval.
  std::vector<std::uint32_t> piecesOfSlab(const IntervalLoops& loops, std::uint32_t patch, std::uint32_t slab) const {
    std::vector<std::uint32_t> found;
    const std::size_t gaps = arrangement_.subdivisions[patch].slabs[slab].faces.size();
    for (std::uint32_t gap = 0; gap < gaps; ++gap) {
      if (const auto piece = loops.pieceAt(graph_.pieceIndex(patch, slab, gap))) found.push_back(*piece);
    }
    return found;
  }

  /// The free pieces over an interval that end at a spiral.
  std::vector<std::uint32_t> endPiecesAt(const IntervalLoops& loops, std::uint32_t spiral) const {
    std::vector<std::uint32_t> found;
    for (const auto& [patch, end] : patchesAtSpiral_[spiral]) {
      const std::optional<std::uint32_t> slab = loops.slabOf(patch);
      if (!slab) continue;
      const std::size_t gaps = arrangement_.subdivisions[patch].slabs[*slab].faces.size();
      const std::uint32_t gap = end == 0 ? 0 : static_cast<std::uint32_t>(gaps - 1);
      if (const auto piece = loops.pieceAt(graph_.pieceIndex(patch, *slab, gap))) found.push_back(*piece);
    }
    return found;
  }

  const PatchSlab& slabOf(const Piece& piece) const {
    return arrangement_.subdivisions[piece.patch].slabs[piece.slab];
  }

  /// The piece a piece continues into across the curve at its low (0) or high (1)
  /// end: on the curve's other patch, the one side of the curve there that bounds
  /// free space (the other side lies inside this patch's obstacle). None at a spiral.
  std::optional<std::uint32_t> curveNeighbour(const IntervalLoops& loops, std::uint32_t index, std::size_t end) const {
    const Piece& piece = loops.pieces[index];
    const PatchSlab& slab = slabOf(piece);
    const std::size_t at = piece.gap + end;
    if (at == 0 || at > slab.curves.size()) return std::nullopt;
    const std::uint32_t curve = slab.curves[at - 1];
    const std::uint32_t other = arrangement_.curves[curve].other(piece.patch);
    const std::optional<std::uint32_t> otherSlab = loops.slabOf(other);
    if (!otherSlab) throw std::logic_error("CellGraph: a free piece's curve ends nowhere");
    const auto& curves = arrangement_.subdivisions[other].slabs[*otherSlab].curves;
    const std::size_t crossing = std::find(curves.begin(), curves.end(), curve) - curves.begin();
    std::optional<std::uint32_t> next;
    for (const std::size_t gap : {crossing, crossing + 1}) {
      const std::optional<std::uint32_t> found = loops.pieceAt(graph_.pieceIndex(other, *otherSlab, gap));
      if (!found) continue;
      if (next) throw std::logic_error("CellGraph: both sides of a curve bound free space");
      next = found;
    }
    if (!next) throw std::logic_error("CellGraph: a free piece continues into no free piece across a curve");
    return next;
  }

  /// Joins the pieces of `subset` to their neighbours across curves; false when one
  /// lies outside it.
  bool joinAcrossCurves(const IntervalLoops& loops, const std::vector<std::uint32_t>& subset,
                        const std::vector<char>& inSubset, detail::DisjointSets& sets) const {
    for (std::uint32_t index : subset) {
      for (const std::size_t end : {0, 1}) {
        const std::optional<std::uint32_t> next = curveNeighbour(loops, index, end);
        if (!next) continue;
        if (!inSubset[*next]) return false;
        sets.unite(index, *next);
      }
    }
    return true;
  }

  /// Pieces ending at one spiral point are joined in pairs, by the gluing around
  /// spirals when more than two end there; false when one of them lies outside
  /// `subset`.
  bool joinAroundSpirals(const IntervalLoops& loops, const std::vector<std::uint32_t>& subset,
                         const std::vector<char>& inSubset, detail::DisjointSets& sets) const {
    std::vector<std::uint32_t> spirals;
    for (std::uint32_t index : subset) {
      const Piece& piece = loops.pieces[index];
      if (piece.gap == 0) spirals.push_back(spiralOfEnd_[piece.patch][0]);
      if (piece.gap + 1 == slabOf(piece).faces.size()) spirals.push_back(spiralOfEnd_[piece.patch][1]);
    }
    std::sort(spirals.begin(), spirals.end());
    spirals.erase(std::unique(spirals.begin(), spirals.end()), spirals.end());
    for (std::uint32_t spiral : spirals) {
      const std::vector<std::uint32_t> ending = endPiecesAt(loops, spiral);
      if (std::any_of(ending.begin(), ending.end(), [&](std::uint32_t piece) { return !inSubset[piece]; })) return false;
      if (ending.size() == 1) throw std::logic_error("CellGraph: a free piece ends alone at a spiral");
      if (ending.size() == 2) {
        sets.unite(ending[0], ending[1]);
        continue;
      }
      for (std::size_t i = 0; i < ending.size(); ++i) {
        for (std::size_t j = i + 1; j < ending.size(); ++j) {
          if (gluedAroundSpiral(faceOf(loops.pieces[ending[i]]), faceOf(loops.pieces[ending[j]]))) {
            sets.unite(ending[i], ending[j]);
          }
        }
      }
    }
    return true;
  }

  SubFaceId faceOf(const Piece& piece) const { return {piece.patch, slabOf(piece).faces[piece.gap]}; }

  bool gluedAroundSpiral(SubFaceId a, SubFaceId b) const {
    return spiralGlues_.count({codeOf(a), codeOf(b)}) != 0 || spiralGlues_.count({codeOf(b), codeOf(a)}) != 0;
  }

  // --- Faces --------------------------------------------------------------------------

  /// Loops of neighbouring intervals that share a piece (a slab across the critical
  /// angle between them) or pieces of one sub-face (a patch's slabs on both sides).
  LoopLinks continuingLoops(const IntervalLoops& before, const IntervalLoops& after) const {
    LoopLinks links;
    // Both lists are increasing: one walk finds the pieces they share.
    for (std::size_t i = 0, j = 0; i < before.pieceIndices.size() && j < after.pieceIndices.size();) {
      if (before.pieceIndices[i] < after.pieceIndices[j]) {
        ++i;
      } else if (after.pieceIndices[j] < before.pieceIndices[i]) {
        ++j;
      } else {
        links.insert({before.loopOf[i++], after.loopOf[j++]});
      }
    }
    for (std::size_t i = 0, j = 0; i < before.slabs.size() && j < after.slabs.size();) {
      const auto& [patchBefore, slabBefore] = before.slabs[i];
      const auto& [patchAfter, slabAfter] = after.slabs[j];
      if (patchBefore != patchAfter) {
        patchBefore < patchAfter ? ++i : ++j;
        continue;
      }
      if (slabBefore != slabAfter) {
        for (const auto& [from, to] : piecesOfSubFaces(before, after, patchAfter, slabAfter)) {
          links.insert({before.loopOf[from], after.loopOf[to]});
        }
      }
      ++i;
      ++j;
    }
    return links;
  }

  /// Adds the loops whose sub-faces are glued across a horizontal edge at the
  /// critical angle where `after` starts.
  void addGluedLoops(const IntervalLoops& before, const IntervalLoops& after, LoopLinks& links) const {
    if (after.interval >= horizontalGluesAt_.size()) return;
    for (const SubFaceGlue& glue : horizontalGluesAt_[after.interval]) {
      for (const auto& [below, above] : {std::pair(glue.first, glue.second), std::pair(glue.second, glue.first)}) {
        for (std::uint32_t from : piecesOf(before, below)) {
          for (std::uint32_t to : piecesOf(after, above)) links.insert({before.loopOf[from], after.loopOf[to]});
        }
      }
    }
  }

  /// Pairs (piece before, piece after) of one patch whose slab changes between the
  /// intervals: the pieces of each sub-face, in their order along the segment
  /// (every pair when the sub-face has more pieces on one side).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> piecesOfSubFaces(const IntervalLoops& before,
                                                                       const IntervalLoops& after, std::uint32_t patch,
                                                                       std::uint32_t slabAfter) const {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    const auto& faces = arrangement_.subdivisions[patch].slabs[slabAfter].faces;
    for (std::uint32_t gap = 0; gap < faces.size(); ++gap) {
      const std::optional<std::uint32_t> to = after.pieceAt(graph_.pieceIndex(patch, slabAfter, gap));
      if (!to) continue;
      const std::vector<std::uint32_t> earlier = piecesOf(before, {patch, faces[gap]});
      const std::vector<std::uint32_t> later = piecesOf(after, {patch, faces[gap]});
      if (earlier.size() == later.size()) {
        const std::size_t rank = std::find(later.begin(), later.end(), *to) - later.begin();
        pairs.push_back({earlier[rank], *to});
      } else {
        for (std::uint32_t from : earlier) pairs.push_back({from, *to});
      }
    }
    return pairs;
  }

  /// The pieces of a sub-face over an interval.
  std::vector<std::uint32_t> piecesOf(const IntervalLoops& loops, SubFaceId face) const {
    std::vector<std::uint32_t> found;
    const std::optional<std::uint32_t> slab = loops.slabOf(face.patch);
    if (!slab) return found;
    const auto& faces = arrangement_.subdivisions[face.patch].slabs[*slab].faces;
    for (std::uint32_t gap = 0; gap < faces.size(); ++gap) {
      if (faces[gap] != face.face) continue;
      if (const auto piece = loops.pieceAt(graph_.pieceIndex(face.patch, *slab, gap))) found.push_back(*piece);
    }
    return found;
  }

  void addEdges(const IntervalLoops& before, const IntervalLoops& after, const LoopLinks& links) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> joined{{before.unboundedNode, after.unboundedNode}};
    for (const auto& [from, to] : links) joined.insert({before.nodeOfLoop[from], after.nodeOfLoop[to]});
    for (const auto& [from, to] : joined) {
      if (from != to) graph_.parts_.edges.push_back({from, to, after.interval});
    }
  }

  /// The faces over an interval, as nodes (see CellGraph). Loops that continue one
  /// to one from the previous interval keep their face's nesting; the others are
  /// nested by rays, and so are the loops of every face one of them is an outer loop
  /// for (a face split or merged or born: its holes may have moved). A face whose
  /// loops are exactly the continuations of one previous face's loops continues its
  /// node; any other face is a new node, joined to every previous face it shares
  /// loops with (or sub-faces glued across a horizontal edge).
  void assignFaces(const IntervalLoops* previous, IntervalLoops& current) {
    LoopLinks links;
    if (previous) links = continuingLoops(*previous, current);
    const std::vector<std::optional<std::uint32_t>> continues =
        previous ? continuations(links, previous->loopCount, current.loopCount)
                 : std::vector<std::optional<std::uint32_t>>(current.loopCount);
    if (previous) addGluedLoops(*previous, current, links);
    const std::vector<std::vector<std::uint32_t>> members = loopMembers(current);
    FaceNesting nesting(current.loopCount);
    std::set<std::uint32_t> renested;
    for (std::uint32_t loop = 0; loop < current.loopCount; ++loop) {
      if (continues[loop] || members[loop].empty()) continue;
      if (nest(current, loop, members[loop], nesting)) {
        for (const auto& [before, after] : links) {
          if (after == loop) renested.insert(previous->nodeOfLoop[before]);
        }
      }
    }
    std::unordered_map<std::uint32_t, std::uint32_t> representative;
    if (previous) representative[previous->unboundedNode] = nesting.unbounded;
    for (std::uint32_t loop = 0; loop < current.loopCount; ++loop) {
      if (!continues[loop] || members[loop].empty()) continue;
      const std::uint32_t node = previous->nodeOfLoop[*continues[loop]];
      if (renested.count(node)) {
        nest(current, loop, members[loop], nesting);
        continue;
      }
      const auto found = representative.emplace(node, loop);
      if (!found.second) nesting.faces.unite(loop, found.first->second);
    }
    numberFaces(previous, current, links, continues, members, nesting);
    checkCells(current);
  }

  /// The loops of the faces over an interval, the unbounded face as one more.
  struct FaceNesting {
    explicit FaceNesting(std::uint32_t loops) : unbounded(loops), faces(loops + 1), outer(loops) {}
    std::uint32_t unbounded;
    detail::DisjointSets faces;
    std::vector<bool> outer;
  };

  /// Nests one loop by rays: joins a hole to the face around it; returns whether it
  /// is an outer loop.
  bool nest(const IntervalLoops& loops, std::uint32_t loop, const std::vector<std::uint32_t>& members,
            FaceNesting& nesting) const {
    const std::optional<std::uint32_t> joined = holeJoinedTo(loops, loop, members);
    if (joined) {
      nesting.faces.unite(loop, *joined);
      return false;
    }
    nesting.outer[loop] = true;
    return true;
  }

  /// For each loop after, the loop before it continues one to one, if any.
  static std::vector<std::optional<std::uint32_t>> continuations(const LoopLinks& links, std::uint32_t before,
                                                                 std::uint32_t after) {
    std::vector<std::uint32_t> forward(before), backward(after);
    for (const auto& [from, to] : links) {
      ++forward[from];
      ++backward[to];
    }
    std::vector<std::optional<std::uint32_t>> continues(after);
    for (const auto& [from, to] : links) {
      if (forward[from] == 1 && backward[to] == 1) continues[to] = from;
    }
    return continues;
  }

  /// Gives each face its node: the previous one when the face continues it, else a
  /// new node with edges from the previous faces it is linked to.
  void numberFaces(const IntervalLoops* previous, IntervalLoops& current, const LoopLinks& links,
                   const std::vector<std::optional<std::uint32_t>>& continues,
                   const std::vector<std::vector<std::uint32_t>>& members, FaceNesting& nesting) {
    struct Face {
      std::vector<std::uint32_t> loops;
      bool changed = false;
      std::set<std::uint32_t> previousNodes;
    };
    std::map<std::uint32_t, Face> faces;
    faces[nesting.faces.find(nesting.unbounded)];
    if (previous) faces[nesting.faces.find(nesting.unbounded)].previousNodes.insert(previous->unboundedNode);
    for (std::uint32_t loop = 0; loop < current.loopCount; ++loop) {
      if (members[loop].empty()) continue;  // a number no loop has over this interval
      Face& face = faces[nesting.faces.find(loop)];
      face.loops.push_back(loop);
      face.changed = face.changed || !continues[loop];
    }
    for (const auto& [before, after] : links) {
      faces[nesting.faces.find(after)].previousNodes.insert(previous->nodeOfLoop[before]);
    }
    std::unordered_map<std::uint32_t, std::uint32_t> loopsOfPreviousNode;
    if (previous) {
      std::vector<char> seen(previous->loopCount, 0);
      for (std::uint32_t loop : previous->loopOf) {
        if (!seen[loop]) ++loopsOfPreviousNode[previous->nodeOfLoop[loop]];
        seen[loop] = 1;
      }
    }
    current.nodeOfLoop.assign(current.loopCount, 0);
    const std::uint32_t unboundedRoot = nesting.faces.find(nesting.unbounded);
    for (const auto& [root, face] : faces) {
      const bool unbounded = root == unboundedRoot;
      std::uint32_t node;
      if (!face.changed && face.previousNodes.size() == 1 &&
          loopsOfPreviousNode[*face.previousNodes.begin()] == face.loops.size()) {
        node = *face.previousNodes.begin();
        graph_.parts_.nodes[node].lastInterval = current.interval;
      } else {
        node = static_cast<std::uint32_t>(graph_.parts_.nodes.size());
        graph_.parts_.nodes.push_back(newNode(current, face.loops, members, nesting.outer, face.previousNodes, unbounded));
        for (std::uint32_t from : face.previousNodes) graph_.parts_.edges.push_back({from, node, current.interval});
      }
      for (std::uint32_t loop : face.loops) current.nodeOfLoop[loop] = node;
      if (unbounded) current.unboundedNode = node;
    }
  }

  std::vector<std::vector<std::uint32_t>> loopMembers(const IntervalLoops& loops) const {
    std::vector<std::vector<std::uint32_t>> members(loops.loopCount);
    for (std::uint32_t piece = 0; piece < loops.pieces.size(); ++piece) members[loops.loopOf[piece]].push_back(piece);
    return members;
  }

  /// For a hole, the loop (or the unbounded face, numbered loopCount) its face is
  /// bounded by next; nothing for an outer loop.
  std::optional<std::uint32_t> holeJoinedTo(const IntervalLoops& loops, std::uint32_t loop,
                                            const std::vector<std::uint32_t>& members) const {
    slices::LeftmostEnd leftmost(arrangement_, loops.sample);
    for (std::uint32_t piece : members) {
      const Piece& p = loops.pieces[piece];
      leftmost.offer(p.patch, slabOf(p), p.gap);
    }
    const slices::LeftOfLeftmost look =
        slices::lookLeftOf(rays_, loops.sample, leftmost.exact().value(), [&](const RayHit& hit) {
          if (hit.kind != RayHit::Kind::SubFace) return slices::Outside::Unknown;
          const std::optional<std::uint32_t> seen = freeLoopOf(loops, hit);
          if (!seen) return slices::Outside::Outer;
          return *seen == loop ? slices::Outside::Hole : slices::Outside::Unknown;
        });
    if (!look.hole) return std::nullopt;
    if (look.leftward.kind == RayHit::Kind::Nothing) return loops.loopCount;
    const std::optional<std::uint32_t> met = freeLoopOf(loops, look.leftward);
    if (!met) throw std::logic_error("CellGraph: a ray in free space meets a blocked side");
    return met;
  }

  /// The loop of the piece a ray hit, when the ray arrives from its free side.
  std::optional<std::uint32_t> freeLoopOf(const IntervalLoops& loops, const RayHit& hit) const {
    if (!hit.fromPositiveSide) return std::nullopt;
    const std::optional<std::uint32_t> found = loops.pieceAt(graph_.pieceIndex(hit.face.patch, hit.slab, hit.gap));
    if (!found) return std::nullopt;
    return loops.loopOf[*found];
  }

  /// A node for a face over the current interval: its cell, a point and a box.
  CellGraphNode newNode(const IntervalLoops& loops, const std::vector<std::uint32_t>& faceLoops,
                        const std::vector<std::vector<std::uint32_t>>& members, const std::vector<bool>& outerLoops,
                        const std::set<std::uint32_t>& previousNodes, bool unbounded) const {
    CellGraphNode node;
    node.firstInterval = node.lastInterval = loops.interval;
    node.sample = loops.sample;
    node.box = {-HUGE_VAL, -HUGE_VAL, HUGE_VAL, HUGE_VAL};
    if (unbounded) {
      node.cell = 0;
      node.point = farPoint();
      return node;
    }
    const Piece& piece = loops.pieces[members[faceLoops.front()].front()];
    node.cell = cellOfPiece_[graph_.pieceIndex(piece.patch, piece.slab, piece.gap)];
    node.point = pointOff(loops, members[faceLoops.front()]);
    const auto outer = std::find_if(faceLoops.begin(), faceLoops.end(), [&](std::uint32_t l) { return outerLoops[l]; });
    if (outer != faceLoops.end()) {
      node.box = boxOf(loops, members[*outer]);
    } else {
      // The outer loop continues from one of the previous faces: their boxes hold it.
      node.box = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
      for (std::uint32_t from : previousNodes) {
        const std::array<double, 4>& box = graph_.parts_.nodes[from].box;
        node.box = {std::min(node.box[0], box[0]), std::min(node.box[1], box[1]), std::max(node.box[2], box[2]),
                    std::max(node.box[3], box[3])};
      }
    }
    return node;
  }

  /// A point left of every patch: in the unbounded face of every slice.
  std::array<double, 2> farPoint() const {
    double lowest = 0, highest = 0;
    for (const auto& [box, patch] : arrangement_.boxIndex->boxes()) {
      lowest = std::min({lowest, box.low[0], box.low[1]});
      highest = std::max({highest, box.high[0], box.high[1]});
    }
    return {lowest - (highest - lowest) - 1, 0.0};
  }

  /// A point of the face a loop bounds: from the middle of one of its pieces, half
  /// way along x to whatever lies next on the piece's free side.
  std::array<double, 2> pointOff(const IntervalLoops& loops, const std::vector<std::uint32_t>& members) const {
    const auto [cosine, sine] = exactCosSin(loops.sample);
    for (std::uint32_t index : members) {
      const Piece& piece = loops.pieces[index];
      const slices::ExactSegment segment = slices::segmentAt(arrangement_.patches[piece.patch], cosine, sine);
      if (segment.nx == 0) continue;
      const auto lambdas =
          slices::pieceOf(arrangement_, piece.patch, slabOf(piece), piece.gap, segment, cosine, sine);
      if (!lambdas) continue;
      const Point middle = segment.at((lambdas->first + lambdas->second) / 2);
      const int direction = segment.nx > 0 ? 1 : -1;
      const Rational scale = 1 + abs(middle[0]) + abs(middle[1]);
      for (Rational step = scale * powerOfHalf(20); step > scale * powerOfHalf(120); step /= 1024) {
        const Point off{middle[0] + direction * step, middle[1]};
        const RayHit back = rays_.castTo(loops.sample, off, middle);
        if (back.kind != RayHit::Kind::SubFace || !back.fromPositiveSide || back.face.patch != piece.patch ||
            back.slab != piece.slab || back.gap != piece.gap) {
          continue;
        }
        const RayHit ahead = rays_.cast(loops.sample, off, direction);
        const Rational room = ahead.kind == RayHit::Kind::Nothing ? scale : Rational(ahead.along) / 2;
        return {(off[0] + direction * room).convert_to<double>(), off[1].convert_to<double>()};
      }
    }
    throw std::runtime_error("CellGraph: no point could be placed inside a face");
  }

  std::array<double, 4> boxOf(const IntervalLoops& loops, const std::vector<std::uint32_t>& members) const {
    const RoundingScope rounding;
    const slices::IntervalSlice slice(loops.sample);
    std::array<double, 4> box{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (std::uint32_t index : members) {
      const Piece& piece = loops.pieces[index];
      const PatchGeometry& patch = arrangement_.patches[piece.patch];
      const std::array<Interval, 2> end0 = slice.end(patch, 0), end1 = slice.end(patch, 1);
      const auto lambdas = slice.pieceOf(arrangement_, piece.patch, slabOf(piece), piece.gap);
      const Interval low = lambdas ? lambdas->first : Interval(0), high = lambdas ? lambdas->second : Interval(1);
      for (const Interval& lambda : {low, high}) {
        for (int axis : {0, 1}) {
          const Interval value = end0[axis] + lambda * (end1[axis] - end0[axis]);
          box[axis] = std::min(box[axis], value.lower());
          box[axis + 2] = std::max(box[axis + 2], value.upper());
        }
      }
    }
    return box;
  }

  /// Every loop of a face bounds the same cell.
  void checkCells(const IntervalLoops& loops) const {
    for (std::uint32_t index = 0; index < loops.pieces.size(); ++index) {
      const Piece& piece = loops.pieces[index];
      const std::uint32_t node = loops.nodeOfLoop[loops.loopOf[index]];
      if (cellOfPiece_[graph_.pieceIndex(piece.patch, piece.slab, piece.gap)] != graph_.parts_.nodes[node].cell) {
        throw std::logic_error("CellGraph: a face's loops bound different cells");
      }
    }
  }

  /// The node of each piece from this interval on, where it changes (only new
  /// pieces can change when the faces went on with their nodes).
  void recordRuns(const IntervalLoops& loops, const std::vector<std::uint32_t>& pieces) {
    for (std::uint32_t index : pieces) {
      addRun(graph_.parts_.runsOfPiece[loops.pieceIndices[index]], loops.interval,
             loops.nodeOfLoop[loops.loopOf[index]]);
    }
    addRun(graph_.parts_.unboundedRuns, loops.interval, loops.unboundedNode);
  }

  void recordRuns(const IntervalLoops& loops) {
    std::vector<std::uint32_t> all(loops.pieces.size());
    std::iota(all.begin(), all.end(), 0);
    recordRuns(loops, all);
  }

  static void addRun(std::vector<CellGraph::NodeRun>& runs, std::uint32_t interval, std::uint32_t node) {
    if (runs.empty() || runs.back().node != node) runs.push_back({interval, node});
  }

  static constexpr std::uint32_t kNotFree = ~std::uint32_t{0};

  CellGraph& graph_;
  const Arrangement& arrangement_;
  const SliceRays& rays_;
  const CellGraph::CellOfFace& cellOf_;
  AngleAlgebra& algebra_;
  std::vector<std::uint32_t> cellOfPiece_;
  std::vector<AlgebraicAngle> samples_;
  std::vector<std::vector<SubFaceGlue>> horizontalGluesAt_;
  std::set<std::pair<std::uint64_t, std::uint64_t>> spiralGlues_;
  std::vector<std::array<std::uint32_t, 2>> spiralOfEnd_;
  std::vector<std::vector<std::pair<std::uint32_t, int>>> patchesAtSpiral_;
};

CellGraph::CellGraph(const Arrangement& arrangement, const SliceRays& rays, const CellOfFace& cellOf,
                     AngleAlgebra& algebra, const Cancellation& cancellation) {
  CellGraphSweep(*this, arrangement, rays, cellOf, algebra).run(cancellation);
}

CellGraph::CellGraph(const Arrangement& arrangement, Parts parts, std::size_t cellCount, AngleAlgebra& algebra)
    : parts_(std::move(parts)) {
  numberPieces(arrangement);
  checkParts(cellCount, algebra);
}

void CellGraph::numberPieces(const Arrangement& arrangement) {
  std::uint32_t slabs = 0, gaps = 0;
  for (const PatchSubdivision& subdivision : arrangement.subdivisions) {
    firstSlabOfPatch_.push_back(slabs);
    for (const PatchSlab& slab : subdivision.slabs) {
      firstGapOfSlab_.push_back(gaps);
      gaps += static_cast<std::uint32_t>(slab.faces.size());
    }
    slabs += static_cast<std::uint32_t>(subdivision.slabs.size());
  }
  pieceCount_ = gaps;
}

void CellGraph::checkParts(std::size_t cellCount, AngleAlgebra& algebra) const {
  const auto require = [](bool holds, const char* part) {
    if (!holds) throw std::invalid_argument(part);
  };
  const std::vector<AlgebraicAngle>& angles = parts_.criticalAngles;
  for (std::size_t i = 1; i < angles.size(); ++i) {
    require(algebra.compare(angles[i - 1], angles[i]) < 0, "the graph's critical angles (not increasing)");
  }
  const std::size_t intervals = intervalCount(), nodes = parts_.nodes.size();
  for (const CellGraphNode& node : parts_.nodes) {
    require(node.cell < cellCount && node.firstInterval <= node.lastInterval && node.lastInterval < intervals &&
                node.sample.isRational(),
            "a node of the graph");
  }
  for (const CellGraphEdge& edge : parts_.edges) {
    require(edge.from < nodes && edge.to < nodes && edge.angle < intervals, "an edge of the graph");
  }
  require(parts_.runsOfPiece.size() == pieceCount_, "the graph's pieces");
  const auto checkRuns = [&](const std::vector<NodeRun>& runs) {
    for (std::size_t i = 0; i < runs.size(); ++i) {
      require(runs[i].interval < intervals && runs[i].node < nodes && (i == 0 || runs[i - 1].interval < runs[i].interval),
              "the nodes of a piece of the graph");
    }
  };
  for (const auto& runs : parts_.runsOfPiece) checkRuns(runs);
  checkRuns(parts_.unboundedRuns);
}

std::uint32_t CellGraph::intervalOf(const AlgebraicAngle& angle, AngleAlgebra& algebra) const {
  const std::vector<AlgebraicAngle>& angles = parts_.criticalAngles;
  if (angles.empty()) return 0;
  const auto after = std::upper_bound(angles.begin(), angles.end(), angle,
                                      [&](const auto& a, const auto& b) { return algebra.compare(a, b) < 0; });
  if (after == angles.begin()) return static_cast<std::uint32_t>(angles.size() - 1);
  return static_cast<std::uint32_t>(after - angles.begin() - 1);
}

std::optional<std::uint32_t> CellGraph::nodeAtRun(const std::vector<NodeRun>& runs, std::uint32_t interval) const {
  const auto after = std::upper_bound(runs.begin(), runs.end(), interval,
                                      [](std::uint32_t i, const NodeRun& run) { return i < run.interval; });
  if (after == runs.begin()) return std::nullopt;
  return std::prev(after)->node;
}

std::optional<std::uint32_t> CellGraph::nodeOf(const RayHit& hit, const AlgebraicAngle& rationalAngle,
                                               AngleAlgebra& algebra) const {
  const std::uint32_t interval = intervalOf(rationalAngle, algebra);
  if (hit.kind == RayHit::Kind::Nothing) return nodeAtRun(parts_.unboundedRuns, interval);
  if (hit.kind != RayHit::Kind::SubFace || !hit.fromPositiveSide) return std::nullopt;
  return nodeAtRun(parts_.runsOfPiece[pieceIndex(hit.face.patch, hit.slab, hit.gap)], interval);
}

}  // namespace freespace
