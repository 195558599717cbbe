#include "freespace/topology/cell_graph.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "../geometry/disjoint_sets.h"
#include "face_placement.h"
#include "slice_loops.h"
#include "slice_nesting.h"

namespace freespace {

namespace {

using cellgraph::IntervalLoops;
using cellgraph::LiveState;
using cellgraph::Piece;
using slices::Point;

/// Pairs (loop before, loop after) that share boundary across a critical angle.
using LoopLinks = std::set<std::pair<std::uint32_t, std::uint32_t>>;

}  // namespace

/// Builds a CellGraph interval after interval (see CellGraph).
class CellGraphSweep {
 public:
  CellGraphSweep(CellGraph& graph, const Arrangement& arrangement, const SliceRays& rays,
                 const CellGraph::CellOfFace& cellOf, AngleAlgebra& algebra)
      : graph_(graph),
        arrangement_(arrangement),
        rays_(rays),
        cellOf_(cellOf),
        algebra_(algebra),
        placement_(arrangement, rays),
        neighbours_(arrangement, graph) {
    numberPieces();
    findCriticalAngles();
    indexHorizontalGlues();
  }

  void run(const Cancellation& cancellation) {
    const std::uint32_t count = static_cast<std::uint32_t>(graph_.intervalCount());
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> starting(count), ending(count);
    active_ = slabsCovering(starting, ending);
    for (const auto& [patch, slab] : starting[0]) active_[patch] = slab;
    IntervalLoops first = loopsOver(0);
    assignFaces(nullptr, first);
    recordRuns(first);
    startState(first);
    for (std::uint32_t interval = 1; interval < count; ++interval) {
      cancellation.check();
      SlabChanges changes;
      for (const auto& [patch, slab] : ending[interval]) {
        if (state_.slabOfPatch[patch] == slab) changes.removed.push_back({patch, slab});
      }
      changes.added = starting[interval];
      if (!advanceByChains(changes, interval)) advanceFromScratch(changes, interval);
    }
    const IntervalLoops last = snapshot(count - 1);
    for (std::uint32_t node : nodesOf(last)) graph_.parts_.nodes[node].lastInterval = count - 1;
    if (!graph_.parts_.criticalAngles.empty()) {
      LoopLinks links = continuingLoops(last, first);
      addGluedLoops(last, first, links);
      addEdges(last, first, links);
    }
  }

 private:
  // --- Pieces and critical angles -------------------------------------------------

  void numberPieces() {
    graph_.numberPieces(arrangement_);
    graph_.parts_.runsOfPiece.resize(graph_.pieceCount_);
    cellOfPiece_.assign(graph_.pieceCount_, kNotFree);
    pieceOfIndex_.reserve(graph_.pieceCount_);
    for (std::uint32_t patch = 0; patch < arrangement_.subdivisions.size(); ++patch) {
      const auto& slabsOfPatch = arrangement_.subdivisions[patch].slabs;
      for (std::uint32_t slab = 0; slab < slabsOfPatch.size(); ++slab) {
        for (std::uint32_t gap = 0; gap < slabsOfPatch[slab].faces.size(); ++gap) {
          pieceOfIndex_.push_back({patch, slab, gap});
          if (const auto cell = cellOf_({patch, slabsOfPatch[slab].faces[gap]})) {
            cellOfPiece_[graph_.pieceIndex(patch, slab, gap)] = *cell;
          }
        }
      }
    }
  }

  bool hasFreePiece(std::uint32_t patch, std::uint32_t slab) const { return !freePiecesOf(patch, slab).empty(); }

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
    angles.erase(
        std::unique(angles.begin(), angles.end(),
                    [&](const AlgebraicAngle& a, const AlgebraicAngle& b) { return algebra_.compare(a, b) == 0; }),
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
    const auto found = std::lower_bound(angles.begin(), angles.end(), angle,
                                        [&](const auto& a, const auto& b) { return algebra_.compare(a, b) < 0; });
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
  IntervalLoops loopsOver(std::uint32_t interval) const {
    IntervalLoops loops = piecesOver(interval);
    detail::DisjointSets sets(loops.pieces.size());
    joinAcrossCurves(loops, sets);
    joinAroundSpirals(loops, sets);
    std::unordered_map<std::uint32_t, std::uint32_t> numberOfRoot;
    for (std::uint32_t piece = 0; piece < loops.pieces.size(); ++piece) {
      const auto found = numberOfRoot.emplace(sets.find(piece), static_cast<std::uint32_t>(numberOfRoot.size()));
      loops.loopOf.push_back(found.first->second);
    }
    loops.loopCount = static_cast<std::uint32_t>(numberOfRoot.size());
    return loops;
  }

  /// The pieces over an interval (the slabs of active_), without their loops.
  IntervalLoops piecesOver(std::uint32_t interval) const {
    IntervalLoops loops;
    loops.interval = interval;
    loops.sample = samples_[interval];
    loops.slabs.assign(active_.begin(), active_.end());
    for (const auto& [patch, slab] : loops.slabs) appendFreePieces(loops, patch, slab);
    return loops;
  }

  void appendFreePieces(IntervalLoops& loops, std::uint32_t patch, std::uint32_t slab) const {
    for (std::size_t index : freePiecesOf(patch, slab)) {
      loops.pieceIndices.push_back(index);
      loops.pieces.push_back(pieceOfIndex_[index]);
    }
  }

  /// The slabs with free pieces that end and start at a critical angle, by patch.
  struct SlabChanges {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> removed, added;
  };

  // --- The live state ------------------------------------------------------------

  void startState(const IntervalLoops& loops) {
    state_.pieceOfIndex = &pieceOfIndex_;
    state_.slabOfPatch.assign(arrangement_.subdivisions.size(), -1);
    state_.live.assign(pieceOfIndex_.size(), 0);
    state_.loopOf.assign(pieceOfIndex_.size(), 0);
    for (const auto& [patch, slab] : loops.slabs) state_.slabOfPatch[patch] = slab;
    keep(loops);
  }

  /// The loops, nodes and pieces of an interval's loops as the live state's.
  void keep(const IntervalLoops& loops) {
    for (std::uint32_t index = 0; index < loops.pieces.size(); ++index) {
      state_.live[loops.pieceIndices[index]] = 1;
      state_.loopOf[loops.pieceIndices[index]] = loops.loopOf[index];
    }
    state_.nodeOfLoop = loops.nodeOfLoop;
    state_.unboundedNode = loops.unboundedNode;
  }

  /// The live state as an interval's loops.
  IntervalLoops snapshot(std::uint32_t interval) const {
    IntervalLoops loops = piecesOver(interval);
    for (std::size_t index : loops.pieceIndices) loops.loopOf.push_back(state_.loopOf[index]);
    loops.loopCount = static_cast<std::uint32_t>(state_.nodeOfLoop.size());
    loops.nodeOfLoop = state_.nodeOfLoop;
    loops.unboundedNode = state_.unboundedNode;
    return loops;
  }

  /// The free pieces of a slab (by CellGraph::pieceIndex).
  std::vector<std::size_t> freePiecesOf(std::uint32_t patch, std::uint32_t slab) const {
    std::vector<std::size_t> pieces;
    const std::size_t first = graph_.pieceIndex(patch, slab, 0);
    const std::size_t gaps = arrangement_.subdivisions[patch].slabs[slab].faces.size();
    for (std::size_t index = first; index < first + gaps; ++index) {
      if (cellOfPiece_[index] != kNotFree) pieces.push_back(index);
    }
    return pieces;
  }

  /// Moves the live state over a critical angle (`forward`) or back.
  void apply(const SlabChanges& changes, bool forward) {
    for (const auto& [patch, slab] : forward ? changes.removed : changes.added) {
      state_.slabOfPatch[patch] = -1;
      active_.erase(patch);
      for (std::size_t index : freePiecesOf(patch, slab)) state_.live[index] = 0;
    }
    for (const auto& [patch, slab] : forward ? changes.added : changes.removed) {
      state_.slabOfPatch[patch] = slab;
      active_[patch] = slab;
      for (std::size_t index : freePiecesOf(patch, slab)) state_.live[index] = 1;
    }
  }

  /// The usual step: the pieces that change only replace chains of pieces between
  /// the same kept pieces (every chain of removed pieces between two kept ones is
  /// matched by a chain of added pieces between the same two, and none closes on
  /// itself), so no loop and no face changes; the added pieces take the loops of the
  /// pieces they hang from. False (the state moved on) otherwise.
  bool advanceByChains(const SlabChanges& changes, std::uint32_t interval) {
    std::vector<std::size_t> removed, added;
    for (const auto& [patch, slab] : changes.removed) {
      for (std::size_t index : freePiecesOf(patch, slab)) removed.push_back(index);
    }
    for (const auto& [patch, slab] : changes.added) {
      for (std::size_t index : freePiecesOf(patch, slab)) added.push_back(index);
    }
    std::sort(removed.begin(), removed.end());
    std::sort(added.begin(), added.end());
    std::vector<std::pair<std::size_t, std::size_t>> before, after;
    std::vector<std::size_t> hangsFrom(added.size());
    const bool walked = chainEnds(removed, before, nullptr);
    apply(changes, true);
    if (!walked || !chainEnds(added, after, &hangsFrom)) return false;
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    if (before != after) return false;
    for (std::size_t i = 0; i < added.size(); ++i) {
      state_.loopOf[added[i]] = state_.loopOf[hangsFrom[i]];
      addRun(graph_.parts_.runsOfPiece[added[i]], interval, state_.nodeOfLoop[state_.loopOf[added[i]]]);
    }
    return true;
  }

  /// Any other step (the state moved on already): every loop over the interval
  /// joined again and the faces found from the previous interval's (assignFaces).
  void advanceFromScratch(const SlabChanges& changes, std::uint32_t interval) {
    apply(changes, false);
    const IntervalLoops previous = snapshot(interval - 1);
    apply(changes, true);
    IntervalLoops current = loopsOver(interval);
    for (std::uint32_t node : nodesOf(previous)) graph_.parts_.nodes[node].lastInterval = interval - 1;
    assignFaces(&previous, current);
    recordRuns(current);
    keep(current);
  }

  /// The chains the live pieces (increasing) form, each as the pair of pieces it
  /// hangs between; false when one closes on itself or a neighbour is unclear. With
  /// `hangsFrom`, for each of the pieces the first piece its chain hangs from.
  bool chainEnds(const std::vector<std::size_t>& pieces, std::vector<std::pair<std::size_t, std::size_t>>& ends,
                 std::vector<std::size_t>* hangsFrom) const {
    const auto position = [&](std::size_t piece) -> std::optional<std::size_t> {
      const auto found = std::lower_bound(pieces.begin(), pieces.end(), piece);
      if (found == pieces.end() || *found != piece) return std::nullopt;
      return static_cast<std::size_t>(found - pieces.begin());
    };
    std::vector<char> seen(pieces.size(), 0);
    for (std::size_t first = 0; first < pieces.size(); ++first) {
      if (seen[first]) continue;
      std::vector<std::size_t> chain{first}, outside;
      seen[first] = 1;
      for (std::size_t at = 0; at < chain.size(); ++at) {
        for (const std::size_t end : {0, 1}) {
          const std::optional<std::size_t> next = neighbours_.neighbour(state_, pieces[chain[at]], end);
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
      ends.push_back({std::min(outside[0], outside[1]), std::max(outside[0], outside[1])});
      if (hangsFrom) {
        for (std::size_t at : chain) (*hangsFrom)[at] = outside[0];
      }
    }
    return true;
  }

  /// The nodes of the faces over an interval.
  std::set<std::uint32_t> nodesOf(const IntervalLoops& loops) const {
    std::set<std::uint32_t> nodes{loops.unboundedNode};
    for (std::uint32_t loop : loops.loopOf) nodes.insert(loops.nodeOfLoop[loop]);
    return nodes;
  }

  const PatchSlab& slabOf(const Piece& piece) const { return arrangement_.subdivisions[piece.patch].slabs[piece.slab]; }

  void joinAcrossCurves(const IntervalLoops& loops, detail::DisjointSets& sets) const {
    for (std::uint32_t index = 0; index < loops.pieces.size(); ++index) {
      for (const std::size_t end : {0, 1}) {
        if (const auto next = neighbours_.curveNeighbour(loops, index, end))
          sets.unite(index, static_cast<std::uint32_t>(*next));
      }
    }
  }

  /// Pieces ending at one spiral point are joined in pairs, by the gluing around
  /// spirals when more than two end there.
  void joinAroundSpirals(const IntervalLoops& loops, detail::DisjointSets& sets) const {
    const cellgraph::SpiralEnds ends = neighbours_.spiralEnds(loops);
    for (auto first = ends.begin(); first != ends.end();) {
      const auto last = std::find_if(first, ends.end(), [&](const auto& end) { return end.first != first->first; });
      const std::size_t count = last - first;
      if (count == 1) throw std::logic_error("CellGraph: a free piece ends alone at a spiral");
      for (auto i = first; i != last; ++i) {
        for (auto j = i + 1; j != last; ++j) {
          if (count == 2 || neighbours_.gluedAroundSpiral(loops.pieces[i->second], loops.pieces[j->second])) {
            sets.unite(static_cast<std::uint32_t>(i->second), static_cast<std::uint32_t>(j->second));
          }
        }
      }
      first = last;
    }
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
        graph_.parts_.nodes.push_back(
            newNode(current, face.loops, members, nesting.outer, face.previousNodes, unbounded));
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
      node.point = placement_.farPoint();
      return node;
    }
    const Piece& piece = loops.pieces[members[faceLoops.front()].front()];
    node.cell = cellOfPiece_[graph_.pieceIndex(piece.patch, piece.slab, piece.gap)];
    node.point = placement_.pointOff(loops, members[faceLoops.front()]);
    const auto outer = std::find_if(faceLoops.begin(), faceLoops.end(), [&](std::uint32_t l) { return outerLoops[l]; });
    if (outer != faceLoops.end()) {
      node.box = placement_.boxOf(loops, members[*outer]);
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

  /// The node of each piece from this interval on, where it changes.
  void recordRuns(const IntervalLoops& loops) {
    for (std::uint32_t index = 0; index < loops.pieces.size(); ++index) {
      addRun(graph_.parts_.runsOfPiece[loops.pieceIndices[index]], loops.interval,
             loops.nodeOfLoop[loops.loopOf[index]]);
    }
    addRun(graph_.parts_.unboundedRuns, loops.interval, loops.unboundedNode);
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
  const cellgraph::FacePlacement placement_;
  const cellgraph::PieceNeighbours neighbours_;
  std::vector<std::uint32_t> cellOfPiece_;
  std::vector<AlgebraicAngle> samples_;
  std::vector<std::vector<SubFaceGlue>> horizontalGluesAt_;

  std::vector<Piece> pieceOfIndex_;
  std::map<std::uint32_t, std::uint32_t> active_;
  LiveState state_;
};

CellGraph::CellGraph(const Arrangement& arrangement, const SliceRays& rays, const CellOfFace& cellOf,
                     AngleAlgebra& algebra, const Cancellation& cancellation) {
  CellGraphSweep(*this, arrangement, rays, cellOf, algebra).run(cancellation);
  indexEdges();
}

CellGraph::CellGraph(const Arrangement& arrangement, Parts parts, std::size_t cellCount, AngleAlgebra& algebra)
    : parts_(std::move(parts)) {
  numberPieces(arrangement);
  checkParts(cellCount, algebra);
  indexEdges();
}

void CellGraph::indexEdges() {
  firstEdgeOfNode_.assign(parts_.nodes.size() + 1, 0);
  for (const CellGraphEdge& edge : parts_.edges) {
    ++firstEdgeOfNode_[edge.from + 1];
    ++firstEdgeOfNode_[edge.to + 1];
  }
  std::partial_sum(firstEdgeOfNode_.begin(), firstEdgeOfNode_.end(), firstEdgeOfNode_.begin());
  edgesByNode_.resize(firstEdgeOfNode_.back());
  std::vector<std::uint32_t> filled(firstEdgeOfNode_.begin(), firstEdgeOfNode_.end() - 1);
  for (std::uint32_t edge = 0; edge < parts_.edges.size(); ++edge) {
    edgesByNode_[filled[parts_.edges[edge].from]++] = edge;
    edgesByNode_[filled[parts_.edges[edge].to]++] = edge;
  }
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
    require(edge.from < nodes && edge.to < nodes && edge.from != edge.to && edge.angle < intervals,
            "an edge of the graph");
  }
  require(parts_.runsOfPiece.size() == pieceCount_, "the graph's pieces");
  const auto checkRuns = [&](const std::vector<NodeRun>& runs) {
    for (std::size_t i = 0; i < runs.size(); ++i) {
      require(
          runs[i].interval < intervals && runs[i].node < nodes && (i == 0 || runs[i - 1].interval < runs[i].interval),
          "the nodes of a piece of the graph");
    }
  };
  for (const auto& runs : parts_.runsOfPiece) checkRuns(runs);
  checkRuns(parts_.unboundedRuns);
}

std::pair<double, double> CellGraph::arc(std::uint32_t first, std::uint32_t last) const {
  const std::vector<AlgebraicAngle>& angles = parts_.criticalAngles;
  if (angles.empty()) return {-M_PI, 2 * M_PI};
  const std::uint32_t count = static_cast<std::uint32_t>(intervalCount());
  const double low = angles[first].radians();
  if ((last + 1) % count == first) return {low, 2 * M_PI};
  return {low, std::fmod(angles[(last + 1) % count].radians() - low + 4 * M_PI, 2 * M_PI)};
}

double CellGraph::arcWidth(std::uint32_t node) const {
  return arc(parts_.nodes[node].firstInterval, parts_.nodes[node].lastInterval).second;
}

bool CellGraph::runHolds(const CellGraphNode& node, std::uint32_t interval) const {
  const auto count = static_cast<std::uint32_t>(intervalCount());
  return (interval + count - node.firstInterval) % count <= (node.lastInterval + count - node.firstInterval) % count;
}

std::optional<std::vector<std::uint32_t>> CellGraph::route(
    std::uint32_t from, std::uint32_t to, const std::function<bool(std::uint32_t, std::uint32_t)>& usable) const {
  // Least cost first (Dijkstra) over (node, critical angle it was entered through),
  // each settled once, with the state it was reached from.
  using State = std::uint64_t;
  constexpr std::uint32_t kStart = ~std::uint32_t{0};
  const auto state = [](std::uint32_t node, std::uint32_t angle) { return (State{node} << 32) | angle; };
  const auto nodeOf = [](State s) { return static_cast<std::uint32_t>(s >> 32); };
  const auto angleOf = [](State s) { return static_cast<std::uint32_t>(s & 0xFFFFFFFFu); };
  std::unordered_map<State, std::pair<double, State>> reached{{state(from, kStart), {0, state(from, kStart)}}};
  using Entry = std::pair<double, State>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  queue.push({0, state(from, kStart)});
  std::optional<State> arrived;
  while (!queue.empty()) {
    const auto [cost, at] = queue.top();
    queue.pop();
    if (cost > reached.at(at).first) continue;
    if (nodeOf(at) == to) {
      arrived = at;
      break;
    }
    const std::uint32_t node = nodeOf(at);
    // A thin node left through the angle it was entered by joins its neighbours only
    // through faces pinched to a sliver of angles.
    const double width = arcWidth(node);
    const double pinch = width < kThinArc ? kThinNodeCost / std::max(width, 1e-12) : 0;
    for (const std::uint32_t index : edgesAt(node)) {
      const CellGraphEdge& edge = parts_.edges[index];
      if (usable && !usable(edge.from, edge.to)) continue;
      const std::uint32_t neighbour = edge.from == node ? edge.to : edge.from, angle = edge.angle;
      const double through = cost + 1 + (angle == angleOf(at) ? pinch : 0);
      const State onward = state(neighbour, angle);
      const auto found = reached.find(onward);
      if (found != reached.end() && found->second.first <= through) continue;
      reached[onward] = {through, at};
      queue.push({through, onward});
    }
  }
  if (!arrived) return std::nullopt;
  std::vector<std::uint32_t> nodes{to};
  for (State at = *arrived; nodeOf(at) != from || angleOf(at) != kStart;) {
    at = reached.at(at).second;
    nodes.push_back(nodeOf(at));
  }
  return std::vector<std::uint32_t>(nodes.rbegin(), nodes.rend());
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
  if (hit.kind == RayHit::Kind::Nothing) return unboundedNode(interval);
  if (hit.kind != RayHit::Kind::SubFace || !hit.fromPositiveSide) return std::nullopt;
  return nodeOfPiece(pieceIndex(hit.face.patch, hit.slab, hit.gap), interval);
}

}  // namespace freespace
