#include "freespace/geometry/patch_subdivision.h"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "freespace/numbers/adaptive_sign.h"

namespace freespace {

namespace {

constexpr std::uint32_t kNoCurve = UINT32_MAX;
constexpr std::uint32_t kNoFace = UINT32_MAX;

/// The value of `other`'s line at end k of `patch`'s segment, at the angle with the
/// given cosine and sine (an SF value, docs/design.md section 4).
template <class T>
T lineAtEnd(const PatchGeometry& patch, int k, const PatchGeometry& other, const T& cosine, const T& sine) {
  return valueAt(spiralFacetForm(lineOf<T>(other.line), spiralOf<T>(patch.ends[k])), cosine, sine);
}

/// A patch's two end spirals in number type T.
template <class T>
std::array<Spiral<T>, 2> endSpirals(const PatchGeometry& patch) {
  return {spiralOf<T>(patch.ends[0]), spiralOf<T>(patch.ends[1])};
}

/// g's line at two end spirals as SF forms (they do not depend on the angle).
template <class T>
std::array<TrigLinear<T>, 2> lineFormsAtEnds(const std::array<Spiral<T>, 2>& ends, const PatchGeometry& g) {
  const PatchLine<T> line = lineOf<T>(g.line);
  return {spiralFacetForm(line, ends[0]), spiralFacetForm(line, ends[1])};
}

/// A patch's two end spirals and an angle's cosine and sine in number type T: what
/// the values of many lines at the segment's ends share.
template <class T>
struct EndsAtAngle {
  EndsAtAngle(const PatchGeometry& patch, const T& cosine, const T& sine)
      : ends(endSpirals<T>(patch)), cosine(cosine), sine(sine) {}

  /// V_g(0) and V_g(1): the values of g's line at the two ends.
  std::array<T, 2> lineValues(const PatchGeometry& g) const {
    const auto forms = lineFormsAtEnds(ends, g);
    return {valueAt(forms[0], cosine, sine), valueAt(forms[1], cosine, sine)};
  }

  std::array<Spiral<T>, 2> ends;
  T cosine, sine;
};

/// The sorted ranges [first, middle) and [middle, last) merged, each element of the
/// second range placed in the first by bisection: fewer comparisons than a merge
/// when the second range is short.
template <class Iterator, class Before>
std::vector<typename Iterator::value_type> mergedByBisection(Iterator first, Iterator middle, Iterator last,
                                                               const Before& before) {
  std::vector<typename Iterator::value_type> merged;
  merged.reserve(static_cast<std::size_t>(last - first));
  for (Iterator inserted = middle; inserted != last; ++inserted) {
    const Iterator place = std::upper_bound(first, middle, *inserted, before);
    merged.insert(merged.end(), first, place);
    merged.push_back(*inserted);
    first = place;
  }
  merged.insert(merged.end(), first, middle);
  return merged;
}

/// With V_g(k) the value of g's line at end k of the patch, g crosses the segment at
/// lambda_g = V_g(0) / (V_g(0) - V_g(1)), and V_g(0), V_g(1) have opposite signs, so
///   sign(lambda_h - lambda_g) = sign((V_g(0) V_h(1) - V_h(0) V_g(1)) V_g(0) V_h(0)).
template <class T>
T crossingOrderValue(const EndsAtAngle<T>& at, const PatchGeometry& g, const PatchGeometry& h) {
  const auto [g0, g1] = at.lineValues(g);
  const auto [h0, h1] = at.lineValues(h);
  return (g0 * h1 - h0 * g1) * g0 * h0;
}

template <class T>
T crossingOrderValue(const PatchGeometry& patch, const PatchGeometry& g, const PatchGeometry& h, const T& cosine,
                     const T& sine) {
  return crossingOrderValue(EndsAtAngle<T>(patch, cosine, sine), g, h);
}

/// lambda_g in double intervals, with the sign of its denominator V_g(0) - V_g(1).
struct IntervalLambda {
  Interval lambda;
  Sign denominator;
};

/// g's line at the patch's two ends as SF forms in double intervals
/// (lineFormsAtEnds): V_g(k) = valueAt(forms[k], cos, sin).
using EndForms = std::array<TrigLinear<Interval>, 2>;

/// lambda_g in double intervals at an angle given by its cosine and sine (inside a
/// RoundingScope); nothing when V_g(0) - V_g(1) may vanish.
std::optional<IntervalLambda> crossingLambda(const EndForms& forms, const Interval& cosine, const Interval& sine) {
  const Interval v0 = valueAt(forms[0], cosine, sine), v1 = valueAt(forms[1], cosine, sine);
  const Interval difference = v0 - v1;
  const std::optional<Sign> sign = certainSign(difference);
  if (!sign || *sign == Sign::Zero) return std::nullopt;
  return IntervalLambda{v0 / difference, *sign};
}

/// sign(lambda_h - lambda_g) when the enclosures are apart; 0 when not known.
int certainOrder(const std::optional<IntervalLambda>& g, const std::optional<IntervalLambda>& h) {
  if (!g || !h) return 0;
  if (g->lambda.upper() < h->lambda.lower()) return 1;
  if (h->lambda.upper() < g->lambda.lower()) return -1;
  return 0;
}

/// The patch's ends at an angle in double-double intervals, from the angle's
/// certified double-double parameter; none when that cannot be certified.
std::optional<EndsAtAngle<DoubleDoubleInterval>> endsInDoubleDoubles(const PatchGeometry& patch,
                                                                     const AlgebraicAngle& angle) {
  const std::optional<DoubleDoubleInterval> t = doubleDoubleParameter(angle);
  if (!t) return std::nullopt;
  const auto [cosine, sine] = doubleDoubleCosSin(*t, angle.chart());
  const NearestRoundingScope rounding;
  return EndsAtAngle<DoubleDoubleInterval>(patch, cosine, sine);
}

/// sign(lambda_h - lambda_g) in double-double intervals, when certain.
std::optional<Sign> crossingOrderInDoubleDoubles(const EndsAtAngle<DoubleDoubleInterval>& at, const PatchGeometry& g,
                                                 const PatchGeometry& h) {
  const NearestRoundingScope rounding;
  const std::optional<Sign> sign = certainSign(crossingOrderValue(at, g, h));
  if (!sign || *sign == Sign::Zero) return std::nullopt;
  return sign;
}

/// V_g(0) V_h(1) - V_h(0) V_g(1) (see crossingOrderValue) as an angle function:
/// lambda_h - lambda_g = that / ((V_g(0) - V_g(1)) (V_h(0) - V_h(1))).
AngleFunction crossingDifference(const PatchGeometry& patch, const PatchGeometry& g, const PatchGeometry& h) {
  return AngleFunction([ends = patch.ends, g = g.line, h = h.line](auto type, int chart) {
    using T = typename decltype(type)::type;
    const auto value = [&](const ContactPoints& line, int k) {
      return spiralFacetForm(lineOf<T>(line), spiralOf<T>(ends[k]));
    };
    const TrigLinear<T> h0 = value(h, 0);
    return tangentPolynomial(value(g, 0), chart) * tangentPolynomial(value(h, 1), chart) +
           tangentPolynomial(TrigLinear<T>{-h0.s, -h0.c, -h0.k}, chart) * tangentPolynomial(value(g, 1), chart);
  });
}

/// V_g(0) - V_g(1): its sign is that of the denominator of lambda_g.
AngleFunction endValueDifference(const PatchGeometry& patch, const PatchGeometry& g) {
  return AngleFunction([ends = patch.ends, g = g.line](auto type, int chart) {
    using T = typename decltype(type)::type;
    const PatchLine<T> line = lineOf<T>(g);
    const TrigLinear<T> v0 = spiralFacetForm(line, spiralOf<T>(ends[0])), v1 = spiralFacetForm(line, spiralOf<T>(ends[1]));
    return tangentPolynomial(TrigLinear<T>{v0.s - v1.s, v0.c - v1.c, v0.k - v1.k}, chart);
  });
}

/// Names the point of the patch where an event's curve crosses the segment, when a
/// combinatorial rule knows it (kind first, 0 for unnamed, then the rule's indices):
/// curves at one named point cross there together, with no exact test.
using PointKey = std::array<std::uint32_t, 7>;
constexpr std::uint32_t kUnnamed = 0, kSpiralPoint = 1, kHorizontalEdge = 2, kVertexPoint = 3;

/// How an event's curve meets its angle: at the start or the end of one of the
/// curve's arcs, or inside one (at a vertex); Inside also for events without a curve.
enum class ArcEnd : std::uint8_t { Start, End, Inside };

/// An event of one patch: the angle, the curve of the patch it involves (none for an
/// end of the patch's range or an overlap), whether it is an overlap (a horizontal
/// cut), the ends of the patch's segment the event's point or cut reaches, the
/// point's name when known, and whether it starts or ends an arc of the curve.
struct PatchEvent {
  AlgebraicAngle angle;
  std::uint32_t curve = kNoCurve;
  bool cut = false;
  std::array<bool, 2> onSide{};
  PointKey point{};
  ArcEnd arcEnd = ArcEnd::Inside;
};

/// The events at one angle: their curves, each with the segment ends it reaches,
/// and the curves whose arcs start or end there.
struct EventGroup {
  AlgebraicAngle angle;
  std::vector<std::uint32_t> curves;
  std::vector<std::array<bool, 2>> curveOnSide;
  std::vector<PointKey> curvePoint;
  bool cut = false;
  std::array<bool, 2> onSide{};
  std::vector<std::uint32_t> starting, ending;
};

class UnionFind {
 public:
  std::uint32_t add() {
    parent_.push_back(static_cast<std::uint32_t>(parent_.size()));
    return parent_.back();
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent_[find(a)] = find(b); }
  std::uint32_t size() const { return static_cast<std::uint32_t>(parent_.size()); }

 private:
  std::vector<std::uint32_t> parent_;
};

/// A value per curve for the few curves of a slab or an event, found by binary
/// search in the sorted curve indices (built per event and per slab, where hash
/// tables cost more to build than their lookups save).
template <class T>
class CurveTable {
 public:
  /// `curves` sorted, without repeats.
  explicit CurveTable(std::vector<std::uint32_t> curves) : curves_(std::move(curves)), values_(curves_.size()) {}

  T& operator[](std::uint32_t curve) { return values_[indexOf(curve)]; }
  const T& at(std::uint32_t curve) const { return values_[indexOf(curve)]; }

 private:
  std::size_t indexOf(std::uint32_t curve) const {
    const auto found = std::lower_bound(curves_.begin(), curves_.end(), curve);
    if (found == curves_.end() || *found != curve) throw std::logic_error("patchSubdivisions: a curve is not in the table");
    return static_cast<std::size_t>(found - curves_.begin());
  }

  std::vector<std::uint32_t> curves_;
  std::vector<T> values_;
};

/// The curves of two lists, sorted, without repeats.
std::vector<std::uint32_t> unionOf(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
  std::vector<std::uint32_t> all(a);
  all.insert(all.end(), b.begin(), b.end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

/// The curves of `order` that an event involves: where they start, how many there
/// are, and the others in order.
struct InvolvedBlock {
  std::vector<std::uint32_t> others;
  std::optional<std::size_t> start;
  std::size_t size = 0;
  bool contiguous = true;
};

InvolvedBlock involvedBlock(const std::vector<std::uint32_t>& order, const std::vector<std::uint32_t>& involved) {
  InvolvedBlock block;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (std::find(involved.begin(), involved.end(), order[i]) == involved.end()) {
      block.others.push_back(order[i]);
      continue;
    }
    if (block.start && *block.start + block.size != i) block.contiguous = false;
    if (!block.start) block.start = i;
    block.size++;
  }
  return block;
}

/// Subdivides one patch from its curves, vertices and overlaps.
class PatchSweep {
 public:
  /// With `recordEvents`, keeps the slices at the events (takeEventSlices).
  PatchSweep(std::uint32_t patch, const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
             AngleAlgebra& algebra, bool recordEvents)
      : patch_(patch), patches_(patches), curves_(curves), algebra_(algebra), recordEvents_(recordEvents) {}

  void addCurve(std::uint32_t curve) {
    curvesOfPatch_.push_back(curve);
    const PatchCurve& c = curves_[curve];
    const int side = c.first == patch_ ? 0 : 1;
    curveWith_[c.other(patch_)] = curve;
    for (std::size_t i = 0; i < c.angles.arcs.size(); ++i) {
      for (int end = 0; end < 2; ++end) {
        const AlgebraicAngle& angle = end == 0 ? c.angles.arcs[i].from : c.angles.arcs[i].to;
        const CurveEnd& cause = c.ends[i][end];
        events_.push_back({angle, curve, false, cause.endOnOtherLine[side], endPoint(curve, cause, angle),
                           end == 0 ? ArcEnd::Start : ArcEnd::End});
      }
    }
  }

  /// Where a curve ends inside the patch, by its cause: at the spiral of the other
  /// patch's segment end that pierces the patch, or on the other patch's horizontal
  /// edge. Patches whose ranges end at the same EF function's root have one line
  /// there (the edge lies in the facet's plane), so one point on this segment.
  PointKey endPoint(std::uint32_t curve, const CurveEnd& cause, const AlgebraicAngle& angle) const {
    const int other = curves_[curve].first == patch_ ? 1 : 0;
    for (int k = 0; k < 2; ++k) {
      if (!cause.endOnOtherLine[other][k]) continue;
      const SegmentEnd& spiral = patches_[otherPatch(curve)].segment.ends[k];
      return {kSpiralPoint, spiral.robotVertex, spiral.vertex, spiral.edge[0], spiral.edge[1], 0, 0};
    }
    // Only EF keys (kinds 0 and 1, six entries) name a range end's function.
    const auto& key = angle.function() ? angle.function()->key() : std::nullopt;
    if (cause.rangeEnd[other] && key && (*key)[0] <= 1) {
      return {kHorizontalEdge, (*key)[0], (*key)[1], (*key)[2], (*key)[3], (*key)[4], (*key)[5]};
    }
    return {};
  }

  /// At a vertex of three crossing patches, the patch's curves with the other two
  /// swap. At a vertex on an overlap the crossing patch's two curves swap, and on
  /// each of the two coincident patches only its curve with the crossing patch takes
  /// part.
  void addVertex(const PatchVertex& vertex, std::uint32_t index) {
    const bool onParallelPatch = vertex.crossing >= 0 && vertex.patches[vertex.crossing] != patch_;
    for (std::uint32_t other : vertex.patches) {
      if (other == patch_) continue;
      if (onParallelPatch && other != vertex.patches[vertex.crossing]) continue;
      events_.push_back({vertex.angle, curveWith_.at(other), false, {}, {kVertexPoint, index, 0, 0, 0, 0, 0}});
    }
  }

  void addOverlap(const PatchOverlap& overlap) {
    const int side = overlap.patches[0] == patch_ ? 0 : 1;
    events_.push_back({overlap.angle, kNoCurve, true, overlap.reachesEnd[side], {}});
  }

  PatchSubdivision run() {
    tabulateEndForms();
    const AngleSet& range = patches_[patch_].patch.range;
    if (range.fullCircle) {
      sweepCircle();
    } else {
      for (const AngleInterval& arc : range.arcs) sweepArc(arc);
    }
    return finish();
  }

  /// The slices recorded at the events (after run, with `recordEvents`).
  std::vector<PatchEventSlice> takeEventSlices() { return std::move(eventSlices_); }

 private:
  /// Sorts events counterclockwise from `origin` and merges equal angles.
  std::vector<EventGroup> groupFrom(const AlgebraicAngle& origin, const std::vector<PatchEvent>& events) {
    // Events before the origin come a turn later; each is compared with it once, and
    // indices are sorted rather than the events.
    std::vector<bool> wraps(events.size());
    std::vector<std::size_t> order(events.size());
    for (std::size_t i = 0; i < events.size(); ++i) {
      wraps[i] = algebra_.compare(events[i].angle, origin) < 0;
      order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (wraps[a] != wraps[b]) return static_cast<bool>(wraps[b]);
      return algebra_.compare(events[a].angle, events[b].angle) < 0;
    });
    std::vector<EventGroup> groups;
    for (std::size_t index : order) {
      const PatchEvent& event = events[index];
      if (groups.empty() || algebra_.compare(groups.back().angle, event.angle) != 0) {
        groups.push_back({event.angle, {}, {}, {}, false, {}, {}, {}});
      }
      EventGroup& group = groups.back();
      if (event.curve != kNoCurve) {
        group.curves.push_back(event.curve);
        group.curveOnSide.push_back(event.onSide);
        group.curvePoint.push_back(event.point);
        if (event.arcEnd == ArcEnd::Start) group.starting.push_back(event.curve);
        if (event.arcEnd == ArcEnd::End) group.ending.push_back(event.curve);
      }
      group.cut = group.cut || event.cut;
      group.onSide[0] = group.onSide[0] || event.onSide[0];
      group.onSide[1] = group.onSide[1] || event.onSide[1];
    }
    return groups;
  }

  void sweepArc(const AngleInterval& arc) {
    std::vector<PatchEvent> inside{{arc.from, kNoCurve, false, {}, {}}, {arc.to, kNoCurve, false, {}, {}}};
    for (const PatchEvent& event : events_) {
      if (algebra_.contains(arc, event.angle)) inside.push_back(event);
    }
    const std::vector<EventGroup> groups = groupFrom(arc.from, inside);
    const std::size_t first = subdivision_.slabs.size();
    subdivision_.slabs.reserve(first + groups.size() - 1);
    for (std::size_t k = 0; k + 1 < groups.size(); ++k) {
      const AlgebraicAngle sample = algebra_.rationalBetween(groups[k].angle, groups[k + 1].angle);
      addSlab(groups[k].angle, groups[k + 1].angle, sample, k == 0 ? curvesAt(sample) : curvesAfter(groups[k]));
    }
    for (std::size_t k = 1; k + 1 < groups.size(); ++k) join(first + k - 1, first + k, groups[k]);
  }

  void sweepCircle() {
    if (events_.empty()) {
      const AlgebraicAngle anywhere = AlgebraicAngle::rational(0, 0.0);
      addSlab(anywhere, anywhere, anywhere, curvesAt(anywhere));
      return;
    }
    AlgebraicAngle origin = events_.front().angle;
    for (const PatchEvent& event : events_) {
      if (algebra_.compare(event.angle, origin) < 0) origin = event.angle;
    }
    const std::vector<EventGroup> groups = groupFrom(origin, events_);
    const std::size_t count = groups.size();
    subdivision_.slabs.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
      const AlgebraicAngle& from = groups[k].angle;
      const AlgebraicAngle& to = groups[(k + 1) % count].angle;
      // A single event: the slab runs once around, from it back to it; the rational
      // angle opposite it (t = 0 of the other chart) lies inside.
      const AlgebraicAngle sample =
          count == 1 ? AlgebraicAngle::rational(1 - from.chart(), 0.0) : algebra_.rationalBetween(from, to);
      addSlab(from, to, sample, k == 0 ? curvesAt(sample) : curvesAfter(groups[k]));
    }
    for (std::size_t k = 0; k < count; ++k) join(k, (k + 1) % count, groups[(k + 1) % count]);
  }

  /// The patch's curves at an angle (the first slab of a sweep).
  std::vector<std::uint32_t> curvesAt(const AlgebraicAngle& angle) {
    std::vector<std::uint32_t> curves;
    for (std::uint32_t curve : curvesOfPatch_) {
      if (algebra_.contains(curves_[curve].angles, angle)) curves.push_back(curve);
    }
    return curves;
  }

  /// The curves of the slab after the last one, across the events of `group`: a
  /// curve's presence changes only where one of its arcs starts or ends (a curve's
  /// arcs have length and are apart, as closures of open sets, AngleAlgebra), so they
  /// are the last slab's less those ending there, with those starting there. The
  /// last slab's order along the segment is kept (nearly sorted for the next slab,
  /// whose few crossings std::sort then orders by insertion).
  std::vector<std::uint32_t> curvesAfter(const EventGroup& group) const {
    const std::vector<std::uint32_t>& last = subdivision_.slabs.back().curves;
    std::vector<std::uint32_t> curves;
    curves.reserve(last.size() + group.starting.size());
    for (std::uint32_t curve : last) {
      if (std::find(group.ending.begin(), group.ending.end(), curve) == group.ending.end()) curves.push_back(curve);
    }
    curves.insert(curves.end(), group.starting.begin(), group.starting.end());
    return curves;
  }

  /// A slab from `from` to `to` crossed by `curves` (in any order).
  void addSlab(const AlgebraicAngle& from, const AlgebraicAngle& to, const AlgebraicAngle& sample,
               std::vector<std::uint32_t> curves) {
    PatchSlab slab{from, to, sample, std::move(curves), {}};
    // Crossings apart in double intervals are ordered by them, the others exactly.
    std::vector<Crossing> crossings = crossingsAt(sample, slab.curves);
    std::sort(crossings.begin(), crossings.end(), [&](const Crossing& a, const Crossing& b) {
      if (const int apart = certainOrder(a.lambda, b.lambda)) return apart > 0;
      const Sign order = crossingOrder(patches_[patch_], other(a.curve), other(b.curve), sample, algebra_);
      if (order == Sign::Zero) fail("two curves cross the segment at one point", sample, {a.curve, b.curve});
      return order == Sign::Positive;
    });
    for (std::size_t i = 0; i < crossings.size(); ++i) slab.curves[i] = crossings[i].curve;
    for (std::size_t gap = 0; gap <= slab.curves.size(); ++gap) slab.faces.push_back(trapezoids_.add());
    subdivision_.slabs.push_back(std::move(slab));
  }

  const PatchGeometry& other(std::uint32_t curve) const { return patches_[otherPatch(curve)]; }

  /// A curve with lambda of its other patch at an angle, in double intervals.
  struct Crossing {
    std::uint32_t curve;
    std::optional<IntervalLambda> lambda;
  };

  std::vector<Crossing> crossingsAt(const AlgebraicAngle& angle, const std::vector<std::uint32_t>& curves) const {
    std::vector<Crossing> crossings;
    crossings.reserve(curves.size());
    RoundingScope rounding;
    const auto [cosine, sine] = cosSinEnclosure(angle);
    for (std::uint32_t curve : curves) crossings.push_back({curve, crossingLambda(endForms_->at(curve), cosine, sine)});
    return crossings;
  }

  /// The EndForms of every curve's other patch, once per sweep.
  void tabulateEndForms() {
    std::vector<std::uint32_t> curves = curvesOfPatch_;
    std::sort(curves.begin(), curves.end());
    endForms_.emplace(curves);
    RoundingScope rounding;
    const std::array<Spiral<Interval>, 2> ends = endSpirals<Interval>(patches_[patch_]);
    for (std::uint32_t curve : curves) (*endForms_)[curve] = lineFormsAtEnds(ends, other(curve));
  }

  std::uint32_t otherPatch(std::uint32_t curve) const { return curves_[curve].other(patch_); }

  [[noreturn]] void fail(const std::string& problem, const AlgebraicAngle& angle,
                         const std::vector<std::uint32_t>& curves) const {
    std::ostringstream message;
    message << "patchSubdivisions: on patch " << patch_ << " at theta " << angle.radians() << ", " << problem
            << " (curves with patches";
    for (std::uint32_t curve : curves) message << ' ' << otherPatch(curve);
    message << ')';
    throw std::logic_error(message.str());
  }

  /// Joins the trapezoids of slab `left` to those of the next slab `right` across
  /// the events of `group` (see patchSubdivisions).
  void join(std::size_t left, std::size_t right, const EventGroup& group) {
    if (group.cut) {
      joinAcrossCut(left, right, group);
    } else {
      joinAtPoints(left, right, group);
    }
  }

  /// Across events at points: a trapezoid of one slab continues in a trapezoid of
  /// the other when their sides at the event's angle share an open piece of the
  /// segment. The sides are intervals between the crossings of consecutive curves
  /// there, ranked exactly along the segment (the event's curves meet in points,
  /// several curves in one point, and a group may hold several points).
  void joinAtPoints(std::size_t left, std::size_t right, const EventGroup& group) {
    const PatchSlab &l = subdivision_.slabs[left], &r = subdivision_.slabs[right];
    const auto [rank, last] = ranksAt(group, l.curves, r.curves);
    if (recordEvents_) record(left, right, group.angle, rank, last);
    // Each slab's curves must meet the event's angle in their order, and the curves
    // not at the event in the same order on both sides (else an event is missing).
    for (const std::vector<std::uint32_t>* curves : {&l.curves, &r.curves}) {
      for (std::size_t i = 1; i < curves->size(); ++i) {
        if (rank.at((*curves)[i - 1]) > rank.at((*curves)[i])) {
          fail("curves meet the event's angle out of their order", group.angle, {(*curves)[i - 1], (*curves)[i]});
        }
      }
    }
    if (involvedBlock(l.curves, group.curves).others != involvedBlock(r.curves, group.curves).others) {
      fail("curves not at the event change order", group.angle, group.curves);
    }
    const auto side = [&](const std::vector<std::uint32_t>& curves, std::size_t gap) {
      return std::make_pair(gap == 0 ? 0 : rank.at(curves[gap - 1]), gap == curves.size() ? last : rank.at(curves[gap]));
    };
    for (std::size_t i = 0, j = 0; i < l.faces.size() && j < r.faces.size();) {
      const auto [lowL, highL] = side(l.curves, i);
      const auto [lowR, highR] = side(r.curves, j);
      if (std::max(lowL, lowR) < std::min(highL, highR)) trapezoids_.join(l.faces[i], r.faces[j]);
      if (highL < highR) {
        ++i;
      } else if (highR < highL) {
        ++j;
      } else {
        ++i, ++j;
      }
    }
  }

  void record(std::size_t left, std::size_t right, const AlgebraicAngle& angle, const CurveTable<int>& rank,
              int last) {
    PatchEventSlice slice{angle, left, right, {}, {}, last};
    for (std::uint32_t curve : subdivision_.slabs[left].curves) slice.ranksBefore.push_back(rank.at(curve));
    for (std::uint32_t curve : subdivision_.slabs[right].curves) slice.ranksAfter.push_back(rank.at(curve));
    eventSlices_.push_back(std::move(slice));
  }

  /// The ranks along the segment, at the group's angle, of the crossings of the
  /// curves of two slabs: 0 for end 0 and the curves that reach it, 1, 2, ... for the
  /// distinct interior points, and one more than the last of them for end 1 and the
  /// curves that reach it. Returns the ranks and the rank of end 1.
  std::pair<CurveTable<int>, int> ranksAt(const EventGroup& group, const std::vector<std::uint32_t>& left,
                                          const std::vector<std::uint32_t>& right) {
    const std::vector<std::uint32_t> all = unionOf(left, right);
    CurveTable<int> rank(all);
    CurveTable<std::size_t> placeBefore(all);
    for (std::size_t i = 0; i < left.size(); ++i) placeBefore[left[i]] = i;
    std::vector<std::uint32_t> atEnd1;
    std::vector<InteriorCurve> interior;
    for (std::uint32_t curve : all) {
      const auto event = std::find(group.curves.begin(), group.curves.end(), curve);
      const bool involved = event != group.curves.end();
      const std::size_t at = static_cast<std::size_t>(event - group.curves.begin());
      const std::array<bool, 2> onSide = involved ? group.curveOnSide[at] : std::array<bool, 2>{};
      if (onSide[0]) {
        rank[curve] = 0;
      } else if (onSide[1]) {
        atEnd1.push_back(curve);
      } else if (involved) {
        interior.push_back({curve, group.curvePoint[at], std::nullopt});
      } else {
        // Not at the event: in both slabs, in one order (checked by joinAtPoints).
        interior.push_back({curve, PointKey{}, placeBefore.at(curve)});
      }
    }
    if (interior.empty()) return finishRanks(std::move(rank), {}, atEnd1);
    const InteriorOrder sorted = sortedAlong(group, interior);
    return finishRanks(std::move(rank), sorted.curves, atEnd1, sorted.distinctFromPrevious);
  }

  /// A curve crossing the segment inside at an event: its named point when it is at
  /// the event, its place in the slab before when it is not.
  struct InteriorCurve {
    std::uint32_t curve;
    PointKey point;
    std::optional<std::size_t> placeBefore;
  };

  /// Interior curves by increasing lambda, each marked where its point differs from
  /// the previous one's.
  struct InteriorOrder {
    std::vector<std::uint32_t> curves;
    std::vector<int> distinctFromPrevious;
  };

  /// An interior curve with lambda in double intervals and the sign of its
  /// denominator.
  struct InteriorCrossing {
    InteriorCurve curve;
    std::optional<IntervalLambda> lambda;
    Sign denominator = Sign::Zero;
  };

  InteriorOrder sortedAlong(const EventGroup& group, const std::vector<InteriorCurve>& interior) {
    // Every predicate below is at the event's angle: refined once.
    const AlgebraicAngle at = group.angle.narrowed();
    std::vector<std::uint32_t> curves;
    for (const InteriorCurve& curve : interior) curves.push_back(curve.curve);
    std::vector<Crossing> lambdas = crossingsAt(at, curves);
    std::vector<InteriorCrossing> crossings;
    crossings.reserve(interior.size());
    for (std::size_t i = 0; i < interior.size(); ++i) {
      // A lambda in intervals comes with its denominator's sign; else it is found exactly.
      const Sign denominator = lambdas[i].lambda ? lambdas[i].lambda->denominator
                                                 : algebra_.signAt(endValueDifference(patches_[patch_], other(curves[i])), at);
      if (denominator == Sign::Zero) fail("a curve's line is parallel to the segment", group.angle, {curves[i]});
      crossings.push_back({interior[i], lambdas[i].lambda, denominator});
    }
    // Crossings too close for double intervals: ordered in double-doubles at the
    // angle's certified parameter (found once), else exactly.
    std::optional<std::optional<EndsAtAngle<DoubleDoubleInterval>>> endsAtEvent;
    const auto closeOrder = [&](std::uint32_t g, Sign gDenominator, std::uint32_t h, Sign hDenominator) {
      if (!endsAtEvent) endsAtEvent = endsInDoubleDoubles(patches_[patch_], at);
      if (*endsAtEvent) {
        if (const auto sign = crossingOrderInDoubleDoubles(**endsAtEvent, other(g), other(h))) {
          algebra_.statistics().recordDecision(PredicateKind::CrossingOrder, static_cast<int>(PrecisionLevel::DoubleDouble));
          return static_cast<int>(*sign);
        }
      }
      const Sign difference = algebra_.signAt(crossingDifference(patches_[patch_], other(g), other(h)), at);
      return static_cast<int>(difference) * static_cast<int>(gDenominator) * static_cast<int>(hDenominator);
    };
    // Exact orders are kept: the sort and the check for equal points below ask for
    // the same pairs again.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> exactOrder;
    // sign(lambda_h - lambda_g) at the event's angle.
    const auto order = [&](const InteriorCrossing& g, const InteriorCrossing& h) {
      // Two curves not at the event cross the segment apart and keep their order: a
      // change (or a common point) would be an event of theirs at this angle.
      if (g.curve.placeBefore && h.curve.placeBefore) return *g.curve.placeBefore < *h.curve.placeBefore ? 1 : -1;
      if (g.curve.point[0] != kUnnamed && g.curve.point == h.curve.point) return 0;
      if (const int apart = certainOrder(g.lambda, h.lambda)) return apart;
      // order(h, g) is -order(g, h): the crossing difference changes sign.
      const bool swapped = h.curve.curve < g.curve.curve;
      const InteriorCrossing& first = swapped ? h : g;
      const InteriorCrossing& second = swapped ? g : h;
      const auto [known, inserted] = exactOrder.try_emplace({first.curve.curve, second.curve.curve}, 0);
      if (inserted) known->second = closeOrder(first.curve.curve, first.denominator, second.curve.curve, second.denominator);
      return swapped ? -known->second : known->second;
    };
    // The curves not at the event keep their slab order; those at it (usually few)
    // are sorted among themselves, and each is placed among the others by bisection.
    const auto before = [&](const InteriorCrossing& g, const InteriorCrossing& h) { return order(g, h) > 0; };
    const auto atEvent = std::stable_partition(crossings.begin(), crossings.end(),
                                               [](const InteriorCrossing& c) { return c.curve.placeBefore.has_value(); });
    std::sort(crossings.begin(), atEvent, before);
    std::sort(atEvent, crossings.end(), before);
    crossings = mergedByBisection(crossings.begin(), atEvent, crossings.end(), before);
    InteriorOrder sorted{{}, std::vector<int>(crossings.size(), 1)};
    for (std::size_t i = 0; i < crossings.size(); ++i) {
      sorted.curves.push_back(crossings[i].curve.curve);
      if (i > 0) sorted.distinctFromPrevious[i] = order(crossings[i - 1], crossings[i]) != 0;
    }
    return sorted;
  }

  /// Ranks 1, 2, ... for the sorted interior curves (a new rank where a curve's
  /// point differs from the previous one's), one more for those at end 1.
  static std::pair<CurveTable<int>, int> finishRanks(CurveTable<int> rank, const std::vector<std::uint32_t>& interior,
                                                     const std::vector<std::uint32_t>& atEnd1,
                                                     const std::vector<int>& distinctFromPrevious = {}) {
    int next = 0;
    for (std::size_t i = 0; i < interior.size(); ++i) {
      if (i == 0 || distinctFromPrevious[i]) ++next;
      rank[interior[i]] = next;
    }
    for (std::uint32_t curve : atEnd1) rank[curve] = next + 1;
    return {std::move(rank), next + 1};
  }

  /// Across an overlap: the curves crossing the cut, and those ending at its ends,
  /// form one block; the trapezoids along the cut are not continued, those beyond
  /// its ends are.
  void joinAcrossCut(std::size_t left, std::size_t right, const EventGroup& group) {
    const PatchSlab &l = subdivision_.slabs[left], &r = subdivision_.slabs[right];
    const InvolvedBlock before = involvedBlock(l.curves, group.curves), after = involvedBlock(r.curves, group.curves);
    if (!before.contiguous || !after.contiguous) fail("the event's curves are not together", group.angle, group.curves);
    if (before.others != after.others) fail("curves not at the event change order", group.angle, group.curves);
    if (!before.start && !after.start) {
      if (group.onSide[0] && group.onSide[1]) return;  // a cut across the whole segment
      for (std::size_t gap = 0; gap < l.faces.size(); ++gap) trapezoids_.join(l.faces[gap], r.faces[gap]);
      return;
    }
    const std::size_t below = before.start ? *before.start : *after.start;
    if (before.start && after.start && *before.start != *after.start) {
      fail("the event's curves are not at one place", group.angle, group.curves);
    }
    if ((group.onSide[0] && below != 0) || (group.onSide[1] && below != before.others.size())) {
      fail("the event reaches a segment end behind other curves", group.angle, group.curves);
    }
    for (std::size_t gap = 0; gap < below; ++gap) trapezoids_.join(l.faces[gap], r.faces[gap]);
    for (std::size_t above = 1; above <= before.others.size() - below; ++above) {
      trapezoids_.join(l.faces[below + before.size + above], r.faces[below + after.size + above]);
    }
    // The trapezoids touching the event's point (or cut) from below and from above.
    if (!group.onSide[0]) trapezoids_.join(l.faces[below], r.faces[below]);
    if (!group.onSide[1]) trapezoids_.join(l.faces[below + before.size], r.faces[below + after.size]);
  }

  PatchSubdivision finish() {
    // Sub-faces numbered in the order their first trapezoids appear.
    std::vector<std::uint32_t> faceOfRoot(trapezoids_.size(), kNoFace);
    std::uint32_t faces = 0;
    for (PatchSlab& slab : subdivision_.slabs) {
      for (std::uint32_t& face : slab.faces) {
        std::uint32_t& numbered = faceOfRoot[trapezoids_.find(face)];
        if (numbered == kNoFace) numbered = faces++;
        face = numbered;
      }
    }
    subdivision_.faceCount = faces;
    return std::move(subdivision_);
  }

  std::uint32_t patch_;
  const std::vector<PatchGeometry>& patches_;
  const std::vector<PatchCurve>& curves_;
  AngleAlgebra& algebra_;
  bool recordEvents_;
  std::vector<std::uint32_t> curvesOfPatch_;
  std::optional<CurveTable<EndForms>> endForms_;
  std::unordered_map<std::uint32_t, std::uint32_t> curveWith_;
  std::vector<PatchEvent> events_;
  UnionFind trapezoids_;
  PatchSubdivision subdivision_;
  std::vector<PatchEventSlice> eventSlices_;
};

/// The sign of value(cosine, sine) at a rational angle: adaptively when its t is a
/// double, exactly otherwise.
template <class Value>
Sign signAtRationalAngle(const AlgebraicAngle& rationalAngle, PredicateKind kind, AngleAlgebra& algebra,
                         const Value& value) {
  if (rationalAngle.lower() == rationalAngle.upper()) {
    const HalfAngle at{rationalAngle.chart(), rationalAngle.lower()};
    return AdaptiveSignEngine(algebra.statistics()).sign(kind, [&](auto type) {
      using T = typename decltype(type)::type;
      T cosine, sine;
      at.cosSin(cosine, sine);
      return value(cosine, sine);
    });
  }
  const auto [cosine, sine] = exactCosSin(rationalAngle);
  {
    RoundingScope rounding;
    if (const std::optional<Sign> sign = certainSign(value(enclosingInterval(cosine), enclosingInterval(sine)))) {
      algebra.statistics().recordDecision(kind, static_cast<int>(PrecisionLevel::DoubleInterval));
      return *sign;
    }
  }
  {
    const auto [ddCosine, ddSine] = doubleDoubleCosSin(DoubleDoubleInterval(rationalAngle.root().lo), rationalAngle.chart());
    const NearestRoundingScope rounding;
    if (const std::optional<Sign> sign = certainSign(value(ddCosine, ddSine))) {
      algebra.statistics().recordDecision(kind, static_cast<int>(PrecisionLevel::DoubleDouble));
      return *sign;
    }
  }
  algebra.statistics().recordDecision(kind, static_cast<int>(PrecisionLevel::Exact));
  return exactSign(value(cosine, sine));
}

}  // namespace

Sign crossingOrder(const PatchGeometry& patch, const PatchGeometry& first, const PatchGeometry& second,
                   const AlgebraicAngle& rationalAngle, AngleAlgebra& algebra) {
  return signAtRationalAngle(rationalAngle, PredicateKind::CrossingOrder, algebra, [&](const auto& cosine, const auto& sine) {
    return crossingOrderValue(patch, first, second, cosine, sine);
  });
}

Sign sideOfEnd(const PatchGeometry& patch, int k, const PatchGeometry& other, const AlgebraicAngle& rationalAngle,
               AngleAlgebra& algebra) {
  return signAtRationalAngle(rationalAngle, PredicateKind::SpiralFacet, algebra, [&](const auto& cosine, const auto& sine) {
    return lineAtEnd(patch, k, other, cosine, sine);
  });
}

namespace {

/// The sweeps of all patches, with their curves, vertices and overlaps added.
std::vector<PatchSweep> sweepsOf(const std::vector<PatchGeometry>& patches, const std::vector<PatchCurve>& curves,
                                 const std::vector<PatchVertex>& vertices, const std::vector<PatchOverlap>& overlaps,
                                 AngleAlgebra& algebra, bool recordEvents) {
  std::vector<PatchSweep> sweeps;
  sweeps.reserve(patches.size());
  for (std::uint32_t patch = 0; patch < patches.size(); ++patch) {
    sweeps.emplace_back(patch, patches, curves, algebra, recordEvents);
  }
  for (std::uint32_t curve = 0; curve < curves.size(); ++curve) {
    sweeps[curves[curve].first].addCurve(curve);
    sweeps[curves[curve].second].addCurve(curve);
  }
  for (std::uint32_t index = 0; index < vertices.size(); ++index) {
    for (std::uint32_t patch : vertices[index].patches) sweeps[patch].addVertex(vertices[index], index);
  }
  for (const PatchOverlap& overlap : overlaps) {
    for (std::uint32_t patch : overlap.patches) sweeps[patch].addOverlap(overlap);
  }
  return sweeps;
}

}  // namespace

std::vector<PatchSubdivision> patchSubdivisions(const std::vector<PatchGeometry>& patches,
                                                const std::vector<PatchCurve>& curves,
                                                const std::vector<PatchVertex>& vertices,
                                                const std::vector<PatchOverlap>& overlaps, AngleAlgebra& algebra,
                                                const Cancellation& cancellation) {
  std::vector<PatchSweep> sweeps = sweepsOf(patches, curves, vertices, overlaps, algebra, false);
  std::vector<PatchSubdivision> subdivisions;
  subdivisions.reserve(patches.size());
  for (PatchSweep& sweep : sweeps) {
    cancellation.check();
    subdivisions.push_back(sweep.run());
  }
  return subdivisions;
}

std::vector<std::vector<PatchEventSlice>> patchEventSlices(const std::vector<PatchGeometry>& patches,
                                                           const std::vector<PatchCurve>& curves,
                                                           const std::vector<PatchVertex>& vertices,
                                                           const std::vector<PatchOverlap>& overlaps,
                                                           AngleAlgebra& algebra) {
  std::vector<std::vector<PatchEventSlice>> slices;
  for (PatchSweep& sweep : sweepsOf(patches, curves, vertices, overlaps, algebra, true)) {
    sweep.run();
    slices.push_back(sweep.takeEventSlices());
  }
  return slices;
}

}  // namespace freespace
