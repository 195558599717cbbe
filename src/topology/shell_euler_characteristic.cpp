#include "freespace/topology/shell_euler_characteristic.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "horizontal_edge.h"
#include "slab_end_order.h"

namespace freespace {

namespace {

/// Names what crosses a slice at a point: a curve, a spiral (a segment end's
/// features), a rank along one patch's segment at its event, or a named point of a
/// horizontal edge. Names joined in a slice are one point.
using AtomKey = std::array<std::uint32_t, 5>;
constexpr std::uint32_t kCurveAtom = 0, kSpiralAtom = 1, kRankAtom = 2, kEdgePointAtom = 3;

AtomKey curveAtom(std::uint32_t curve) { return {kCurveAtom, curve, 0, 0, 0}; }

AtomKey spiralAtom(const PatchGeometry& patch, int k) {
  const SegmentEnd& end = patch.segment.ends[k];
  return {kSpiralAtom, end.robotVertex, end.vertex, end.edge[0], end.edge[1]};
}

AtomKey rankAtom(std::uint32_t patch, int rank) { return {kRankAtom, patch, static_cast<std::uint32_t>(rank), 0, 0}; }

AtomKey edgePointAtom(std::size_t edge, std::size_t point) {
  return {kEdgePointAtom, static_cast<std::uint32_t>(edge), static_cast<std::uint32_t>(point), 0, 0};
}

/// A piece of a segment in a slice, for one shell: inside a slab (patch, gap), at an
/// event of a patch (patch, rank of its low end), or on a horizontal edge (edge, index
/// of its low point). Pieces of the patches on one edge are one piece.
using PieceKey = std::array<std::uint32_t, 4>;
constexpr std::uint32_t kSlabPiece = 0, kEventPiece = 1, kEdgePiece = 2;

/// The points and pieces of every shell in one slice.
class SliceGraph {
 public:
  void join(const AtomKey& a, const AtomKey& b) {
    for (const AtomKey* atom : {&a, &b}) {
      if ((*atom)[0] == kCurveAtom || (*atom)[0] == kSpiralAtom) touched_.push_back(*atom);
    }
    const std::uint32_t rootA = find(index(a)), rootB = find(index(b));
    parent_[rootA] = rootB;
  }

  /// The curves and spirals joined to other names in this slice.
  std::vector<AtomKey> touched() const {
    std::vector<AtomKey> atoms = touched_;
    std::sort(atoms.begin(), atoms.end());
    atoms.erase(std::unique(atoms.begin(), atoms.end()), atoms.end());
    return atoms;
  }

  void point(std::uint32_t shell, const AtomKey& atom) { points_.emplace_back(shell, index(atom)); }

  void piece(std::uint32_t shell, std::uint32_t kind, std::uint32_t owner, std::uint32_t index) {
    pieces_.insert({shell, kind, owner, index});
  }

  /// Adds sign * (points - pieces) of each shell to chi.
  void addTo(std::vector<long>& chi, int sign) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> distinct;
    for (const auto& [shell, atom] : points_) distinct.emplace(shell, find(atom));
    for (const auto& [shell, root] : distinct) chi[shell] += sign;
    for (const PieceKey& piece : pieces_) chi[piece[0]] -= sign;
  }

 private:
  std::uint32_t index(const AtomKey& atom) {
    const auto [found, inserted] = atoms_.try_emplace(atom, static_cast<std::uint32_t>(parent_.size()));
    if (inserted) parent_.push_back(found->second);
    return found->second;
  }

  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  std::map<AtomKey, std::uint32_t> atoms_;
  std::vector<std::uint32_t> parent_;
  std::vector<AtomKey> touched_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> points_;
  std::set<PieceKey> pieces_;
};

/// The sweep over the angles Theta (see shellEulerCharacteristics). At an angle of
/// Theta, the slice is compared with the one over the arc after it: a slab holding
/// the angle inside adds the same pieces and points to both, except where its curves
/// and spirals are joined to others at the angle (by the events there), so only
/// those points of it are counted; the slabs starting at the angle (after a patch's
/// event, or above a horizontal edge) are counted whole over the arc.
class EulerSweep {
 public:
  EulerSweep(const Arrangement& arrangement, AngleAlgebra& algebra)
      : arrangement_(arrangement),
        algebra_(algebra),
        events_(patchEventSlices(arrangement.patches, arrangement.curves, arrangement.vertices, arrangement.overlaps,
                                 algebra)),
        edges_(gluing::horizontalEdgeSlices(arrangement.patches, arrangement.curves, arrangement.overlaps,
                                            arrangement.subdivisions, algebra)),
        order_(allPatches(arrangement), arrangement.subdivisions, algebra) {}

  std::vector<long> run() {
    std::vector<long> chi(arrangement_.shells.count(), 0);
    if (order_.angles().empty()) return chi;  // no events: every shell is a slice times the circle
    placeItems();
    for (std::size_t k = 0; k < order_.angles().size(); ++k) {
      SliceGraph atAngle, afterAngle;
      std::set<std::uint32_t> withEvent;
      for (const auto& [patch, slice] : eventsAt_[k]) {
        addEvent(atAngle, patch, *slice);
        addSlab(afterAngle, patch, slice->after);
        withEvent.insert(patch);
      }
      for (std::size_t edge : edgesAt_[k]) {
        addEdge(atAngle, edge);
        for (std::size_t i = 0; i < edges_[edge].edge.sides.size(); ++i) {
          const std::uint32_t patch = edges_[edge].edge.sides[i].patch;
          if (!edges_[edge].edge.sides[i].below) addSlab(afterAngle, patch, slabIndex(patch, *edges_[edge].slabs[i]));
          withEvent.insert(patch);
        }
      }
      for (const AtomKey& atom : atAngle.touched()) {
        for (const auto& [patch, slab] : slabsHoldingInside(atom, k, withEvent)) {
          addPointsOf(atom, patch, slab, {&atAngle, &afterAngle});
        }
      }
      atAngle.addTo(chi, 1);
      afterAngle.addTo(chi, -1);
    }
    return chi;
  }

 private:
  static std::vector<std::uint32_t> allPatches(const Arrangement& arrangement) {
    std::vector<std::uint32_t> patches(arrangement.patches.size());
    for (std::uint32_t patch = 0; patch < patches.size(); ++patch) patches[patch] = patch;
    return patches;
  }

  std::size_t indexOf(const AlgebraicAngle& angle) const { return order_.indexOf(angle, algebra_); }

  /// The angles at which patches have event slices and horizontal edges lie, and the
  /// patches ending at each spiral.
  void placeItems() {
    eventsAt_.assign(order_.angles().size(), {});
    edgesAt_.assign(order_.angles().size(), {});
    for (std::uint32_t patch = 0; patch < arrangement_.subdivisions.size(); ++patch) {
      for (const PatchEventSlice& slice : events_[patch]) eventsAt_[indexOf(slice.angle)].emplace_back(patch, &slice);
      for (int k = 0; k < 2; ++k) patchesAtSpiral_[spiralAtom(arrangement_.patches[patch], k)].push_back(patch);
    }
    for (std::size_t edge = 0; edge < edges_.size(); ++edge) edgesAt_[indexOf(edges_[edge].edge.angle)].push_back(edge);
  }

  std::uint32_t slabIndex(std::uint32_t patch, const PatchSlab& slab) const {
    return static_cast<std::uint32_t>(&slab - arrangement_.subdivisions[patch].slabs.data());
  }

  /// The patches (other than those with an event or edge at angle k) whose slabs
  /// holding the angle inside have a curve or spiral as a side.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> slabsHoldingInside(const AtomKey& atom, std::size_t k,
                                                                          const std::set<std::uint32_t>& withEvent) const {
    std::vector<std::uint32_t> patches;
    if (atom[0] == kCurveAtom) {
      patches = {arrangement_.curves[atom[1]].first, arrangement_.curves[atom[1]].second};
    } else {
      patches = patchesAtSpiral_.at(atom);
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> holding;
    for (std::uint32_t patch : patches) {
      if (withEvent.count(patch)) continue;
      if (const std::optional<std::uint32_t> slab = order_.slabHoldingAngle(patch, k)) holding.emplace_back(patch, *slab);
    }
    return holding;
  }

  std::uint32_t shellOf(std::uint32_t patch, std::uint32_t face) const {
    return arrangement_.shells.shellOf({patch, face});
  }

  /// The points and pieces of a slab, at an angle it holds inside: each gap between
  /// its curves is a piece between two points, the curves or segment ends around it.
  void addSlab(SliceGraph& graph, std::uint32_t patchIndex, std::uint32_t slabIndex) const {
    const PatchGeometry& patch = arrangement_.patches[patchIndex];
    const PatchSlab& slab = arrangement_.subdivisions[patchIndex].slabs[slabIndex];
    for (std::uint32_t gap = 0; gap < slab.faces.size(); ++gap) {
      const std::uint32_t shell = shellOf(patchIndex, slab.faces[gap]);
      graph.piece(shell, kSlabPiece, patchIndex, gap);
      graph.point(shell, gap == 0 ? spiralAtom(patch, 0) : curveAtom(slab.curves[gap - 1]));
      graph.point(shell, gap == slab.curves.size() ? spiralAtom(patch, 1) : curveAtom(slab.curves[gap]));
    }
  }

  /// The point a curve or spiral makes on a slab's segment, for the shells of the
  /// gaps next to it.
  void addPointsOf(const AtomKey& atom, std::uint32_t patchIndex, std::uint32_t slabIndex,
                   std::initializer_list<SliceGraph*> graphs) const {
    const PatchSlab& slab = arrangement_.subdivisions[patchIndex].slabs[slabIndex];
    std::vector<std::uint32_t> gaps;
    if (atom[0] == kCurveAtom) {
      const auto at = std::find(slab.curves.begin(), slab.curves.end(), atom[1]);
      if (at == slab.curves.end()) return;  // the curve does not run here
      gaps = {static_cast<std::uint32_t>(at - slab.curves.begin()), static_cast<std::uint32_t>(at - slab.curves.begin() + 1)};
    } else {
      const PatchGeometry& patch = arrangement_.patches[patchIndex];
      if (spiralAtom(patch, 0) == atom) gaps.push_back(0);
      if (spiralAtom(patch, 1) == atom) gaps.push_back(static_cast<std::uint32_t>(slab.curves.size()));
    }
    for (SliceGraph* graph : graphs) {
      for (std::uint32_t gap : gaps) graph->point(shellOf(patchIndex, slab.faces[gap]), atom);
    }
  }

  /// A patch's event: the curves and ends at one rank are one point; each sub-face
  /// of the slab before and after covers the ranks from its low side's to its high
  /// side's there.
  void addEvent(SliceGraph& graph, std::uint32_t patchIndex, const PatchEventSlice& slice) const {
    const PatchGeometry& patch = arrangement_.patches[patchIndex];
    graph.join(spiralAtom(patch, 0), rankAtom(patchIndex, 0));
    graph.join(spiralAtom(patch, 1), rankAtom(patchIndex, slice.endRank));
    const auto cover = [&](std::size_t slabIndex, const std::vector<int>& ranks) {
      const PatchSlab& slab = arrangement_.subdivisions[patchIndex].slabs[slabIndex];
      for (std::size_t i = 0; i < slab.curves.size(); ++i) graph.join(curveAtom(slab.curves[i]), rankAtom(patchIndex, ranks[i]));
      std::vector<int> sides{0};
      sides.insert(sides.end(), ranks.begin(), ranks.end());
      sides.push_back(slice.endRank);
      coverGaps(graph, patchIndex, slab, sides, kEventPiece, patchIndex,
                [&](int rank) { return rankAtom(patchIndex, rank); });
    };
    cover(slice.before, slice.ranksBefore);
    cover(slice.after, slice.ranksAfter);
  }

  /// Each sub-face of a slab covers the positions along a line (ranks, or named
  /// points of an edge) from its low side's to its high side's (`sides`: the
  /// positions of end 0, of the slab's curves in order and of end 1), and the pieces
  /// between them.
  template <class AtomOf>
  void coverGaps(SliceGraph& graph, std::uint32_t patchIndex, const PatchSlab& slab, const std::vector<int>& sides,
                 std::uint32_t kind, std::uint32_t owner, const AtomOf& atomOf) const {
    for (std::size_t gap = 0; gap < slab.faces.size(); ++gap) {
      const std::uint32_t shell = shellOf(patchIndex, slab.faces[gap]);
      const int low = std::min(sides[gap], sides[gap + 1]), high = std::max(sides[gap], sides[gap + 1]);
      for (int position = low; position <= high; ++position) graph.point(shell, atomOf(position));
      for (int position = low; position < high; ++position) {
        graph.piece(shell, kind, owner, static_cast<std::uint32_t>(position));
      }
    }
  }

  /// A horizontal edge: the segment ends and curves of each side are at named points
  /// of the edge; each sub-face of a side covers the named points from its low side's
  /// to its high side's, and the pieces between them, which the sides share.
  void addEdge(SliceGraph& graph, std::size_t edgeIndex) const {
    const gluing::EdgeSlice& edge = edges_[edgeIndex];
    std::map<gluing::EdgePoint, int> pointIndex;
    for (std::size_t k = 0; k < edge.reading.points.size(); ++k) {
      for (const gluing::EdgePoint& name : edge.reading.points[k]) pointIndex[name] = static_cast<int>(k);
    }
    std::vector<std::uint32_t> onEdge;
    for (const gluing::EdgeSide& side : edge.edge.sides) onEdge.push_back(side.patch);
    const auto at = [&](const gluing::EdgePoint& name) {
      const auto found = pointIndex.find(name);
      if (found == pointIndex.end()) throw std::logic_error("shellEulerCharacteristics: a side's point is not on its edge");
      return found->second;
    };
    for (std::size_t i = 0; i < edge.edge.sides.size(); ++i) {
      const std::uint32_t patchIndex = edge.edge.sides[i].patch;
      const PatchGeometry& patch = arrangement_.patches[patchIndex];
      const PatchSlab& slab = *edge.slabs[i];
      std::vector<int> bounds{at(gluing::spiralPointOf(patch, 0))};
      graph.join(spiralAtom(patch, 0), edgePointAtom(edgeIndex, bounds.back()));
      for (std::uint32_t curve : slab.curves) {
        bounds.push_back(at(gluing::curvePointOf(patchIndex, arrangement_.curves[curve].other(patchIndex), onEdge)));
        graph.join(curveAtom(curve), edgePointAtom(edgeIndex, bounds.back()));
      }
      bounds.push_back(at(gluing::spiralPointOf(patch, 1)));
      graph.join(spiralAtom(patch, 1), edgePointAtom(edgeIndex, bounds.back()));
      coverGaps(graph, patchIndex, slab, bounds, kEdgePiece, static_cast<std::uint32_t>(edgeIndex),
                [&](int point) { return edgePointAtom(edgeIndex, point); });
    }
  }

  const Arrangement& arrangement_;
  AngleAlgebra& algebra_;
  std::vector<std::vector<PatchEventSlice>> events_;
  std::vector<gluing::EdgeSlice> edges_;
  /// Theta: every angle where a slab begins or ends.
  gluing::SlabEndOrder order_;
  std::vector<std::vector<std::pair<std::uint32_t, const PatchEventSlice*>>> eventsAt_;
  std::vector<std::vector<std::size_t>> edgesAt_;
  std::map<AtomKey, std::vector<std::uint32_t>> patchesAtSpiral_;
};

}  // namespace

std::vector<long> shellEulerCharacteristics(const Arrangement& arrangement, AngleAlgebra& algebra) {
  return EulerSweep(arrangement, algebra).run();
}

}  // namespace freespace
