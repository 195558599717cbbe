#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "freespace/numbers/adaptive_sign.h"
#include "freespace/numbers/double_double_interval.h"
#include "freespace/numbers/exact_polynomial.h"
#include "freespace/numbers/half_angle.h"
#include "freespace/numbers/interval.h"
#include "freespace/numbers/multiprecision_interval.h"
#include "freespace/numbers/polynomial.h"

namespace freespace {

namespace detail {

/// A value kept for some roots of a function, by chart and by the root's index
/// there.
template <class T>
class RootMemo {
 public:
  std::optional<T> find(int chart, int index) const {
    const auto& values = values_[chart];
    if (index < 0 || static_cast<std::size_t>(index) >= values.size()) return std::nullopt;
    return values[index];
  }
  void remember(int chart, int index, const T& value) {
    auto& values = values_[chart];
    if (static_cast<std::size_t>(index) >= values.size()) values.resize(index + 1);
    values[index] = value;
  }

 private:
  std::array<std::vector<std::optional<T>>, 2> values_;
};

}  // namespace detail

/// A function of the angle theta given in each chart (HalfAngle) by a polynomial in
/// the tangent parameter t whose sign is the function's sign. It keeps double
/// interval coefficients for filtering; the first time they are needed it computes
/// double-double ones (the formula evaluated in DoubleDoubleInterval, about 106
/// bits), their rounding outward to doubles (tight coefficients: an ulp or two wide
/// instead of the tens that double interval arithmetic accumulates), their MPFI
/// enclosure for bisection past doubles, and exact rational ones. Threads may share
/// a function: what it makes on first use is made under one lock (and never changes
/// after), and its memos are read and written under it (a remembered enclosure only
/// narrows).
class AngleFunction {
 public:
  /// Names a function up to a nonzero constant factor: two functions with the same
  /// key have the same roots, so their roots are told apart by their index alone
  /// (a combinatorial identity rule, docs/design.md section 5). Keys are chosen by the
  /// caller from input feature indices and are only compared within one AngleAlgebra.
  using RootKey = std::array<std::uint32_t, 9>;

  /// `formula(NumberType<T>{}, chart)` returns the chart's Polynomial<T>, computed
  /// from double inputs; it is written once for every number type.
  template <class Formula>
  explicit AngleFunction(const Formula& formula, std::optional<RootKey> key = std::nullopt)
      : evaluator_(std::make_unique<EvaluatorOf<Formula>>(formula)), key_(key) {
    RoundingScope rounding;
    for (int chart = 0; chart < 2; ++chart) approximate_[chart] = formula(NumberType<Interval>{}, chart);
  }

  /// The same with its charts' double interval polynomials given: the caller has
  /// already evaluated the formula in double intervals (for a filter) and hands the
  /// result over instead of having it computed again.
  template <class Formula>
  AngleFunction(const Formula& formula, std::optional<RootKey> key, std::array<Polynomial<Interval>, 2> approximate)
      : approximate_(std::move(approximate)), evaluator_(std::make_unique<EvaluatorOf<Formula>>(formula)), key_(key) {}

  /// Where a function read back (from a saved free space) gets its exact
  /// polynomials: asked only when a predicate first needs them, which most functions
  /// never do (docs/design.md section 6, saving and loading).
  class ExactSource {
   public:
    virtual ~ExactSource() = default;
    /// The chart's exact polynomial, whose coefficients must lie in `enclosure`'s;
    /// a source that cannot give it so throws.
    virtual RationalPolynomial polynomial(int chart, const Polynomial<Interval>& enclosure) const = 0;
  };

  /// A function read back: double interval coefficients as narrow as doubles allow
  /// (so they are its tight ones too) and the source of its exact polynomials.
  AngleFunction(std::array<Polynomial<Interval>, 2> enclosures, std::optional<RootKey> key,
                std::unique_ptr<const ExactSource> exact);

  const Polynomial<Interval>& approximate(int chart) const { return approximate_[chart]; }
  const Polynomial<Interval>& tight(int chart) const;
  /// The chart's polynomial in double-double intervals (whose rounding is `tight`).
  const Polynomial<DoubleDoubleInterval>& doubleDouble(int chart) const;
  /// The same in MPFI at about 108 bits, for bisection at that precision.
  const Polynomial<PreciseInterval>& precise(int chart) const;
  const RationalPolynomial& exact(int chart) const;
  /// The same, but made without keeping it when it was not made yet: for a caller
  /// that needs every function's once (saving a free space), on several threads at
  /// once (exact makes one function's at a time).
  RationalPolynomial exactOnce(int chart) const;
  const RationalPolynomial& squareFree(int chart) const;
  /// True when the function vanishes at every angle (decided from the double
  /// interval or else the tight coefficients when one is certainly not zero,
  /// exactly otherwise).
  bool isIdenticallyZero() const;
  const std::optional<RootKey>& key() const { return key_; }

  /// The certified double-double enclosure of the chart's root with the given index
  /// (its place among the chart's roots), once one was found (rememberRoot).
  std::optional<DoubleDoubleInterval> rememberedRoot(int chart, int index) const;
  void rememberRoot(int chart, int index, const DoubleDoubleInterval& root) const;

  /// The narrowest double enclosure found so far of the chart's root with the given
  /// index, and whether the tight coefficients were in use (rememberEnclosure): a
  /// comparison that had to refine a root lets the next one start there.
  struct NarrowEnclosure {
    double lower, upper;
    bool tight;
  };
  std::optional<NarrowEnclosure> rememberedEnclosure(int chart, int index) const;
  /// Kept only when narrower than the one remembered.
  void rememberEnclosure(int chart, int index, const NarrowEnclosure& enclosure) const;

 private:
  /// The formula in the number types past double intervals, kept once.
  struct Evaluator {
    virtual ~Evaluator() = default;
    virtual Polynomial<DoubleDoubleInterval> doubleDouble(int chart) const = 0;
    virtual RationalPolynomial exact(int chart) const = 0;
  };
  template <class Formula>
  struct EvaluatorOf final : Evaluator {
    explicit EvaluatorOf(const Formula& formula) : formula(formula) {}
    Polynomial<DoubleDoubleInterval> doubleDouble(int chart) const override {
      NearestRoundingScope rounding;
      return formula(NumberType<DoubleDoubleInterval>{}, chart);
    }
    RationalPolynomial exact(int chart) const override { return formula(NumberType<Rational>{}, chart); }
    Formula formula;
  };

  std::array<Polynomial<Interval>, 2> approximate_;
  /// One of the two: the formula of a function made from one, the source of one read back.
  std::unique_ptr<const Evaluator> evaluator_;
  std::unique_ptr<const ExactSource> source_;
  std::optional<RootKey> key_;
  /// The coefficients past double intervals, and the roots found with them, made on
  /// first use: most functions never need them, and kept apart they leave a function
  /// small to make and to free.
  struct Escalation {
    std::array<std::optional<Polynomial<DoubleDoubleInterval>>, 2> doubleDouble;
    std::array<std::optional<Polynomial<Interval>>, 2> tight;
    std::array<std::optional<Polynomial<PreciseInterval>>, 2> precise;
    std::array<std::optional<RationalPolynomial>, 2> exact;
    std::array<std::optional<RationalPolynomial>, 2> squareFree;
    detail::RootMemo<DoubleDoubleInterval> doubleDoubleRoots;
  };
  /// Made on first use; its callers hold the lock on first-use values.
  Escalation& escalation() const;

  mutable std::unique_ptr<Escalation> escalation_;
  mutable detail::RootMemo<NarrowEnclosure> narrowEnclosures_;
};

/// An angle that is a root of an AngleFunction (or a rational angle, a HalfAngle):
/// its chart and a double enclosure of t in that chart that isolates the root, plus
/// an exact isolating interval when the root was isolated exactly (a root isolated
/// in doubles needs none: its double enclosure is an exact isolating interval). Charts are canonical: chart 0 holds t in [-1, 1]
/// (theta in [-pi/2, pi/2]), chart 1 holds t in (-1, 1) (theta in (pi/2, 3pi/2)).
class AlgebraicAngle {
 public:
  /// A root isolated in double intervals by [lower, upper]; `index` is its place
  /// among the function's distinct roots in the chart, in increasing t (-1: unknown).
  AlgebraicAngle(std::shared_ptr<const AngleFunction> function, int chart, double lower, double upper,
                 int index = -1);
  /// A root isolated exactly.
  AlgebraicAngle(std::shared_ptr<const AngleFunction> function, int chart, const IsolatingInterval& root,
                 int index = -1);
  static AlgebraicAngle rational(const HalfAngle& angle);
  /// The rational angle with tangent parameter t (in [-1, 1]) in the chart.
  static AlgebraicAngle rational(int chart, const Rational& t);
  /// The same for a t that is a double (no rational arithmetic until needed).
  static AlgebraicAngle rational(int chart, double t);

  int chart() const { return chart_; }
  /// Null for a rational angle.
  const std::shared_ptr<const AngleFunction>& function() const { return function_; }
  /// An exact isolating interval of t: the exact one narrowed by the double enclosure.
  IsolatingInterval root() const;
  double lower() const { return lower_; }
  double upper() const { return upper_; }
  bool isRational() const { return !function_; }
  int index() const { return index_; }
  /// theta in radians, approximately (for output only).
  double radians() const;

  /// Halves the double enclosure once (or splits it off the middle), when the
  /// function's sign there is certain in double intervals. Returns false when no
  /// progress can be made in doubles.
  bool refineInDoubles();
  /// Refines in doubles until the enclosure is at most `width` wide or no progress
  /// can be made.
  void refineInDoublesTo(double width);
  /// From now on refines with the function's tight coefficients. Returns false when
  /// there is nothing to tighten (a rational angle, or already tight).
  bool useTightCoefficients();
  /// Takes the narrowest enclosure its function remembers for this root, when
  /// narrower than its own.
  void adoptRememberedEnclosure();
  /// Its own enclosure narrowed by the one its function remembers (no change made).
  std::pair<double, double> narrowestKnownEnclosure() const;
  /// Gives its enclosure to its function to remember, when narrower than what it has.
  void rememberEnclosure() const;
  /// A copy refined in doubles as far as they go (with tight coefficients when the
  /// function's own leave it wider than 2^-40): for many predicates at one angle,
  /// which then start from a narrow enclosure.
  AlgebraicAngle narrowed() const;

 private:
  /// The polynomial refinement evaluates: the function's own or tight coefficients.
  const Polynomial<Interval>& refinedPolynomial() const;
  /// Whether p's signs at the enclosure's ends are certain and opposite (then kept
  /// in signAtLower_); inside a RoundingScope.
  bool knowsSignChange(const Polynomial<Interval>& p);
  /// Narrows the enclosure to a bracket at most `width` wide around a Newton guess,
  /// when signs certify it. Returns whether it did.
  bool bracketByNewton(double width);

  std::shared_ptr<const AngleFunction> function_;
  int chart_;
  /// Exact isolating interval, when the root was isolated in rationals (rare: kept
  /// apart so that copies of the angle stay small).
  std::shared_ptr<const IsolatingInterval> exactRoot_;
  double lower_, upper_;
  int index_ = -1;
  bool tight_ = false;
  /// The function's sign at `lower_` once found certain (it never changes as the
  /// enclosure narrows); Zero while unknown.
  Sign signAtLower_ = Sign::Zero;
};

/// An arc of the circle, counterclockwise from `from` to `to` (both included).
/// `wraps` when it passes through the cut at theta = -pi/2 (`to` precedes `from` in
/// the order of AngleAlgebra::compare); it is decided once, when the arc is made.
struct AngleInterval {
  AlgebraicAngle from;
  AlgebraicAngle to;
  bool wraps = false;
};

/// A closed set of angles: the whole circle, or disjoint closed arcs in the order of
/// AngleAlgebra::compare (the last may wrap through the cut at -pi/2).
struct AngleSet {
  bool fullCircle = false;
  std::vector<AngleInterval> arcs;

  bool empty() const { return !fullCircle && arcs.empty(); }
};

/// The cosine and sine of a rational angle (AlgebraicAngle::isRational), exactly,
/// from its chart's parameter t (HalfAngle's formulas).
std::pair<Rational, Rational> exactCosSin(const AlgebraicAngle& rationalAngle);

/// Double enclosures of the cosine and sine of an angle (inside a RoundingScope): a
/// rational angle's own, or HalfAngle's formulas over its enclosure of t.
std::pair<Interval, Interval> cosSinEnclosure(const AlgebraicAngle& angle);

/// The angle's tangent parameter t (in its chart) as a double-double interval of
/// radius 2^-99 (up to 2^-79 for ill-conditioned roots): a rational angle's own
/// value, or Newton steps on the function's double-double polynomial from its double
/// enclosure, certified by certain opposite signs at both ends, inside the
/// enclosure. Nothing when that fails (a root of even multiplicity, or one the
/// coefficients do not resolve).
std::optional<DoubleDoubleInterval> doubleDoubleParameter(const AlgebraicAngle& angle);

/// The cosine and sine of the angle with parameter t in a chart (HalfAngle's
/// formulas), in double-double intervals.
std::pair<DoubleDoubleInterval, DoubleDoubleInterval> doubleDoubleCosSin(const DoubleDoubleInterval& t, int chart);

/// Exact predicates on algebraic angles, filtered in double intervals with exact
/// rational fallback and exact identity detection (equal roots compare equal; a
/// function that vanishes at a root has sign exactly zero), counted in statistics.
class AngleAlgebra {
 public:
  explicit AngleAlgebra(PredicateStatistics& statistics) : statistics_(statistics) {}

  PredicateStatistics& statistics() { return statistics_; }

  /// The real roots of `function` on the circle, distinct, in the order of
  /// compare(). Throws std::invalid_argument when the function is identically zero.
  std::vector<AlgebraicAngle> roots(const std::shared_ptr<const AngleFunction>& function, PredicateKind kind);

  /// Sign of `function` at `angle`.
  Sign signAt(const AngleFunction& function, const AlgebraicAngle& angle);

  /// -1, 0 or +1: the order of two angles along the circle cut at theta = -pi/2,
  /// i.e. by theta in [-pi/2, 3pi/2).
  int compare(const AlgebraicAngle& a, const AlgebraicAngle& b) {
    // Enclosures apart decide at once (most comparisons), here in the caller.
    if (a.chart() != b.chart() || a.upper() < b.lower() || b.upper() < a.lower()) {
      const int order = a.chart() != b.chart() ? (a.chart() < b.chart() ? -1 : 1) : (a.upper() < b.lower() ? -1 : 1);
      record(PredicateKind::RootOrder, static_cast<int>(PrecisionLevel::DoubleInterval), signOf(order));
      return order;
    }
    return compareOverlapping(a, b);
  }

  /// Whether an arc's ends belong to it for `contains`: the closed arc, or the open
  /// one (its interior; the interior of an AngleSet is the union of its open arcs,
  /// which are apart).
  enum class Boundary { Included, Excluded };

  /// Whether the arc contains `angle`; an arc whose `to` precedes its `from` wraps
  /// through the cut.
  bool contains(const AngleInterval& arc, const AlgebraicAngle& angle, Boundary boundary = Boundary::Included);
  /// The same for the arc from `from` to `to` given by its ends (no copies of them:
  /// slab lookups ask this for every slab they pass).
  bool contains(const AlgebraicAngle& from, const AlgebraicAngle& to, bool wraps, const AlgebraicAngle& angle,
                Boundary boundary);
  bool contains(const AngleSet& set, const AlgebraicAngle& angle, Boundary boundary = Boundary::Included);

  /// A rational angle strictly inside the open arc from `from` to `to`
  /// (counterclockwise, so through the cut when `to` precedes `from`); the two
  /// angles must differ.
  AlgebraicAngle rationalBetween(const AlgebraicAngle& from, const AlgebraicAngle& to);

  /// A rational angle next to `angle`, before it (`before`) or after it, less than
  /// 2^-bits away in the circle's parameter u (t, and t + 2 in chart 1), and strictly
  /// between it and `bound`, which must differ from it. Halves the exact isolating
  /// interval as often as needed.
  AlgebraicAngle rationalNextTo(const AlgebraicAngle& angle, const AlgebraicAngle& bound, bool before, int bits);

  /// The closure of the set of angles where every function is positive (empty when
  /// one of them vanishes identically).
  AngleSet positiveSet(const std::vector<std::shared_ptr<const AngleFunction>>& functions, PredicateKind kind);

  /// The closure of the set of angles where `holds` is true, for a property that can
  /// change only at the roots of `functions` and at the `breakpoints` (none of the
  /// functions may vanish identically). `holds` is asked at rational angles only.
  AngleSet closureWhere(const std::vector<std::shared_ptr<const AngleFunction>>& functions,
                        std::vector<AlgebraicAngle> breakpoints,
                        const std::function<bool(const AlgebraicAngle&)>& holds, PredicateKind kind);

  /// The same for a property that can change only at the `breakpoints`.
  AngleSet closureOver(std::vector<AlgebraicAngle> breakpoints, const std::function<bool(const AlgebraicAngle&)>& holds);

  /// The same for `count` properties at once (bit i of `holding` for property i),
  /// sampled once per gap between breakpoints.
  std::vector<AngleSet> closuresOver(std::vector<AlgebraicAngle> breakpoints, std::size_t count,
                                     const std::function<std::uint32_t(const AlgebraicAngle&)>& holding);

  /// The closures of the set where every function has the sign `pattern` gives it
  /// (Positive or Negative), and of the set where every one has the opposite sign:
  /// both from one set of roots (empty when a function vanishes identically).
  std::array<AngleSet, 2> signPatternSets(const std::vector<std::shared_ptr<const AngleFunction>>& functions,
                                          const std::vector<Sign>& pattern, PredicateKind kind);

 private:
  std::optional<int> compareInDoubles(AlgebraicAngle& a, AlgebraicAngle& b) const;
  /// compare for angles in one chart whose double enclosures overlap.
  int compareOverlapping(const AlgebraicAngle& a, const AlgebraicAngle& b);
  std::optional<int> compareByKey(const AlgebraicAngle& a, const AlgebraicAngle& b);
  /// The order in double intervals once the functions' tight coefficients are used.
  std::optional<int> compareTightly(AlgebraicAngle& first, AlgebraicAngle& second);
  /// The order of the angles' parameters refined in double-doubles, when apart.
  std::optional<int> compareInDoubleDoubles(const AlgebraicAngle& first, const AlgebraicAngle& second);
  /// The order from the roots bisected in MPFI (the functions' precise polynomials),
  /// when their signs stay certain.
  std::optional<int> comparePrecisely(const AlgebraicAngle& first, const AlgebraicAngle& second);
  int compareEscalated(const AlgebraicAngle& a, const AlgebraicAngle& b);
  Sign record(PredicateKind kind, int level, Sign sign) {
    statistics_.recordDecision(kind, level);
    if (sign == Sign::Zero) statistics_.recordIdentity(kind);
    return sign;
  }

  /// Two roots, each by its function's address, chart and index there.
  struct RootPair {
    const AngleFunction* first;
    const AngleFunction* second;
    int firstChart, firstIndex, secondChart, secondIndex;
    bool operator==(const RootPair& other) const {
      return first == other.first && second == other.second && firstChart == other.firstChart &&
             firstIndex == other.firstIndex && secondChart == other.secondChart && secondIndex == other.secondIndex;
    }
  };
  struct RootPairHash {
    std::size_t operator()(const RootPair& pair) const;
  };
  /// An order found, with the two functions kept alive (so that their addresses
  /// stay unique).
  struct KnownOrder {
    int order;
    std::shared_ptr<const AngleFunction> first, second;
  };

  PredicateStatistics& statistics_;
  /// Orders of roots that doubles could not separate, decided once: the same pair
  /// of close roots is met again and again by a construction.
  std::unordered_map<RootPair, KnownOrder, RootPairHash> knownOrders_;
};

}  // namespace freespace
