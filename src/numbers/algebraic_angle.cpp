#include "freespace/numbers/algebraic_angle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

#include "interval_root_isolation.h"
#include "multiprecision_refinement.h"

namespace freespace {

namespace {

constexpr int kDoubleLevel = static_cast<int>(PrecisionLevel::DoubleInterval);
constexpr int kExactLevel = static_cast<int>(PrecisionLevel::Exact);
/// Decisions from a function's double-double coefficients rounded to doubles (tight
/// coefficients, AngleFunction::tight).
constexpr int kTightLevel = static_cast<int>(PrecisionLevel::DoubleDouble);
/// Decisions from roots bisected in 108-bit MPFI.
constexpr int kPreciseLevel = static_cast<int>(PrecisionLevel::Multiprecision);
/// Bisections tried in double intervals before a predicate escalates.
constexpr int kDoubleRefinements = 48;

double lowerDouble(const Rational& value) {
  double near = nearDouble(value);
  if (Rational(near) > value) near = std::nextafter(near, -std::numeric_limits<double>::infinity());
  return near;
}

double upperDouble(const Rational& value) {
  double near = nearDouble(value);
  if (Rational(near) < value) near = std::nextafter(near, std::numeric_limits<double>::infinity());
  return near;
}

/// Bisects an exactly isolated root until its interval is about as narrow as a
/// double enclosure can be, so that later predicates can be decided in doubles
/// (this also works for roots of even multiplicity, where doubles cannot bisect).
void tighten(const RationalPolynomial& squareFree, IsolatingInterval& root) {
  static const Rational kWidth(std::ldexp(1.0, -60));  // exact: a power of two
  while (root.lo != root.hi && root.hi - root.lo > kWidth) bisect(squareFree, root);
}

/// The exact square-free polynomial whose root the angle is: t - t0 for a rational
/// angle.
RationalPolynomial exactPolynomialOf(const AlgebraicAngle& angle) {
  if (angle.isRational()) return RationalPolynomial({-angle.root().lo, Rational(1)});
  return angle.function()->squareFree(angle.chart());
}

/// Refines both enclosures in doubles until `decide` answers, as long as one of
/// them can still be narrowed.
template <class Decide>
auto refineBothUntil(AlgebraicAngle& a, AlgebraicAngle& b, Decide&& decide) -> decltype(decide()) {
  for (int step = 0; step <= kDoubleRefinements; ++step) {
    if (auto answer = decide()) return answer;
    const bool refinedA = a.refineInDoubles();
    const bool refinedB = b.refineInDoubles();
    if (!refinedA && !refinedB) break;
  }
  return std::nullopt;
}

/// Closed-form roots of a quadratic (docs/design.md section 4: EF and SF are degree 2),
/// certified by interval arithmetic. Nothing when any step is uncertain: a leading
/// coefficient or discriminant that may be zero, overlapping roots, or a root that
/// may lie on the chart boundary t = +-1.
std::optional<std::vector<Interval>> quadraticRootsInDoubles(const Polynomial<Interval>& p) {
  const Interval& c0 = p.coefficients()[0];
  const Interval& c1 = p.coefficients()[1];
  const Interval& a = p.coefficients()[2];
  const std::optional<Sign> leading = certainSign(a);
  if (!leading || *leading == Sign::Zero) return std::nullopt;
  const Interval discriminant = c1 * c1 - Interval(4) * a * c0;
  const std::optional<Sign> discriminantSign = certainSign(discriminant);
  if (discriminantSign == Sign::Negative) return std::vector<Interval>{};
  if (discriminantSign != Sign::Positive) return std::nullopt;
  const Interval root = sqrt(discriminant);
  Interval first = (-c1 - root) / (Interval(2) * a), second = (-c1 + root) / (Interval(2) * a);
  if (*leading == Sign::Negative) std::swap(first, second);
  if (!(first.upper() < second.lower())) return std::nullopt;
  std::vector<Interval> roots;
  roots.reserve(2);
  for (const Interval& t : {first, second}) {
    if (t.upper() < -1 || t.lower() > 1) continue;
    if (!(t.lower() > -1 && t.upper() < 1)) return std::nullopt;
    roots.push_back(t);
  }
  return roots;
}

/// The roots of a chart polynomial in [-1, 1] certified in double intervals: the
/// closed form for quadratics (docs/design.md section 4: EF and SF), Descartes bisection
/// otherwise (FFF).
std::optional<std::vector<Interval>> chartRootsInDoubles(const Polynomial<Interval>& p) {
  RoundingScope rounding;
  if (p.size() == 3) {
    if (auto roots = quadraticRootsInDoubles(p)) return roots;
  }
  return detail::isolateRootsInDoubles(p, -1, 1);
}

/// The width in t to which roots are refined when they are isolated.
constexpr double kNarrowRoot = 0x1p-40;

/// The same in double-double intervals, for roots that double intervals cannot
/// isolate (near a chart's end, or too close together); each enclosure bisected in
/// double-doubles to kNarrowRoot, since the doubles that refine roots later may not
/// be able to start (an enclosure may be the whole chart).
std::optional<std::vector<Interval>> chartRootsInDoubleDoubles(const Polynomial<DoubleDoubleInterval>& p) {
  NearestRoundingScope rounding;
  std::optional<std::vector<Interval>> enclosures = detail::isolateRootsInDoubleDoubles(p, -1, 1);
  if (!enclosures) return std::nullopt;
  const auto signAt = [&p](double t) { return certainSign(p.evaluate(DoubleDoubleInterval(t))); };
  for (Interval& enclosure : *enclosures) {
    double low = enclosure.lower(), high = enclosure.upper();
    const std::optional<Sign> atLow = signAt(low);  // certain and not zero: isolated so
    while (high - low > kNarrowRoot) {
      const double middle = 0.5 * (low + high);
      const std::optional<Sign> atMiddle = signAt(middle);
      if (!(middle > low && middle < high) || !atMiddle || *atMiddle == Sign::Zero) break;
      (*atMiddle == *atLow ? low : high) = middle;
    }
    enclosure = Interval(low, high);
  }
  return enclosures;
}

/// The angle's exact isolating interval in the form the exact functions require:
/// an endpoint where the function vanishes (possible for enclosures found in
/// doubles) becomes the exact root.
IsolatingInterval verifiedIsolating(const AlgebraicAngle& angle) {
  const IsolatingInterval root = angle.root();
  if (angle.isRational() || root.lo == root.hi) return root;
  const RationalPolynomial& p = angle.function()->squareFree(angle.chart());
  if (signAt(p, root.lo) == Sign::Zero) return {root.lo, root.lo};
  if (signAt(p, root.hi) == Sign::Zero) return {root.hi, root.hi};
  return root;
}

/// Whether p vanishes at the root of `squareFree` isolated by `root`: exactly when
/// gcd(p, squareFree) has a root in the closed interval, since any root of the gcd
/// there is a root of squareFree there, and that is the isolated one.
bool vanishesAtRoot(const RationalPolynomial& p, const RationalPolynomial& squareFree, const IsolatingInterval& root) {
  const RationalPolynomial common = gcd(p, squareFree);
  if (degree(common) < 1) return false;
  if (signAt(common, root.lo) == Sign::Zero) return true;
  return root.lo != root.hi && countDistinctRoots(sturmSequence(squareFreePart(common)), root.lo, root.hi) > 0;
}

/// The sign of the function at the angle from its double-double polynomial at the
/// angle's parameter refined in double-doubles; nothing when not certain.
std::optional<Sign> signInDoubleDoubles(const AngleFunction& function, const AlgebraicAngle& angle) {
  const std::optional<DoubleDoubleInterval> t = doubleDoubleParameter(angle);
  if (!t) return std::nullopt;
  const Polynomial<DoubleDoubleInterval>& p = function.doubleDouble(angle.chart());
  NearestRoundingScope rounding;
  return certainSign(p.evaluate(*t));
}

/// Whether b - a is certainly positive.
bool certainlyBelow(const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) {
  return certainSign(b - a) == Sign::Positive;
}

/// A rational angle between two angles of one chart, `from` below `to`, from their
/// parameters refined in double-doubles: a double when one lies between, else a
/// double-double.
std::optional<AlgebraicAngle> betweenInDoubleDoubles(const AlgebraicAngle& from, const AlgebraicAngle& to) {
  const std::optional<DoubleDoubleInterval> low = doubleDoubleParameter(from), high = doubleDoubleParameter(to);
  if (!low || !high) return std::nullopt;
  NearestRoundingScope rounding;
  const DoubleDoubleInterval middle = ((*low + *high) * 0.5).midpoint();
  for (const DoubleDoubleInterval& point : {DoubleDoubleInterval(middle.high()), middle}) {
    if (certainlyBelow(*low, point) && certainlyBelow(point, *high)) {
      if (point.low() == 0) return AlgebraicAngle::rational(from.chart(), point.high());
      return AlgebraicAngle::rational(from.chart(), Rational(point.high()) + Rational(point.low()));
    }
  }
  return std::nullopt;
}

/// The MPFI ladder for the sign of f at a root: the level that decided, or nothing.
template <int Step = 0>
std::optional<std::pair<Sign, int>> signAtRootOnLadder(const RationalPolynomial& f,
                                                       const RationalPolynomial& squareFree, IsolatingInterval root) {
  if constexpr (Step == kMultiprecisionLevels) {
    return std::nullopt;
  } else {
    if (const auto sign = detail::signAtRootInPrecision<kMultiprecisionDigits[Step]>(f, squareFree, root)) {
      return std::make_pair(*sign, static_cast<int>(PrecisionLevel::Multiprecision) + Step);
    }
    return signAtRootOnLadder<Step + 1>(f, squareFree, root);
  }
}

/// The MPFI ladder for the order of two distinct roots.
template <int Step = 0>
std::optional<std::pair<int, int>> compareRootsOnLadder(const RationalPolynomial& f, IsolatingInterval a,
                                                        const RationalPolynomial& g, IsolatingInterval b) {
  if constexpr (Step == kMultiprecisionLevels) {
    return std::nullopt;
  } else {
    if (const auto order = detail::compareRootsInPrecision<kMultiprecisionDigits[Step]>(f, a, g, b)) {
      return std::make_pair(*order, static_cast<int>(PrecisionLevel::Multiprecision) + Step);
    }
    return compareRootsOnLadder<Step + 1>(f, a, g, b);
  }
}

/// The sign of p at the angle, certain in double intervals, refining the angle's
/// enclosure as long as that helps.
std::optional<Sign> signInDoubles(const Polynomial<Interval>& p, AlgebraicAngle& angle) {
  for (int step = 0; step <= kDoubleRefinements; ++step) {
    {
      RoundingScope rounding;
      if (const auto sign = certainSign(p.evaluate(Interval(angle.lower(), angle.upper())))) return sign;
    }
    if (!angle.refineInDoubles()) break;
  }
  return std::nullopt;
}

}  // namespace

AngleFunction::AngleFunction(std::array<Polynomial<Interval>, 2> enclosures, std::optional<RootKey> key,
                             std::unique_ptr<const ExactSource> exact)
    : approximate_(std::move(enclosures)), source_(std::move(exact)), key_(key) {}

namespace {

/// Guards what AngleFunctions make or remember on first use (their escalation and
/// memos): the functions of a free space are shared by the threads that query it.
/// Recursive: a value made on first use may need another (the tight coefficients
/// need the double-double ones). Taken on every use of the values past double
/// intervals and of the memos (about 2% of a path query's time on two threads).
std::recursive_mutex& firstUseMutex() {
  static std::recursive_mutex mutex;
  return mutex;
}

}  // namespace

AngleFunction::Escalation& AngleFunction::escalation() const {
  if (!escalation_) escalation_ = std::make_unique<Escalation>();
  return *escalation_;
}

const Polynomial<DoubleDoubleInterval>& AngleFunction::doubleDouble(int chart) const {
  const std::lock_guard lock(firstUseMutex());
  auto& doubleDouble = escalation().doubleDouble[chart];
  if (!doubleDouble) {
    if (source_) {
      std::vector<DoubleDoubleInterval> coefficients;
      for (const Rational& coefficient : exact(chart).coefficients()) coefficients.emplace_back(coefficient);
      doubleDouble = Polynomial<DoubleDoubleInterval>(std::move(coefficients));
    } else {
      doubleDouble = evaluator_->doubleDouble(chart);
    }
  }
  return *doubleDouble;
}

std::optional<DoubleDoubleInterval> AngleFunction::rememberedRoot(int chart, int index) const {
  const std::lock_guard lock(firstUseMutex());
  return escalation_ ? escalation_->doubleDoubleRoots.find(chart, index) : std::nullopt;
}

void AngleFunction::rememberRoot(int chart, int index, const DoubleDoubleInterval& root) const {
  const std::lock_guard lock(firstUseMutex());
  escalation().doubleDoubleRoots.remember(chart, index, root);
}

std::optional<AngleFunction::NarrowEnclosure> AngleFunction::rememberedEnclosure(int chart, int index) const {
  const std::lock_guard lock(firstUseMutex());
  return narrowEnclosures_.find(chart, index);
}

void AngleFunction::rememberEnclosure(int chart, int index, const NarrowEnclosure& enclosure) const {
  const std::lock_guard lock(firstUseMutex());
  // Checked and written under one lock: another thread may be remembering a narrower one.
  const std::optional<NarrowEnclosure> known = narrowEnclosures_.find(chart, index);
  if (known && !(enclosure.upper - enclosure.lower < known->upper - known->lower)) return;
  narrowEnclosures_.remember(chart, index, enclosure);
}

const Polynomial<Interval>& AngleFunction::tight(int chart) const {
  if (source_) return approximate_[chart];  // as narrow as doubles allow
  const std::lock_guard lock(firstUseMutex());
  auto& tight = escalation().tight[chart];
  if (!tight) {
    std::vector<Interval> coefficients;
    for (const DoubleDoubleInterval& coefficient : doubleDouble(chart).coefficients()) {
      coefficients.push_back(enclosingInterval(coefficient));
    }
    tight = Polynomial<Interval>(std::move(coefficients));
  }
  return *tight;
}

const Polynomial<PreciseInterval>& AngleFunction::precise(int chart) const {
  const std::lock_guard lock(firstUseMutex());
  auto& precise = escalation().precise[chart];
  if (!precise) {
    std::vector<PreciseInterval> coefficients;
    for (const DoubleDoubleInterval& coefficient : doubleDouble(chart).coefficients()) {
      coefficients.push_back(enclosingPreciseInterval(coefficient));
    }
    precise = Polynomial<PreciseInterval>(std::move(coefficients));
  }
  return *precise;
}

const RationalPolynomial& AngleFunction::exact(int chart) const {
  const std::lock_guard lock(firstUseMutex());
  auto& exact = escalation().exact[chart];
  if (!exact) exact = trimmed(source_ ? source_->polynomial(chart, approximate_[chart]) : evaluator_->exact(chart));
  return *exact;
}

RationalPolynomial AngleFunction::exactOnce(int chart) const {
  {
    const std::lock_guard lock(firstUseMutex());
    if (escalation_ && escalation_->exact[chart]) return *escalation_->exact[chart];
  }
  return trimmed(source_ ? source_->polynomial(chart, approximate_[chart]) : evaluator_->exact(chart));
}

bool AngleFunction::isIdenticallyZero() const {
  // A coefficient certainly nonzero in double intervals, else in the tight ones
  // (a nonzero function can be as small as the perturbation squared), else exactly.
  const auto certainlyNonzero = [](const Polynomial<Interval>& polynomial) {
    return std::any_of(polynomial.coefficients().begin(), polynomial.coefficients().end(), [](const Interval& c) {
      const std::optional<Sign> sign = certainSign(c);
      return sign && *sign != Sign::Zero;
    });
  };
  if (certainlyNonzero(approximate_[0]) || certainlyNonzero(tight(0))) return false;
  return isZero(exact(0));
}

const RationalPolynomial& AngleFunction::squareFree(int chart) const {
  const std::lock_guard lock(firstUseMutex());
  auto& squareFree = escalation().squareFree[chart];
  if (!squareFree) squareFree = squareFreePart(exact(chart));
  return *squareFree;
}

AlgebraicAngle::AlgebraicAngle(std::shared_ptr<const AngleFunction> function, int chart, double lower, double upper,
                               int index)
    : function_(std::move(function)), chart_(chart), lower_(lower), upper_(upper), index_(index) {}

AlgebraicAngle::AlgebraicAngle(std::shared_ptr<const AngleFunction> function, int chart, const IsolatingInterval& root,
                               int index)
    : function_(std::move(function)),
      chart_(chart),
      exactRoot_(std::make_shared<const IsolatingInterval>(root)),
      lower_(lowerDouble(root.lo)),
      upper_(upperDouble(root.hi)),
      index_(index) {}

IsolatingInterval AlgebraicAngle::root() const {
  if (!exactRoot_) return {Rational(lower_), Rational(upper_)};
  if (exactRoot_->lo == exactRoot_->hi) return *exactRoot_;
  const Rational low(lower_), high(upper_);
  return {low > exactRoot_->lo ? low : exactRoot_->lo, high < exactRoot_->hi ? high : exactRoot_->hi};
}

AlgebraicAngle AlgebraicAngle::rational(int chart, const Rational& t) {
  return AlgebraicAngle(nullptr, chart, IsolatingInterval{t, t});
}

AlgebraicAngle AlgebraicAngle::rational(int chart, double t) { return AlgebraicAngle(nullptr, chart, t, t); }

AlgebraicAngle AlgebraicAngle::rational(const HalfAngle& angle) {
  // Chart 1 does not hold t = +-1: those angles are chart 0's -+1.
  const bool boundary = angle.chart == 1 && std::fabs(angle.t) == 1;
  const int chart = boundary ? 0 : angle.chart;
  return rational(chart, boundary ? -angle.t : angle.t);
}

double AlgebraicAngle::radians() const { return HalfAngle{chart_, 0.5 * (lower_ + upper_)}.radians(); }

bool AlgebraicAngle::knowsSignChange(const Polynomial<Interval>& p) {
  if (signAtLower_ != Sign::Zero) return true;
  const std::optional<Sign> atLower = certainSign(p.evaluate(Interval(lower_)));
  const std::optional<Sign> atUpper = certainSign(p.evaluate(Interval(upper_)));
  // Bisect by sign only across a certain sign change: the enclosure holds one
  // distinct root, and if p changes sign over it that root is the only change. A
  // root of even multiplicity is left to the exact level.
  if (!atLower || !atUpper || *atLower != -*atUpper || *atLower == Sign::Zero) return false;
  signAtLower_ = *atLower;
  return true;
}

const Polynomial<Interval>& AlgebraicAngle::refinedPolynomial() const {
  return tight_ ? function_->tight(chart_) : function_->approximate(chart_);
}

bool AlgebraicAngle::refineInDoubles() {
  if (!function_ || !(lower_ < upper_)) return false;
  const Polynomial<Interval>& p = refinedPolynomial();
  const double width = upper_ - lower_;
  RoundingScope rounding;
  if (!knowsSignChange(p)) return false;
  for (const double fraction : detail::kSplitFractions) {
    const double point = lower_ + fraction * width;  // rounded upward: still a double
    if (!(point > lower_ && point < upper_)) continue;
    const std::optional<Sign> atPoint = certainSign(p.evaluate(Interval(point)));
    if (!atPoint || *atPoint == Sign::Zero) continue;
    (*atPoint == signAtLower_ ? lower_ : upper_) = point;
    return true;
  }
  return false;
}

namespace {

/// Newton's iteration in plain doubles (the coefficients' middles) from the middle of
/// [lower, upper], for a root there; none when it leaves the interval or stalls.
/// Only a guess: the caller certifies it by signs.
std::optional<double> newtonGuess(const Polynomial<Interval>& p, double lower, double upper, double tolerance) {
  constexpr int kSteps = 8;
  const auto& coefficients = p.coefficients();
  double t = 0.5 * (lower + upper);
  for (int step = 0; step < kSteps; ++step) {
    double value = 0, slope = 0;
    for (auto k = coefficients.rbegin(); k != coefficients.rend(); ++k) {
      slope = slope * t + value;
      value = value * t + 0.5 * (k->lower() + k->upper());
    }
    if (slope == 0 || !std::isfinite(value / slope)) return std::nullopt;
    const double next = t - value / slope;
    if (!(next > lower && next < upper)) return std::nullopt;
    const bool converged = std::fabs(next - t) <= tolerance;
    t = next;
    if (converged) return t;
  }
  return std::nullopt;
}

}  // namespace

bool AlgebraicAngle::bracketByNewton(double width) {
  const Polynomial<Interval>& p = refinedPolynomial();
  const std::optional<double> guess = newtonGuess(p, lower_, upper_, width / 16);
  if (!guess) return false;
  RoundingScope rounding;
  if (!knowsSignChange(p)) return false;
  // Certain signs at both ends of a narrow bracket around the guess, opposite as at
  // the enclosure's ends: the enclosure's one root lies inside the bracket.
  const double low = std::max(lower_, *guess - 0.25 * width), high = std::min(upper_, *guess + 0.25 * width);
  const std::optional<Sign> atLow = certainSign(p.evaluate(Interval(low)));
  const std::optional<Sign> atHigh = certainSign(p.evaluate(Interval(high)));
  if (atLow != signAtLower_ || atHigh != -signAtLower_) return false;
  lower_ = low;
  upper_ = high;
  return true;
}

void AlgebraicAngle::refineInDoublesTo(double width) {
  if (!function_ || !(upper_ - lower_ > width)) return;
  // One certified Newton bracket usually replaces some forty bisections.
  bracketByNewton(width);
  while (upper_ - lower_ > width && refineInDoubles()) {
  }
}

std::pair<double, double> AlgebraicAngle::narrowestKnownEnclosure() const {
  if (!function_ || index_ < 0) return {lower_, upper_};
  const std::optional<AngleFunction::NarrowEnclosure> known = function_->rememberedEnclosure(chart_, index_);
  if (!known) return {lower_, upper_};
  // Both enclose the one root of the function in this isolating interval.
  return {std::max(lower_, known->lower), std::min(upper_, known->upper)};
}

void AlgebraicAngle::adoptRememberedEnclosure() {
  if (!function_ || index_ < 0) return;
  const std::optional<AngleFunction::NarrowEnclosure> known = function_->rememberedEnclosure(chart_, index_);
  if (!known || !(known->upper - known->lower < upper_ - lower_)) return;
  // A narrower enclosure of the same root: the function's sign at its lower end is
  // the sign at this one's (both below the root, inside one isolating interval).
  lower_ = known->lower;
  upper_ = known->upper;
  tight_ = tight_ || known->tight;
}

void AlgebraicAngle::rememberEnclosure() const {
  if (!function_ || index_ < 0) return;
  function_->rememberEnclosure(chart_, index_, {lower_, upper_, tight_});
}

AlgebraicAngle AlgebraicAngle::narrowed() const {
  constexpr double kNarrowEnough = 0x1p-40;
  AlgebraicAngle copy = *this;
  // An event's angle is narrowed by the sweep of each patch at it: the first
  // narrowing is remembered by the function for the others.
  copy.adoptRememberedEnclosure();
  for (int pass = 0; pass < 2; ++pass) {
    while (copy.refineInDoubles()) {
    }
    if (!(copy.upper_ - copy.lower_ > kNarrowEnough) || !copy.useTightCoefficients()) break;
  }
  copy.rememberEnclosure();
  return copy;
}

bool AlgebraicAngle::useTightCoefficients() {
  if (!function_ || tight_) return false;
  tight_ = true;
  return true;
}

std::vector<AlgebraicAngle> AngleAlgebra::roots(const std::shared_ptr<const AngleFunction>& function,
                                                PredicateKind kind) {
  std::vector<AlgebraicAngle> angles;
  angles.reserve(4);  // the roots of a trig-linear form (EF, SF) and most others
  // Enclosures from bisection (Descartes' rule) can be as wide as the chart: they
  // are narrowed here once rather than by every comparison.
  const auto addEnclosures = [&](int chart, const std::vector<Interval>& enclosures, bool tight) {
    int index = 0;
    for (const Interval& t : enclosures) {
      angles.emplace_back(function, chart, t.lower(), t.upper(), index++);
      if (tight) angles.back().useTightCoefficients();
      angles.back().refineInDoublesTo(kNarrowRoot);
    }
  };
  for (int chart = 0; chart < 2; ++chart) {
    if (const auto enclosures = chartRootsInDoubles(function->approximate(chart))) {
      statistics_.recordDecision(kind, kDoubleLevel);
      addEnclosures(chart, *enclosures, false);
      continue;
    }
    const EscalationTimer timer(statistics_, kind);
    if (const auto enclosures = chartRootsInDoubles(function->tight(chart))) {
      statistics_.recordDecision(kind, kTightLevel);
      addEnclosures(chart, *enclosures, true);
      continue;
    }
    if (const auto enclosures = chartRootsInDoubleDoubles(function->doubleDouble(chart))) {
      statistics_.recordDecision(kind, kTightLevel);
      addEnclosures(chart, *enclosures, true);
      continue;
    }
    statistics_.recordDecision(kind, kExactLevel);
    const RationalPolynomial& exact = function->exact(chart);
    if (isZero(exact)) throw std::invalid_argument("the angle function vanishes identically");
    int index = 0;
    for (IsolatingInterval root : isolateRoots(exact, Rational(-1), Rational(1))) {
      // Chart 1 leaves t = +-1 to chart 0.
      if (chart == 1 && root.lo == root.hi && abs(root.lo) == 1) continue;
      tighten(function->squareFree(chart), root);
      angles.emplace_back(function, chart, root, index++);
    }
  }
  return angles;
}

Sign AngleAlgebra::signAt(const AngleFunction& function, const AlgebraicAngle& angle) {
  // A root of this function, or of one with the same key (the same roots): zero by
  // construction, a combinatorial identity.
  const AngleFunction* rootOf = angle.function().get();
  if (rootOf == &function || (rootOf && function.key() && rootOf->key() == function.key())) {
    statistics_.recordIdentity(PredicateKind::SignAtRoot);
    return Sign::Zero;
  }
  AlgebraicAngle refined = angle;
  if (const auto sign = signInDoubles(function.approximate(angle.chart()), refined)) {
    return record(PredicateKind::SignAtRoot, kDoubleLevel, *sign);
  }
  // Escalation: tight coefficients, then an exact identity test (after perturbation,
  // most signs that doubles cannot decide are identities), then the MPFI ladder,
  // then exact.
  const EscalationTimer timer(statistics_, PredicateKind::SignAtRoot);
  refined.useTightCoefficients();
  if (const auto sign = signInDoubles(function.tight(angle.chart()), refined)) {
    return record(PredicateKind::SignAtRoot, kTightLevel, *sign);
  }
  if (const auto sign = signInDoubleDoubles(function, refined)) {
    return record(PredicateKind::SignAtRoot, kTightLevel, *sign);
  }
  const RationalPolynomial& exact = function.exact(angle.chart());
  if (angle.isRational())
    return record(PredicateKind::SignAtRoot, kExactLevel, freespace::signAt(exact, angle.root().lo));
  const RationalPolynomial& squareFree = angle.function()->squareFree(angle.chart());
  const IsolatingInterval root = verifiedIsolating(refined);
  if (vanishesAtRoot(exact, squareFree, root)) return record(PredicateKind::SignAtRoot, kExactLevel, Sign::Zero);
  if (const auto decided = signAtRootOnLadder(exact, squareFree, root)) {
    return record(PredicateKind::SignAtRoot, decided->second, decided->first);
  }
  return record(PredicateKind::SignAtRoot, kExactLevel, signAtRoot(exact, squareFree, root));
}

std::optional<int> AngleAlgebra::compareInDoubles(AlgebraicAngle& a, AlgebraicAngle& b) const {
  if (a.chart() != b.chart()) return a.chart() < b.chart() ? -1 : 1;
  return refineBothUntil(a, b, [&a, &b]() -> std::optional<int> {
    if (a.upper() < b.lower()) return -1;
    if (b.upper() < a.lower()) return 1;
    const bool exactDoubles = a.isRational() && b.isRational() && a.lower() == a.upper() && b.lower() == b.upper();
    if (exactDoubles) return a.lower() < b.lower() ? -1 : (a.lower() > b.lower() ? 1 : 0);
    return std::nullopt;
  });
}

std::optional<int> AngleAlgebra::compareByKey(const AlgebraicAngle& a, const AlgebraicAngle& b) {
  if (a.isRational() || b.isRational() || a.chart() != b.chart() || a.index() < 0 || b.index() < 0) return std::nullopt;
  // Roots of one function, or of two with one key, have the same roots.
  const auto& keyA = a.function()->key();
  if (a.function() != b.function() && (!keyA || keyA != b.function()->key())) return std::nullopt;
  // Same roots in the chart, isolated in increasing order: the indices decide.
  if (a.index() == b.index()) statistics_.recordIdentity(PredicateKind::RootOrder);
  return a.index() < b.index() ? -1 : (a.index() > b.index() ? 1 : 0);
}

int AngleAlgebra::compareOverlapping(const AlgebraicAngle& a, const AlgebraicAngle& b) {
  if (const std::optional<int> order = compareByKey(a, b)) return *order;
  // Enclosures that earlier comparisons narrowed (remembered by the functions) are
  // usually apart: that decides before any lookup or copy.
  const auto [aLower, aUpper] = a.narrowestKnownEnclosure();
  const auto [bLower, bUpper] = b.narrowestKnownEnclosure();
  if (aUpper < bLower || bUpper < aLower) {
    const int order = aUpper < bLower ? -1 : 1;
    record(PredicateKind::RootOrder, kDoubleLevel, signOf(order));
    return order;
  }
  // Orders of roots that needed refinement are remembered: sorts ask again.
  const bool remembered = !a.isRational() && !b.isRational() && a.index() >= 0 && b.index() >= 0;
  const RootPair pair{a.function().get(), b.function().get(), a.chart(), a.index(), b.chart(), b.index()};
  if (remembered) {
    const auto known = knownOrders_.find(pair);
    if (known != knownOrders_.end()) return known->second.order;
  }
  AlgebraicAngle first = a, second = b;
  first.adoptRememberedEnclosure();
  second.adoptRememberedEnclosure();
  std::optional<int> order = compareInDoubles(first, second);
  if (order) record(PredicateKind::RootOrder, kDoubleLevel, signOf(*order));
  if (!order) order = compareTightly(first, second);
  first.rememberEnclosure();
  second.rememberEnclosure();
  if (!order) order = compareInDoubleDoubles(first, second);
  if (!order) order = comparePrecisely(first, second);
  if (!order) order = compareEscalated(first, second);
  if (remembered) knownOrders_.emplace(pair, KnownOrder{*order, a.function(), b.function()});
  return *order;
}

std::size_t AngleAlgebra::RootPairHash::operator()(const RootPair& pair) const {
  const std::size_t functions = std::hash<const void*>()(pair.first) * 31 + std::hash<const void*>()(pair.second);
  const auto roots = static_cast<std::size_t>(((pair.firstChart * 64 + pair.firstIndex) * 2 + pair.secondChart) * 64 +
                                              pair.secondIndex);
  return functions * 1000003 + roots;
}

namespace {

/// Bisections of a precise root: from a double enclosure about 56 bits more.
constexpr int kPreciseBisections = 56;

std::optional<detail::PreciseRoot> preciseRootOf(const AlgebraicAngle& angle) {
  if (angle.isRational()) return detail::PreciseRoot::fixed(angle.root().lo, angle.root().hi);
  return detail::PreciseRoot::isolating(angle.function()->precise(angle.chart()), angle.lower(), angle.upper());
}

/// The roots bisected in MPFI until they are apart.
std::optional<std::pair<detail::PreciseRoot, detail::PreciseRoot>> apartPrecisely(const AlgebraicAngle& first,
                                                                                  const AlgebraicAngle& second) {
  std::optional<detail::PreciseRoot> a = preciseRootOf(first), b = preciseRootOf(second);
  if (!a || !b) return std::nullopt;
  for (int step = 0; step < kPreciseBisections; ++step) {
    if (a->below(*b) || b->below(*a)) return std::make_pair(std::move(*a), std::move(*b));
    const bool movedA = !first.isRational() && a->bisect(first.function()->precise(first.chart()));
    const bool movedB = !second.isRational() && b->bisect(second.function()->precise(second.chart()));
    if (!movedA && !movedB) return std::nullopt;
  }
  return std::nullopt;
}

/// A rational angle between two angles of one chart, `from` below `to`, from their
/// roots bisected in MPFI.
std::optional<AlgebraicAngle> betweenPrecisely(const AlgebraicAngle& from, const AlgebraicAngle& to) {
  const auto apart = apartPrecisely(from, to);
  if (!apart || !apart->first.below(apart->second)) return std::nullopt;
  const std::optional<Rational> t = apart->first.pointBelow(apart->second);
  if (!t) return std::nullopt;
  return AlgebraicAngle::rational(from.chart(), *t);
}

}  // namespace

std::optional<int> AngleAlgebra::comparePrecisely(const AlgebraicAngle& first, const AlgebraicAngle& second) {
  const EscalationTimer timer(statistics_, PredicateKind::RootOrder);
  const auto apart = apartPrecisely(first, second);
  if (!apart) return std::nullopt;
  const int order = apart->first.below(apart->second) ? -1 : 1;
  record(PredicateKind::RootOrder, kPreciseLevel, signOf(order));
  return order;
}

std::optional<int> AngleAlgebra::compareInDoubleDoubles(const AlgebraicAngle& first, const AlgebraicAngle& second) {
  const EscalationTimer timer(statistics_, PredicateKind::RootOrder);
  const std::optional<DoubleDoubleInterval> a = doubleDoubleParameter(first), b = doubleDoubleParameter(second);
  if (!a || !b || first.chart() != second.chart()) return std::nullopt;
  NearestRoundingScope rounding;
  if (certainlyBelow(*a, *b)) return static_cast<int>(record(PredicateKind::RootOrder, kTightLevel, Sign::Negative));
  if (certainlyBelow(*b, *a)) return static_cast<int>(record(PredicateKind::RootOrder, kTightLevel, Sign::Positive));
  return std::nullopt;
}

std::optional<int> AngleAlgebra::compareTightly(AlgebraicAngle& first, AlgebraicAngle& second) {
  const bool tightened = first.useTightCoefficients() | second.useTightCoefficients();
  if (!tightened) return std::nullopt;
  const EscalationTimer timer(statistics_, PredicateKind::RootOrder);
  const std::optional<int> order = compareInDoubles(first, second);
  if (order) record(PredicateKind::RootOrder, kTightLevel, signOf(*order));
  return order;
}

int AngleAlgebra::compareEscalated(const AlgebraicAngle& first, const AlgebraicAngle& second) {
  const EscalationTimer timer(statistics_, PredicateKind::RootOrder);
  const RationalPolynomial f = exactPolynomialOf(first), g = exactPolynomialOf(second);
  const IsolatingInterval rootA = verifiedIsolating(first), rootB = verifiedIsolating(second);
  // Escalation as in signAt: equal roots are an exact identity, found first.
  const IsolatingInterval overlap{rootA.lo > rootB.lo ? rootA.lo : rootB.lo, rootA.hi < rootB.hi ? rootA.hi : rootB.hi};
  if (overlap.lo <= overlap.hi && vanishesAtRoot(f, g, overlap)) {
    record(PredicateKind::RootOrder, kExactLevel, Sign::Zero);
    return 0;
  }
  if (const auto decided = compareRootsOnLadder(f, rootA, g, rootB)) {
    record(PredicateKind::RootOrder, decided->second, signOf(decided->first));
    return decided->first;
  }
  const int order = compareRoots(f, rootA, g, rootB);
  record(PredicateKind::RootOrder, kExactLevel, signOf(order));
  return order;
}

bool AngleAlgebra::contains(const AngleInterval& arc, const AlgebraicAngle& angle, Boundary boundary) {
  return contains(arc.from, arc.to, arc.wraps, angle, boundary);
}

bool AngleAlgebra::contains(const AlgebraicAngle& from, const AlgebraicAngle& to, bool wraps,
                            const AlgebraicAngle& angle, Boundary boundary) {
  const int bound = boundary == Boundary::Included ? 0 : -1;
  // The second comparison only when the first does not decide.
  const bool afterFrom = compare(from, angle) <= bound;
  if (afterFrom == wraps) return afterFrom;
  return compare(angle, to) <= bound;
}

bool AngleAlgebra::contains(const AngleSet& set, const AlgebraicAngle& angle, Boundary boundary) {
  if (set.fullCircle) return true;
  for (const AngleInterval& arc : set.arcs) {
    if (contains(arc, angle, boundary)) return true;
  }
  return false;
}

namespace {

/// Position along the circle cut at -pi/2 as one parameter: u = t in chart 0
/// ([-1, 1]) and u = t + 2 in chart 1 ((1, 3)); a full turn adds 4.
constexpr int kTurn = 4;

Rational chartOffset(int chart) { return Rational(chart == 0 ? 0 : 2); }

/// An angle's exact isolating interval in u, with the polynomial that refines it.
struct ExactPosition {
  RationalPolynomial squareFree;
  IsolatingInterval u;
};

ExactPosition exactPosition(const AlgebraicAngle& angle) {
  const IsolatingInterval t = verifiedIsolating(angle);
  return {exactPolynomialOf(angle), {t.lo + chartOffset(angle.chart()), t.hi + chartOffset(angle.chart())}};
}

/// Halves an isolating interval given in u (its polynomial is in t).
void bisectPosition(ExactPosition& position, const Rational& offset) {
  IsolatingInterval t{position.u.lo - offset, position.u.hi - offset};
  bisect(position.squareFree, t);
  position.u = {t.lo + offset, t.hi + offset};
}

/// The rational angle at position u, taken modulo a full turn.
AlgebraicAngle angleAtPosition(Rational u) {
  while (u >= 3) u -= kTurn;
  while (u < -1) u += kTurn;
  return u <= 1 ? AlgebraicAngle::rational(0, u) : AlgebraicAngle::rational(1, u - 2);
}

/// A double strictly between a and b, if there is one.
std::optional<double> midpoint(double a, double b) {
  const double middle = 0.5 * (a + b);
  if (a < middle && middle < b) return middle;
  return std::nullopt;
}

/// A rational angle strictly inside the open arc from `from` to `to`, found from
/// their double enclosures; `wraps` when `to` precedes `from` in the cut order.
std::optional<AlgebraicAngle> betweenInDoubles(const AlgebraicAngle& from, const AlgebraicAngle& to, bool wraps) {
  const auto angle = [](int chart, std::optional<double> t) -> std::optional<AlgebraicAngle> {
    if (!t) return std::nullopt;
    return AlgebraicAngle::rational(chart, *t);
  };
  if (!wraps) {
    if (from.chart() == to.chart()) return angle(from.chart(), midpoint(from.upper(), to.lower()));
    // From chart 0 to chart 1: the end of chart 0 or the start of chart 1.
    if (auto inside = angle(0, midpoint(from.upper(), 1.0))) return inside;
    return angle(1, midpoint(-1.0, to.lower()));
  }
  // Through the cut at theta = -pi/2: the rest of `from`'s chart, then the start of
  // `to`'s, or a whole chart the arc passes through.
  if (from.chart() == 1) {
    if (auto inside = angle(1, midpoint(from.upper(), 1.0))) return inside;
  }
  if (to.chart() == 0) {
    if (auto inside = angle(0, midpoint(-1.0, to.lower()))) return inside;
  }
  if (from.chart() == to.chart()) return AlgebraicAngle::rational(1 - from.chart(), 0.0);
  return std::nullopt;
}

/// Newton's iteration in double-doubles from the middle of the angle's enclosure,
/// certified by a sign change around the result inside the enclosure.
std::optional<DoubleDoubleInterval> newtonInDoubleDoubles(const AlgebraicAngle& angle) {
  constexpr int kNewtonSteps = 6;
  const Polynomial<DoubleDoubleInterval>& p = angle.function()->doubleDouble(angle.chart());
  const Polynomial<DoubleDoubleInterval> slope = p.derivative();
  NearestRoundingScope rounding;
  const DoubleDoubleInterval lower(angle.lower()), upper(angle.upper());
  DoubleDoubleInterval t = DoubleDoubleInterval(0.5 * angle.lower() + 0.5 * angle.upper());
  for (int step = 0; step < kNewtonSteps; ++step) {
    const DoubleDoubleInterval derivative = slope.evaluate(t);
    const std::optional<Sign> derivativeSign = certainSign(derivative);
    if (!derivativeSign || *derivativeSign == Sign::Zero) return std::nullopt;
    t = (t - p.evaluate(t).midpoint() / derivative.midpoint()).midpoint();
  }
  // Certified: certain opposite signs at t - delta and t + delta, both inside the
  // isolating enclosure, so the enclosure's one root lies between.
  const auto below = [](const DoubleDoubleInterval& a, const DoubleDoubleInterval& b) {
    return certainSign(b - a) == Sign::Positive;
  };
  for (double delta = 0x1p-100; delta <= 0x1p-80; delta *= 4) {
    const DoubleDoubleInterval low = (t - delta).midpoint(), high = (t + delta).midpoint();
    if (!below(lower, low) || !below(high, upper)) return std::nullopt;
    const std::optional<Sign> atLow = certainSign(p.evaluate(low)), atHigh = certainSign(p.evaluate(high));
    if (atLow && atHigh && *atLow != Sign::Zero && *atLow == -*atHigh) return t.widened(2 * delta);
  }
  return std::nullopt;
}

/// Bisection in double-doubles of the angle's enclosure, for roots where Newton's
/// iteration cannot run (the derivative's sign is not certain: another root lies
/// near): halves while the sign at the middle is certain, to about 2^-100 at most.
std::optional<DoubleDoubleInterval> bisectInDoubleDoubles(const AlgebraicAngle& angle) {
  constexpr int kBisections = 120;
  constexpr double kWidth = 0x1p-100;
  const Polynomial<DoubleDoubleInterval>& p = angle.function()->doubleDouble(angle.chart());
  NearestRoundingScope rounding;
  DoubleDoubleInterval low(angle.lower()), high(angle.upper());
  const std::optional<Sign> atLow = certainSign(p.evaluate(low)), atHigh = certainSign(p.evaluate(high));
  if (!atLow || !atHigh || *atLow == Sign::Zero || *atLow != -*atHigh) return std::nullopt;
  for (int step = 0; step < kBisections; ++step) {
    const DoubleDoubleInterval width = high - low;
    if (width.high() + width.radius() <= kWidth) break;
    const DoubleDoubleInterval middle = ((low + high) * DoubleDoubleInterval(0.5)).midpoint();
    const std::optional<Sign> sign = certainSign(p.evaluate(middle));
    if (!sign) break;
    if (*sign == Sign::Zero) return middle;
    (*sign == *atLow ? low : high) = middle;
  }
  // The root lies in [low, high]: their middle, widened by half their distance.
  const DoubleDoubleInterval width = high - low;
  return ((low + high) * DoubleDoubleInterval(0.5))
      .widened(0.5 * (std::fabs(width.high()) + std::fabs(width.low()) + width.radius()));
}

}  // namespace

std::optional<DoubleDoubleInterval> doubleDoubleParameter(const AlgebraicAngle& angle) {
  if (angle.isRational()) {
    if (angle.lower() == angle.upper()) return DoubleDoubleInterval(angle.lower());
    return DoubleDoubleInterval(angle.root().lo);
  }
  const AngleFunction& function = *angle.function();
  if (angle.index() >= 0) {
    if (const std::optional<DoubleDoubleInterval> known = function.rememberedRoot(angle.chart(), angle.index())) {
      return known;
    }
  }
  std::optional<DoubleDoubleInterval> root = newtonInDoubleDoubles(angle);
  if (!root) root = bisectInDoubleDoubles(angle);
  if (root && angle.index() >= 0) function.rememberRoot(angle.chart(), angle.index(), *root);
  return root;
}

std::pair<DoubleDoubleInterval, DoubleDoubleInterval> doubleDoubleCosSin(const DoubleDoubleInterval& t, int chart) {
  const NearestRoundingScope rounding;
  const DoubleDoubleInterval w = DoubleDoubleInterval(1.0) + t * t;
  const DoubleDoubleInterval chartSign(chart == 0 ? 1.0 : -1.0);
  return {chartSign * (DoubleDoubleInterval(1.0) - t * t) / w, chartSign * (t + t) / w};
}

namespace {

/// t^2 as an interval of non-negative numbers (t * t, for an interval t holding 0,
/// would take its ends as independent and reach below 0).
Interval squareOf(const Interval& t) {
  if (t.lower() >= 0 || t.upper() <= 0) return t * t;
  const double reach = std::max(-t.lower(), t.upper());
  return Interval(0, (Interval(reach) * Interval(reach)).upper());
}

}  // namespace

std::pair<Interval, Interval> cosSinEnclosure(const AlgebraicAngle& angle) {
  Interval cosine, sine;
  if (angle.lower() == angle.upper()) {
    HalfAngle{angle.chart(), angle.lower()}.cosSin(cosine, sine);
  } else if (angle.isRational()) {
    const auto [c, s] = exactCosSin(angle);
    cosine = enclosingInterval(c);
    sine = enclosingInterval(s);
  } else {
    const Interval t(angle.lower(), angle.upper()), square = squareOf(t), w = Interval(1) + square;
    const Interval chartSign(angle.chart() == 0 ? 1.0 : -1.0);
    cosine = chartSign * (Interval(1) - square) / w;
    sine = chartSign * (t + t) / w;
  }
  return {cosine, sine};
}

std::pair<Rational, Rational> exactCosSin(const AlgebraicAngle& rationalAngle) {
  const Rational t = rationalAngle.root().lo, w = 1 + t * t, chartSign(rationalAngle.chart() == 0 ? 1 : -1);
  return {chartSign * (1 - t * t) / w, chartSign * 2 * t / w};
}

AlgebraicAngle AngleAlgebra::rationalBetween(const AlgebraicAngle& from, const AlgebraicAngle& to) {
  const int order = compare(from, to);
  if (order == 0) throw std::invalid_argument("rationalBetween: the two angles are equal");
  AlgebraicAngle narrowFrom = from, narrowTo = to;
  const auto between = [&] { return betweenInDoubles(narrowFrom, narrowTo, order > 0); };
  if (auto inside = between()) return *inside;
  // Close angles: refined from the narrowest enclosures known for them.
  narrowFrom.adoptRememberedEnclosure();
  narrowTo.adoptRememberedEnclosure();
  if (auto inside = refineBothUntil(narrowFrom, narrowTo, between)) return *inside;
  if (narrowFrom.useTightCoefficients() | narrowTo.useTightCoefficients()) {
    if (auto inside = refineBothUntil(narrowFrom, narrowTo, between)) return *inside;
  }
  if (order < 0 && from.chart() == to.chart()) {
    if (auto inside = betweenInDoubleDoubles(narrowFrom, narrowTo)) return *inside;
    if (auto inside = betweenPrecisely(narrowFrom, narrowTo)) return *inside;
  }
  // Going counterclockwise from `from`, `to` comes a full turn later when it
  // precedes `from` in the cut order.
  const Rational turn(order < 0 ? 0 : kTurn);
  ExactPosition start = exactPosition(from), end = exactPosition(to);
  while (!(start.u.hi < end.u.lo + turn)) {
    bisectPosition(start, chartOffset(from.chart()));
    bisectPosition(end, chartOffset(to.chart()));
  }
  return angleAtPosition((start.u.hi + end.u.lo + turn) / 2);
}

AlgebraicAngle AngleAlgebra::rationalNextTo(const AlgebraicAngle& angle, const AlgebraicAngle& bound, bool before,
                                            int bits) {
  if (compare(angle, bound) == 0) throw std::invalid_argument("rationalNextTo: the bound is the angle");
  const bool boundWraps = before ? compare(bound, angle) > 0 : compare(angle, bound) > 0;
  const AngleInterval between =
      before ? AngleInterval{bound, angle, boundWraps} : AngleInterval{angle, bound, boundWraps};
  ExactPosition position = exactPosition(angle);
  for (Rational gap = powerOfHalf(static_cast<unsigned>(bits));; gap /= 2) {
    while (position.u.hi - position.u.lo >= gap / 2) bisectPosition(position, chartOffset(angle.chart()));
    // The root is in [lo, hi], narrower than gap / 2: a step of gap / 2 past the
    // near end is less than gap from it and not on it.
    const AlgebraicAngle next =
        angleAtPosition(before ? Rational(position.u.lo - gap / 2) : Rational(position.u.hi + gap / 2));
    if (contains(between, next, Boundary::Excluded)) return next;
  }
}

AngleSet AngleAlgebra::positiveSet(const std::vector<std::shared_ptr<const AngleFunction>>& functions,
                                   PredicateKind kind) {
  return signPatternSets(functions, std::vector<Sign>(functions.size(), Sign::Positive), kind)[0];
}

std::array<AngleSet, 2> AngleAlgebra::signPatternSets(
    const std::vector<std::shared_ptr<const AngleFunction>>& functions, const std::vector<Sign>& pattern,
    PredicateKind kind) {
  // A function that vanishes identically has no sign anywhere.
  for (const auto& function : functions) {
    if (function->isIdenticallyZero()) return {};
  }
  std::vector<AlgebraicAngle> breakpoints;
  breakpoints.reserve(2 * functions.size());  // two roots each for trigonometric lines
  for (const auto& function : functions) {
    for (const AlgebraicAngle& root : this->roots(function, kind)) breakpoints.push_back(root);
  }
  const std::vector<AngleSet> sets = closuresOver(std::move(breakpoints), 2, [&](const AlgebraicAngle& angle) {
    bool same = true, opposite = true;
    for (std::size_t k = 0; k < functions.size() && (same || opposite); ++k) {
      const Sign sign = signAt(*functions[k], angle);
      same = same && sign == pattern[k];
      opposite = opposite && sign == -pattern[k];
    }
    return (same ? 1u : 0u) | (opposite ? 2u : 0u);
  });
  return {sets[0], sets[1]};
}

AngleSet AngleAlgebra::closureWhere(const std::vector<std::shared_ptr<const AngleFunction>>& functions,
                                    std::vector<AlgebraicAngle> breakpoints,
                                    const std::function<bool(const AlgebraicAngle&)>& holds, PredicateKind kind) {
  for (const auto& function : functions) {
    for (const AlgebraicAngle& root : this->roots(function, kind)) breakpoints.push_back(root);
  }
  return closureOver(std::move(breakpoints), holds);
}

AngleSet AngleAlgebra::closureOver(std::vector<AlgebraicAngle> breakpoints,
                                   const std::function<bool(const AlgebraicAngle&)>& holds) {
  return closuresOver(std::move(breakpoints), 1,
                      [&](const AlgebraicAngle& angle) { return holds(angle) ? 1u : 0u; })[0];
}

namespace {

/// The closed arcs over the gaps between sorted breakpoints (gap i from breakpoint i
/// to i + 1, the last around to the first) where a property holds: runs of true
/// gaps, each started after a gap that is not.
AngleSet setOfGaps(const std::vector<AlgebraicAngle>& breakpoints, const std::vector<bool>& trueGap) {
  AngleSet set;
  const std::size_t count = breakpoints.size();
  if (std::all_of(trueGap.begin(), trueGap.end(), [](bool value) { return value; })) {
    set.fullCircle = true;
    return set;
  }
  const std::size_t first =
      static_cast<std::size_t>(std::find(trueGap.begin(), trueGap.end(), false) - trueGap.begin());
  for (std::size_t step = 1; step <= count; ++step) {
    const std::size_t gap = (first + step) % count;
    if (!trueGap[gap]) continue;
    const bool continuesRun = trueGap[(gap + count - 1) % count];
    // Breakpoints are sorted: the arc wraps when it runs on from the last one.
    const bool wrapsHere = gap + 1 == count;
    if (continuesRun) {
      set.arcs.back().to = breakpoints[(gap + 1) % count];
      set.arcs.back().wraps = set.arcs.back().wraps || wrapsHere;
    } else {
      set.arcs.push_back({breakpoints[gap], breakpoints[(gap + 1) % count], wrapsHere});
    }
  }
  return set;
}

}  // namespace

std::vector<AngleSet> AngleAlgebra::closuresOver(std::vector<AlgebraicAngle> breakpoints, std::size_t count,
                                                 const std::function<std::uint32_t(const AlgebraicAngle&)>& holding) {
  std::sort(breakpoints.begin(), breakpoints.end(),
            [this](const AlgebraicAngle& a, const AlgebraicAngle& b) { return compare(a, b) < 0; });
  breakpoints.erase(
      std::unique(breakpoints.begin(), breakpoints.end(),
                  [this](const AlgebraicAngle& a, const AlgebraicAngle& b) { return compare(a, b) == 0; }),
      breakpoints.end());
  std::vector<AngleSet> sets(count);
  if (breakpoints.empty()) {
    const std::uint32_t bits = holding(AlgebraicAngle::rational(0, 0.0));
    for (std::size_t property = 0; property < count; ++property) sets[property].fullCircle = (bits >> property) & 1u;
    return sets;
  }
  // The properties are constant inside a gap, so one sample decides them.
  const std::size_t gaps = breakpoints.size();
  std::vector<std::uint32_t> bitsOfGap(gaps);
  for (std::size_t i = 0; i < gaps; ++i) {
    const AlgebraicAngle& next = breakpoints[(i + 1) % gaps];
    const AlgebraicAngle sample =
        gaps == 1 ? angleAtPosition(exactPosition(breakpoints[0]).u.lo + 2) : rationalBetween(breakpoints[i], next);
    bitsOfGap[i] = holding(sample);
  }
  for (std::size_t property = 0; property < count; ++property) {
    std::vector<bool> trueGap(gaps);
    for (std::size_t i = 0; i < gaps; ++i) trueGap[i] = (bitsOfGap[i] >> property) & 1u;
    sets[property] = setOfGaps(breakpoints, trueGap);
    std::sort(sets[property].arcs.begin(), sets[property].arcs.end(),
              [this](const AngleInterval& a, const AngleInterval& b) { return compare(a.from, b.from) < 0; });
  }
  return sets;
}

}  // namespace freespace
