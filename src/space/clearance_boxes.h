#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "freespace/space/free_space.h"

namespace freespace {

/// A configuration, or a segment of configurations at one angle (from `at` to `at` +
/// `along` in (x, y)), with a certified upper bound on its clearance: the clearance of
/// any configuration is at most max(0, that + |dxy|) + lever |dtheta|, dxy its offset
/// from the nearest (the lever is the robot's reach r, or for a contact, how far from
/// the robot's axis its point in the contact lies: turning moves that point no faster;
/// a negative bound, a blocked configuration's depth, bounds only its own slice:
/// docs/design.md section 7). A segment is a contact's whole patch at that angle:
/// every configuration on it touches; at the fraction t along it, the robot's point in
/// the contact lies at minus contactFrom + t contactAlong from the robot's axis (in the
/// robot's frame), whose length is the lever there.
struct ClearanceAnchor {
  std::array<double, 3> at;
  double upper;
  double lever;
  std::array<double, 2> along{}, contactFrom{}, contactAlong{};
};

/// Angles counterclockwise from `from` to `to` (radians in [-pi, pi], padded), or
/// the whole circle.
struct AngleArc {
  double from, to;
  bool whole;
};

/// A box of configurations [low, high] in (x, y, theta), with bounds on the clearance
/// at every configuration in it.
struct ClearanceBox {
  // First what the searches over chains read of each box they pass, in one cache line
  // at most two: those reads were most of OMPL.app's Maze_planar searches.
  double lower = 0, upper = 0;
  bool split = false;
  /// Never useful again: its clearance is below a bottleneck already reached.
  bool dropped = false;
  std::uint8_t splitAxes = 0;
  /// No patch of the free space's boundary meets the box (as when its lower bound is
  /// above 0): all of it lies where its centre does (blocked, or in centreCell). Known
  /// once bounded for a box blocked at its centre, unless its bound lies below the
  /// level boxes are dropped below (see settleBlocked); for one free there, false until
  /// dropOutside asks it of another cell than the box's.
  bool unbroken = false;
  /// Once split, its parts are boxes firstChild on: halved along the axes of
  /// `splitAxes` (bit k for axis k), 2 to the number of those axes of them, part i
  /// on the upper side of the j-th of those axes when bit j of i is set.
  std::uint32_t firstChild = 0;
  /// The free cell holding the box's centre (none when it is blocked).
  std::optional<std::uint32_t> centreCell;
  /// Boxes it touches (closed boxes, theta wrapping around); some may be split since.
  std::vector<std::uint32_t> neighbours;
  std::array<double, 3> low, high;
  /// The certified lower bound on its centre's clearance.
  double centreLower = -HUGE_VAL;
  /// Its centre, the contact its clearance reaches there (the witness, clearance 0)
  /// and that contact's whole patch at its angle, then the distinct anchors that bound
  /// it best among its own, its siblings', its parent's neighbours' (their own) and its
  /// parent's (upper is the least of their bounds and of the best one's mixes with
  /// each other: ClearanceBoxes::bound); both forgotten once it is split or dropped,
  /// and no anchors kept by a box bounded below the drop level (see dropBelow).
  std::vector<ClearanceAnchor> own, anchors;
};

/// The free space's clearance over a domain of (x, y, theta) bounded by boxes that are
/// halved where needed (docs/design.md section 7): the clearance is certified at each
/// box's centre, and is 1-Lipschitz in (x, y) and r-Lipschitz in theta, so it lies
/// above the centre's lower bound minus |half diagonal in (x, y)| + r (half width in
/// theta) everywhere in the box, and below the least, over configurations of known
/// clearance nearby (centres, the contacts their witnesses reach and those contacts'
/// patches), of that clearance plus the distance to the box's farthest corner. Any continuous path
/// passes through a chain of touching boxes, so the widest chain by upper bounds
/// bounds every path's bottleneck from above, and a chain by lower bounds gives a path
/// whose bottleneck is at least its value.
class ClearanceBoxes {
 public:
  /// Boxes covering x in [low[0], high[0]], y in [low[1], high[1]] and every theta,
  /// nearly cubes in the metric |dxy| + reach |dtheta|, about `across` along the
  /// longer side.
  ClearanceBoxes(const FreeSpace& space, const std::array<double, 2>& low, const std::array<double, 2>& high,
                 double reach, int across = 16);

  /// A chain of touching boxes and the least of their bounds (the lower or upper
  /// ones): its bottleneck.
  struct Chain {
    double bottleneck = -HUGE_VAL;
    std::vector<std::uint32_t> boxes;
  };
  enum class Bound { Lower, Upper };
  /// A widest-chain search's room: each box's bottleneck, predecessor and whether it
  /// is final. A caller that searches round after round keeps it: made anew each time
  /// on memory the process has not touched yet, it took a fifth of the maze's searches.
  struct ChainRoom {
    std::vector<double> widest;
    std::vector<std::uint32_t> previous;
    std::vector<char> final;
  };
  /// The chain of boxes neither split nor dropped from `from` to `to` whose least
  /// bound is largest (empty when none joins them), through boxes whose upper bound
  /// is at least `upperAtLeast`, and whose centres lie in `centreCell` when given,
  /// only.
  Chain widestChain(std::uint32_t from, std::uint32_t to, Bound bound, double upperAtLeast = -HUGE_VAL,
                    std::optional<std::uint32_t> centreCell = std::nullopt) const;
  /// The same, searched in `room`.
  Chain widestChain(std::uint32_t from, std::uint32_t to, Bound bound, double upperAtLeast,
                    std::optional<std::uint32_t> centreCell, ChainRoom& room) const;

  /// The widest chains by upper bounds from one box, kept between searches: each
  /// search starts again only the boxes whose chain passed a box halved or dropped
  /// since the last one and the boxes added since, and goes on from the boxes the last
  /// one left below its level (bounds only fall and boxes only go, so every other box
  /// keeps its chain and its value).
  struct UpperSearch {
    std::uint32_t from = UINT32_MAX;
    std::vector<double> widest;
    std::vector<std::uint32_t> previous;
    std::vector<char> final;
    std::size_t changesSeen = 0;
    /// Room the next search reuses: the boxes it starts again, and the tree of
    /// predecessors turned into each box's successors (ClearanceBoxes::markReset).
    std::vector<char> reset;
    std::vector<std::uint32_t> firstSuccessor, successors, nextSuccessor;
  };
  /// For every box, the widest chain's bottleneck by upper bounds from `from` to it
  /// (-infinity where none reaches), where that is at least `ratio` times the least of
  /// `cap` and the bottleneck to `to`; below, the search stops and leaves lower
  /// values (a path query asks no more: docs/design.md section 7). With `search`, from
  /// where the last search with it left off (see UpperSearch).
  std::vector<double> widestUpperFrom(std::uint32_t from, std::uint32_t to, double ratio, double cap) const;
  const std::vector<double>& widestUpperFrom(std::uint32_t from, std::uint32_t to, double ratio, double cap,
                                             UpperSearch& search) const;

  /// Marks (1) the boxes, neither split nor dropped, that a chain from `from` through
  /// boxes whose upper bounds all exceed `level` reaches (the widest chains by upper
  /// bounds from `from` to them are wider than `level`, without their values).
  std::vector<char> reachedAbove(std::uint32_t from, double level) const;

  /// The widest chain by upper bounds a search (widestUpperFrom) found from its box to
  /// `to`, a box it reached at its level: along its tree of predecessors (empty when it
  /// did not reach `to`).
  static Chain chainTo(const UpperSearch& search, std::uint32_t to);

  /// The box (not split) holding a configuration of the domain.
  std::uint32_t leafAt(const Pose2& pose) const;
  /// Halves a box along the axes of `axes` (bit k for axis k; every axis: eight
  /// clearances).
  void split(std::uint32_t box, std::uint8_t axes = kEveryAxis);
  /// Halves each of `boxes` (distinct, none split) along its axesToSplit, as split()
  /// one after another would, their halves measured on every core, attached in order,
  /// then bounded on every core (from the neighbours each box had when attached); asks
  /// `keepGoing` (from any thread) before each and stops when it says no. Returns how
  /// many of `boxes` (the first ones) were halved; when `keepGoing` or a clearance
  /// throws, none is, and the exception is thrown again.
  std::size_t splitEach(const std::vector<std::uint32_t>& boxes, const std::function<bool()>& keepGoing);
  static constexpr std::uint8_t kEveryAxis = 7, kThetaAxis = 4;
  /// The axes worth halving a box along: theta alone when its centre lies deeper in
  /// the obstacle than its half diagonal in (x, y) (its upper bound then comes from
  /// its theta width alone, docs/design.md section 7), else every axis.
  std::uint8_t axesToSplit(std::uint32_t box) const;
  /// Drops every box whose upper bound is below `level`. A box's bounds and cell never
  /// change once bounded, so a call looks only at the boxes added since the last one
  /// (at every box when the level rose). The level is meant to rise only (a path
  /// query's: the best path's clearance): the boxes halved until the next call are
  /// bounded only as far as it (see bound and settleBlocked). Should a lower level
  /// come, those below the last one stay live with certified, looser, bounds.
  void dropBelow(double level);
  /// Drops every box that lies in another free cell than `cell`: unbroken (free
  /// throughout or not, all of it in its centre's cell), its centre in another (at the
  /// boxes added since the last call, as dropBelow, every box for another cell).
  void dropOutside(std::uint32_t cell);

  const ClearanceBox& box(std::uint32_t index) const { return boxes_[index]; }
  std::size_t size() const { return boxes_.size(); }
  /// The configuration at a box's centre.
  static Pose2 centre(const ClearanceBox& box);
  /// A configuration both (touching) boxes hold: the centre of their common part,
  /// theta taken from `box`'s range where they touch across theta = pi.
  Pose2 meeting(std::uint32_t box, std::uint32_t next) const;

 private:
  /// The box [low, high] with its centre's clearance (its contact looked for about
  /// `expected` away first, a hint: FreeSpace::clearance; its location taken from
  /// `location` when given, certified by the caller) and the bounds its own anchors
  /// give. It reads the boxes only: threads may measure at once.
  ClearanceBox measured(const std::array<double, 3>& low, const std::array<double, 3>& high, double expected,
                        const std::optional<Location>& location) const;
  /// A box's halves along `axes`, measured (not yet added).
  std::vector<ClearanceBox> halves(std::uint32_t box, std::uint8_t axes) const;
  /// Adds a box's halves in its place and joins them to its neighbours (not split, not
  /// dropped), whom it returns; bounds wait for boundHalves.
  std::vector<std::uint32_t> attach(std::uint32_t box, std::uint8_t axes, std::vector<ClearanceBox> halves);
  /// Bounds a split box's halves from its anchors and its halves' and `neighbours`'
  /// own (those attach returned). It writes those halves alone: threads may bound
  /// different boxes' halves at once.
  void boundHalves(std::uint32_t box, const std::vector<std::uint32_t>& neighbours);
  /// Where the centre of [low, high] lies when a free box's centre certifies it: its
  /// clearance exceeds the move between the centres (|dxy| + reach |dtheta|), so the
  /// motion between them stays free, in its cell (docs/design.md section 7).
  std::optional<Location> certifiedLocation(const ClearanceBox& known, const std::array<double, 3>& low,
                                            const std::array<double, 3>& high) const;
  /// The move from an anchor to the centre of [low, high]: |dxy| + reach |dtheta|.
  double moveBetween(const ClearanceAnchor& centre, const std::array<double, 3>& low,
                     const std::array<double, 3>& high) const;
  /// About how far the contact of the centre of [low, high] lies, from a box whose
  /// centre's clearance is known: that clearance plus the move between the centres
  /// (|dxy| + reach |dtheta|), the bound of the Lipschitz clearance on the free side
  /// (docs/design.md section 7); only a hint on the blocked side.
  double expectedClearance(const ClearanceBox& known, const std::array<double, 3>& low,
                           const std::array<double, 3>& high) const;
  /// The lever of the contact a clearance's witness reaches at angle `theta` (see
  /// ClearanceAnchor), its place `slack` from the true contact's at most.
  double contactLever(const Clearance& clearance, double theta, double slack) const;
  /// The witness's patch at angle `theta` as an anchor (none when its ends are not
  /// known to a few thousandths of the reach).
  std::optional<ClearanceAnchor> contactSegment(const Clearance& clearance, double theta) const;
  /// The bound an anchor gives on the clearance in a box, at each of its (x, y)
  /// corners (low, low), (low, high), (high, low), (high, high), over all its angles:
  /// convex in (x, y), so the most of them bounds all of the box.
  std::array<double, 4> cornerBounds(const ClearanceAnchor& anchor, const ClearanceBox& box) const;
  /// The bound an anchor gives on the clearance in a box.
  double upperBoundFrom(const ClearanceAnchor& anchor, const ClearanceBox& box) const;
  /// Room bound() reuses between calls: the candidates' bounds at a box's corners, and
  /// the most of each with its candidate.
  struct BoundScratch {
    std::vector<std::array<double, 4>> corners;
    std::vector<std::pair<double, std::uint32_t>> bounds;
  };
  /// Keeps the anchors (of `candidates`) that bound the box best, and its upper bound;
  /// none, and the first bound found below the level dropBelow last dropped by, when
  /// there is one (the next call drops the box, unless its level is lower).
  void bound(ClearanceBox& box, const std::vector<const ClearanceAnchor*>& candidates, BoundScratch& scratch) const;
  bool touch(const ClearanceBox& a, const ClearanceBox& b) const;
  /// Marks a box dropped (and logs it for the searches), and forgets its anchors.
  void drop(std::uint32_t index);
  /// Frees a box's anchors: once it is split and its halves bounded, or dropped,
  /// nothing reads them.
  void forgetAnchors(std::uint32_t index);
  /// Drops the boxes from `seen` on, neither split nor dropped, that `droppable`
  /// accepts; `seen` becomes the number of boxes (dropBelow, dropOutside).
  template <typename Droppable>
  void dropLiveFrom(std::size_t& seen, Droppable droppable);
  /// Marks (1 in search.reset) the boxes an UpperSearch must start again before its
  /// next search: those halved or dropped since its last, every box whose chain passed
  /// them, and the boxes added since; all for a new one.
  void markReset(UpperSearch& search) const;
  /// Looks whether a box blocked at its centre, once bounded, is unbroken (then its
  /// upper bound falls to 0), unless its bound lies below the level dropBelow last
  /// dropped by: the next call drops it either way (unless its level is lower). It
  /// writes that box alone.
  void settleBlocked(ClearanceBox& box) const;
  /// Whether a sub-face that bounds a free cell may meet the box: the patches whose
  /// boxes meet it (their boxes hold their segments), and of each, its slabs with such
  /// sub-faces, each over its own part of the box's angles (slabMayMeet).
  bool meetsFreeBoundary(const ClearanceBox& box) const;
  struct FreeSlab;
  /// Whether a sub-face of a patch's slab (`free`) that bounds a free cell may meet the
  /// query box at the angles given; where a crossing is known too loosely to say, asks
  /// again of each half of the angles, `halvings` times at most.
  bool slabMayMeet(std::uint32_t patch, const FreeSlab& free, const std::array<double, 2>& angles,
                   const PatchBox& query, int halvings) const;
  /// How many times meetsFreeBoundary halves a slab's angles at most, and how wide a
  /// crossing's interval (in the segment's parameter) counts as too loose.
  static constexpr int kAngleHalvings = 4;
  static constexpr double kLooseCrossing = 0.05;

  const FreeSpace& space_;
  double reach_;
  std::array<std::vector<double>, 3> rootEdges_;  // the first boxes' edges along each axis
  /// The boxes, in chunks of 4,096 that never move: a vector of them, growing, moved
  /// every box to fresh memory each time it doubled, whose first touches cost the
  /// maze's halvings up to 80 ms more (boost::container::deque, with blocks as large,
  /// finds a box more slowly: the maze's query took about a tenth longer).
  class BoxStore {
   public:
    ClearanceBox& operator[](std::size_t index) { return chunks_[index >> kChunkBits][index & kChunkMask]; }
    const ClearanceBox& operator[](std::size_t index) const { return chunks_[index >> kChunkBits][index & kChunkMask]; }
    std::size_t size() const { return size_; }
    /// Adds a box at the end.
    void push_back(ClearanceBox box);

   private:
    static constexpr int kChunkBits = 12;
    static constexpr std::size_t kChunkMask = (std::size_t{1} << kChunkBits) - 1;
    std::vector<std::unique_ptr<ClearanceBox[]>> chunks_;
    std::size_t size_ = 0;
  };
  BoxStore boxes_;
  /// The boxes halved or dropped, in order (UpperSearch::changesSeen counts them).
  std::vector<std::uint32_t> changed_;
  /// The last level and cell dropped by, and how many boxes there were then.
  double droppedBelow_ = -HUGE_VAL;
  std::size_t seenByDropBelow_ = 0;
  std::optional<std::uint32_t> droppedOutside_;
  std::size_t seenByDropOutside_ = 0;
  /// A slab of a patch with sub-faces that bound a free cell: its angles, its index,
  /// and the first and last of its gaps between curves (PatchSlab::faces) that are
  /// such sub-faces.
  struct FreeSlab {
    AngleArc arc;
    std::uint32_t slab, firstGap, lastGap;
  };
  /// Each patch's slabs with sub-faces that bound a free cell.
  std::vector<std::vector<FreeSlab>> freeSlabs_;
};

}  // namespace freespace
