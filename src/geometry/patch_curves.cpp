#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <stdexcept>

#include "angle_bounds.h"
#include "contact_vectors.h"
#include "freespace/geometry/patch_box_index.h"
#include "freespace/geometry/patch_curve.h"
#include "freespace/numbers/trig_linear_function.h"

namespace freespace {

namespace {

bool contains(std::initializer_list<std::uint32_t> set, std::uint32_t vertex) {
  return std::find(set.begin(), set.end(), vertex) != set.end();
}

/// The EF function an SF function equals up to a constant factor, when the
/// spiral's vertex and edge lie in the contact's features so that the translation
/// cancels (docs/design.md section 5: identities from shared input vertices). With d
/// placing vertex v on edge e (e(z) its point at v's height):
///   VF(p, f), robot v on e in f:               n . (R p + d - q0) = (R (p - v)) . n
///   VF(p, f), environment v in f on h from p:  n . (R (p - h(z))) = lambda (R h) . n
///   FV(q, g), robot v in g on e from q:        (R m) . (q - e(z)) = lambda (R m) . e
///   FV(q, g), environment v on h in g:         (R m) . (q - v)
///   EE(a, b), robot v on b:                    -sigma det(R u, b, R (a0 - v))
///   EE(a, b), environment v on a:              -sigma det(R u, b, v - b0)
///   EE(a, b), robot end v of a on h from b's end: a lies in the plane of b and h,
///                                              (R (a1 - a0)) . (b x h) = 0
///   EE(a, b), environment end v of b on h from a's end: likewise with roles swapped
std::optional<AngleFunction::RootKey> spiralFacetKey(const ContactPoints& line, const SegmentEnd& end) {
  const auto& [v0, v1, v2, v3] = line.vertices;
  const std::uint32_t v = end.vertex, e0 = end.edge[0], e1 = end.edge[1];
  switch (line.kind) {
    case ContactKind::VertexFacet:
      if (end.robotVertex && contains({v1, v2, v3}, e0) && contains({v1, v2, v3}, e1)) {
        return detail::edgeFacetKey(true, v0, v, {v1, v2, v3});
      }
      if (!end.robotVertex && contains({v1, v2, v3}, v) && contains({e0, e1}, v0)) {
        return detail::edgeFacetKey(true, e0, e1, {v1, v2, v3});
      }
      return std::nullopt;
    case ContactKind::FacetVertex:
      if (end.robotVertex && contains({v1, v2, v3}, v) && contains({e0, e1}, v0)) {
        return detail::edgeFacetKey(false, e0, e1, {v1, v2, v3});
      }
      if (!end.robotVertex && contains({v1, v2, v3}, e0) && contains({v1, v2, v3}, e1)) {
        return detail::edgeFacetKey(false, v0, v, {v1, v2, v3});
      }
      return std::nullopt;
    case ContactKind::EdgeEdge: break;
  }
  if (end.robotVertex && contains({v2, v3}, e0) && contains({v2, v3}, e1)) return detail::edgeFacetKey(false, v2, v3, {v0, v1, v});
  if (!end.robotVertex && contains({v0, v1}, e0) && contains({v0, v1}, e1)) return detail::edgeFacetKey(true, v0, v1, {v2, v3, v});
  // An end of one edge on an edge sharing an end with the other: the first edge
  // passes through the plane of the two others' edges, and lies in it.
  const auto hinge = [](std::uint32_t a, std::uint32_t b, std::uint32_t f0, std::uint32_t f1) -> std::optional<std::uint32_t> {
    if (a == f0 || a == f1) return b;
    if (b == f0 || b == f1) return a;
    return std::nullopt;
  };
  if (end.robotVertex && contains({v0, v1}, v)) {
    if (const auto apart = hinge(e0, e1, v2, v3)) return detail::edgeFacetKey(true, v0, v1, {v2, v3, *apart});
  }
  if (!end.robotVertex && contains({v2, v3}, v)) {
    if (const auto apart = hinge(e0, e1, v0, v1)) return detail::edgeFacetKey(false, v2, v3, {v0, v1, *apart});
  }
  return std::nullopt;
}

/// Whether two contacts' lines are parallel at every angle: contacts of one facet
/// (shareFacet), or two EE contacts of the same edges (one line). Their segments
/// never cross (they may only overlap where the lines coincide: patchOverlaps).
bool alwaysParallel(const Contact& a, const Contact& b) {
  const bool sameEdges = a.kind == ContactKind::EdgeEdge && b.kind == ContactKind::EdgeEdge && a.robot == b.robot &&
                         a.world == b.world;
  return sameEdges || shareFacet(a, b);
}

bool shareAnEnd(const PatchSegment& a, const PatchSegment& b) {
  for (const SegmentEnd& x : a.ends) {
    for (const SegmentEnd& y : b.ends) {
      if (x == y) return true;
    }
  }
  return false;
}

void appendArcEnds(const AngleSet& set, std::vector<AlgebraicAngle>& angles) {
  for (const AngleInterval& arc : set.arcs) {
    angles.push_back(arc.from);
    angles.push_back(arc.to);
  }
}

/// A patch's line and end spirals in double intervals and its angle ranges in
/// radians, for the quick rejection.
struct IntervalPatch {
  PatchLine<Interval> line;
  std::array<Spiral<Interval>, 2> ends;
  std::vector<detail::RadianRange> angles;
};

IntervalPatch intervalPatch(const PatchGeometry& patch) {
  return {lineOf<Interval>(patch.line),
          {spiralOf<Interval>(patch.ends[0]), spiralOf<Interval>(patch.ends[1])},
          detail::radianRanges(patch.patch.range)};
}

/// The sign of the form over the angles, when certain; else zero.
int certainSignOver(const TrigLinear<Interval>& form, const Interval& cosine, const Interval& sine) {
  const std::optional<Sign> sign = certainSign(valueAt(form, cosine, sine));
  return sign ? static_cast<int>(*sign) : 0;
}

/// The SF forms of a segment pair, which do not depend on the angle: the ends of a
/// on b's line, then the ends of b on a's line.
using PairForms = std::array<TrigLinear<Interval>, 4>;

/// A pair's SF forms, each computed when first asked for (inside a RoundingScope):
/// the quick rejection often needs only the first two.
class LazyPairForms {
 public:
  LazyPairForms(const IntervalPatch& a, const IntervalPatch& b) : a_(a), b_(b) {}

  const TrigLinear<Interval>& operator[](std::size_t k) {
    if (!forms_[k]) forms_[k] = k < 2 ? spiralFacetForm(b_.line, a_.ends[k]) : spiralFacetForm(a_.line, b_.ends[k - 2]);
    return *forms_[k];
  }

  PairForms all() { return {(*this)[0], (*this)[1], (*this)[2], (*this)[3]}; }

 private:
  const IntervalPatch& a_;
  const IntervalPatch& b_;
  std::array<std::optional<TrigLinear<Interval>>, 4> forms_;
};

/// Whether one segment's ends lie strictly on one side of the other's line at every
/// angle whose cosine and sine lie in the given intervals.
bool apartOver(LazyPairForms& forms, const Interval& cosine, const Interval& sine) {
  const auto oneSide = [&](std::size_t first) {
    const int sign = certainSignOver(forms[first], cosine, sine);
    return sign != 0 && sign == certainSignOver(forms[first + 1], cosine, sine);
  };
  return oneSide(0) || oneSide(2);
}

/// Halvings of a common range of angles where the segments are not found apart over
/// it: the enclosures over narrower ranges are tighter.
constexpr int kRangeHalvings = 4;

/// Whether the segments may cross at an angle of [from, to]: not when found apart
/// over it or over each half, halved up to `halvings` times (halves share the cosines
/// and sines of their ends).
bool mayCrossOver(LazyPairForms& forms, const detail::RadianCosSin& from, const detail::RadianCosSin& to,
                  int halvings) {
  const auto [cosine, sine] = detail::cosSinOver(from, to);
  if (apartOver(forms, cosine, sine)) return false;
  if (halvings == 0) return true;
  const auto middle = detail::RadianCosSin::at(from.angle + 0.5 * (to.angle - from.angle));
  return mayCrossOver(forms, from, middle, halvings - 1) || mayCrossOver(forms, middle, to, halvings - 1);
}

/// Nothing when, at every common angle of the two ranges, both ends of one segment
/// lie strictly on one side of the other's line: then the segments never cross
/// (decided in double intervals). Otherwise the pair's SF forms, for the exact work.
std::optional<PairForms> formsIfMayCross(const IntervalPatch& a, const IntervalPatch& b) {
  RoundingScope rounding;
  const std::vector<detail::RadianRange> common = detail::overlap(a.angles, b.angles);
  if (common.empty()) return std::nullopt;
  LazyPairForms forms(a, b);
  for (const auto& [from, to] : common) {
    const auto start = detail::RadianCosSin::at(from), end = detail::RadianCosSin::at(to);
    if (mayCrossOver(forms, start, end, kRangeHalvings)) return forms.all();
  }
  return std::nullopt;
}

bool isRangeEnd(const AngleSet& range, const AlgebraicAngle& angle, AngleAlgebra& algebra) {
  return std::any_of(range.arcs.begin(), range.arcs.end(), [&](const AngleInterval& arc) {
    return algebra.compare(angle, arc.from) == 0 || algebra.compare(angle, arc.to) == 0;
  });
}

/// The key of any SF function: the line's contact kind and input vertices, and the
/// spiral's vertex and edge, which determine the function up to the line's sign
/// (kinds 2 to 7, apart from the EF keys' 0 and 1).
AngleFunction::RootKey spiralLineKey(const ContactPoints& line, const SegmentEnd& end) {
  const std::uint32_t kind = 2 + 2 * static_cast<std::uint32_t>(line.kind) + (end.robotVertex ? 1 : 0);
  const auto& v = line.vertices;
  return {kind, v[0], v[1], v[2], v[3], end.vertex, end.edge[0], end.edge[1], 0};
}

/// spiralOnLine, given the SF form in double intervals when the caller has it
/// (spiralFacetForm of the line's and the spiral's double interval coefficients).
std::shared_ptr<const AngleFunction> spiralOnLine(const ContactPoints& line, const SpiralPoints& end,
                                                  const SegmentEnd& endFeatures,
                                                  const std::optional<TrigLinear<Interval>>& approximateForm) {
  const std::optional<AngleFunction::RootKey> edgeFacet = spiralFacetKey(line, endFeatures);
  if (edgeFacet && detail::namesZeroFunction(*edgeFacet)) {
    // Exactly zero, with no arithmetic that could blur it.
    return std::make_shared<AngleFunction>([](auto type, int) {
      using T = typename decltype(type)::type;
      return Polynomial<T>({T(0)});
    }, edgeFacet);
  }
  const auto form = [line, end](auto type) {
    using T = typename decltype(type)::type;
    return spiralFacetForm(lineOf<T>(line), spiralOf<T>(end));
  };
  const AngleFunction::RootKey key = edgeFacet.value_or(spiralLineKey(line, endFeatures));
  if (approximateForm) return trigLinearFunction(form, key, *approximateForm);
  RoundingScope rounding;
  return trigLinearFunction(form, key, form(NumberType<Interval>{}));
}

}  // namespace

std::shared_ptr<const AngleFunction> spiralOnLine(const ContactPoints& line, const SpiralPoints& end,
                                                  const SegmentEnd& endFeatures) {
  return spiralOnLine(line, end, endFeatures, std::nullopt);
}

namespace {

/// An SF function with its roots (none when it vanishes identically).
struct SideFunction {
  std::shared_ptr<const AngleFunction> function;
  bool zero = false;
  std::vector<AlgebraicAngle> roots;
};

/// The line of patch `line` at end k of patch `owner`'s segment, with its SF form in
/// double intervals.
SideFunction sideFunction(const PatchGeometry& line, const PatchGeometry& owner, int k,
                          const TrigLinear<Interval>& approximateForm, AngleAlgebra& algebra) {
  SideFunction side{spiralOnLine(line.line, owner.ends[k], owner.segment.ends[k], approximateForm), false, {}};
  side.zero = side.function->isIdenticallyZero();
  if (!side.zero) side.roots = algebra.roots(side.function, PredicateKind::SpiralFacet);
  return side;
}

/// The curve of patches `first` (geometry a) and `second` (geometry b): the closure
/// of the set of angles in both ranges where the two segments cross at a point
/// inside both, i.e. each segment's ends lie strictly on opposite sides of the
/// other's line (four SF functions), with the causes of its arcs' ends; for
/// segments that share no end. Empty when their lines coincide. Throws
/// std::logic_error if an arc end has no cause (a bug).
PatchCurve patchCurve(std::uint32_t first, const PatchGeometry& a, std::uint32_t second, const PatchGeometry& b,
                      const PairForms& forms, AngleAlgebra& algebra) {
  PatchCurve curve{first, second, {}, {}};
  // The ends of a on b's line, then the ends of b on a's line.
  std::array<SideFunction, 4> sides;
  const auto inBothRanges = [&](const AlgebraicAngle& angle) {
    return algebra.contains(a.patch.range, angle) && algebra.contains(b.patch.range, angle);
  };
  // A property of the sides' signs can change only where a range ends or a side's
  // SF function vanishes inside both ranges (elsewhere it is false on both sides).
  // At most two roots per side function (a trigonometric line's).
  std::vector<AlgebraicAngle> breakpoints;
  breakpoints.reserve(2 * (a.patch.range.arcs.size() + b.patch.range.arcs.size()) + 4);
  appendArcEnds(a.patch.range, breakpoints);
  appendArcEnds(b.patch.range, breakpoints);
  // Side k: the line of `line` at end `end` of `owner`, its roots where `keep` holds
  // added to `into`; false when it vanishes.
  const auto addSide = [&](int k, const PatchGeometry& line, const PatchGeometry& owner, int end, const auto& keep,
                           std::vector<AlgebraicAngle>& into) {
    sides[k] = sideFunction(line, owner, end, forms[k], algebra);
    for (const AlgebraicAngle& root : sides[k].roots) {
      if (keep(root)) into.push_back(root);
    }
    return !sides[k].zero;
  };
  const auto opposite = [&](const AlgebraicAngle& angle, std::size_t first) {
    const Sign one = algebra.signAt(*sides[first].function, angle);
    return one != Sign::Zero && algebra.signAt(*sides[first + 1].function, angle) == -one;
  };
  if (!addSide(0, b, a, 0, inBothRanges, breakpoints) || !addSide(1, b, a, 1, inBothRanges, breakpoints)) return curve;
  // First a's ends alone: where they are never on opposite sides of b's line in both
  // ranges, the segments never cross and b's ends need not be looked at (about
  // a third of the pairs that reach this test end here).
  const AngleSet aAcross = algebra.closureOver(std::move(breakpoints), [&](const AlgebraicAngle& angle) {
    return inBothRanges(angle) && opposite(angle, 0);
  });
  if (aAcross.empty()) return curve;
  // Then b's ends inside that set: the closure of the set where both properties hold
  // is the closure, over the gaps between aAcross's ends and the roots of b's sides
  // inside it, of the gaps inside aAcross where b's ends are on opposite sides (the
  // first property may fail at single points inside aAcross only, which the closure
  // fills).
  const auto inAAcross = [&](const AlgebraicAngle& angle) { return algebra.contains(aAcross, angle); };
  std::vector<AlgebraicAngle> acrossBreakpoints;
  acrossBreakpoints.reserve(2 * aAcross.arcs.size() + 4);
  appendArcEnds(aAcross, acrossBreakpoints);
  if (!addSide(2, a, b, 0, inAAcross, acrossBreakpoints) || !addSide(3, a, b, 1, inAAcross, acrossBreakpoints)) {
    return curve;
  }
  curve.angles = algebra.closureOver(std::move(acrossBreakpoints), [&](const AlgebraicAngle& angle) {
    return inAAcross(angle) && opposite(angle, 2);
  });
  // Each arc end is where one of the four SF functions vanishes or a range ends:
  // the property above can change nowhere else.
  const auto endAt = [&](const AlgebraicAngle& angle) {
    CurveEnd end;
    for (int k = 0; k < 4; ++k) {
      end.endOnOtherLine[k / 2][k % 2] = algebra.signAt(*sides[k].function, angle) == Sign::Zero;
    }
    end.rangeEnd = {isRangeEnd(a.patch.range, angle, algebra), isRangeEnd(b.patch.range, angle, algebra)};
    if (!end.any()) throw std::logic_error("patchCurve: an arc of a curve ends without a cause");
    return end;
  };
  for (const AngleInterval& arc : curve.angles.arcs) curve.ends.push_back({endAt(arc.from), endAt(arc.to)});
  return curve;
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> candidatePatchPairs(const std::vector<PatchGeometry>& patches) {
  return PatchBoxIndex(patches).meetingPairs();
}

std::vector<PatchCurve> patchCurves(const std::vector<PatchGeometry>& patches, AngleAlgebra& algebra,
                                    const Cancellation& cancellation) {
  return patchCurves(patches, candidatePatchPairs(patches), algebra, cancellation);
}

std::vector<PatchCurve> patchCurves(const std::vector<PatchGeometry>& patches,
                                    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& candidates,
                                    AngleAlgebra& algebra, const Cancellation& cancellation) {
  std::vector<IntervalPatch> approximate;
  approximate.reserve(patches.size());
  {
    RoundingScope rounding;
    for (const PatchGeometry& patch : patches) approximate.push_back(intervalPatch(patch));
  }
  std::vector<PatchCurve> curves;
  for (const auto& [first, second] : candidates) {
    cancellation.check();
    // Segments sharing an end: their lines always meet there (an identity).
    if (shareAnEnd(patches[first].segment, patches[second].segment)) {
      AdaptiveSignEngine(algebra.statistics()).knownIdentity(PredicateKind::SpiralFacet);
      continue;
    }
    if (alwaysParallel(patches[first].patch.contact, patches[second].patch.contact)) {
      AdaptiveSignEngine(algebra.statistics()).knownIdentity(PredicateKind::SpiralFacet);
      continue;
    }
    const std::optional<PairForms> forms = formsIfMayCross(approximate[first], approximate[second]);
    if (!forms) continue;
    PatchCurve curve = patchCurve(first, patches[first], second, patches[second], *forms, algebra);
    if (!curve.angles.empty()) curves.push_back(std::move(curve));
  }
  return curves;
}

}  // namespace freespace
