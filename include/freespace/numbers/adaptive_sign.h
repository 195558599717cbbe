#pragma once

#include <optional>

#include "freespace/numbers/double_double_interval.h"
#include "freespace/numbers/interval.h"
#include "freespace/numbers/multiprecision_interval.h"
#include "freespace/numbers/predicate_statistics.h"
#include "freespace/numbers/rational.h"

namespace freespace {

/// Names a number type for a predicate: a predicate is written once as
///   template <class T> T operator()(NumberType<T>) const
/// computing its value from double inputs (T(x) converts exactly) with +, -, *.
template <class T>
struct NumberType {
  using type = T;
};

/// Evaluates the sign of a predicate at rising precision (docs/design.md section 5):
/// double intervals, double-double intervals, then MPFI intervals doubling the
/// precision at each level, then exact rationals. The first level whose interval excludes zero, or is exactly
/// zero, decides. An exact zero is a structural identity and is counted as one.
///
/// Not thread safe: use one engine (and one PredicateStatistics) per thread and
/// merge the statistics.
class AdaptiveSignEngine {
 public:
  explicit AdaptiveSignEngine(PredicateStatistics& statistics) : statistics_(statistics) {}

  template <class Predicate>
  Sign sign(PredicateKind kind, const Predicate& predicate) {
    if (const std::optional<Sign> sign = doubleIntervalSign(predicate)) {
      return record(kind, static_cast<int>(PrecisionLevel::DoubleInterval), *sign);
    }
    const EscalationTimer timer(statistics_, kind);
    if (const std::optional<Sign> sign = doubleDoubleSign(predicate)) {
      return record(kind, static_cast<int>(PrecisionLevel::DoubleDouble), *sign);
    }
    int level = static_cast<int>(PrecisionLevel::Exact);
    std::optional<Sign> sign = multiprecisionSign<0>(predicate, level);
    if (!sign) sign = exactSign(Rational(predicate(NumberType<Rational>{})));
    return record(kind, level, *sign);
  }

  /// A sign known to be zero by a combinatorial rule (shared input features): no
  /// evaluation, counted as an identity.
  Sign knownIdentity(PredicateKind kind) {
    statistics_.recordIdentity(kind);
    return Sign::Zero;
  }

  PredicateStatistics& statistics() { return statistics_; }

 private:
  template <class Predicate>
  static std::optional<Sign> doubleIntervalSign(const Predicate& predicate) {
    RoundingScope rounding;
    return certainSign(predicate(NumberType<Interval>{}));
  }

  template <class Predicate>
  static std::optional<Sign> doubleDoubleSign(const Predicate& predicate) {
    NearestRoundingScope rounding;
    return certainSign(predicate(NumberType<DoubleDoubleInterval>{}));
  }

  template <int Step, class Predicate>
  static std::optional<Sign> multiprecisionSign(const Predicate& predicate, int& level) {
    if constexpr (Step == kMultiprecisionLevels) {
      return std::nullopt;
    } else {
      using T = MultiprecisionInterval<kMultiprecisionDigits[Step]>;
      if (const std::optional<Sign> sign = certainSign(T(predicate(NumberType<T>{})))) {
        level = static_cast<int>(PrecisionLevel::Multiprecision) + Step;
        return sign;
      }
      return multiprecisionSign<Step + 1>(predicate, level);
    }
  }

  Sign record(PredicateKind kind, int level, Sign sign) {
    statistics_.recordDecision(kind, level);
    if (sign == Sign::Zero) statistics_.recordIdentity(kind);
    return sign;
  }

  PredicateStatistics& statistics_;
};

}  // namespace freespace
