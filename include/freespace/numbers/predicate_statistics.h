#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <string>

#include "freespace/numbers/multiprecision_interval.h"

namespace freespace {

/// The kinds of predicate the statistics are kept for (docs/design.md section 4).
enum class PredicateKind : int {
  Orientation,   // orientation determinants on points
  EdgeFacet,     // EF: sign of a degree-2 angle polynomial
  SpiralFacet,   // SF: spiral point against a patch line, degree 2
  ThreePatch,    // FFF: three patch lines concurrent, degree 4
  SignAtRoot,    // sign of an angle polynomial at an algebraic angle
  RootOrder,     // order of two algebraic angles
  CrossingOrder, // order of two lines' crossings along a patch's segment
  EdgeCrossSection,  // the cross-sections of a horizontal edge, read as one decision
  Other,
  Count
};

const char* predicateKindName(PredicateKind kind);

/// Levels of the adaptive evaluation, cheapest first: double intervals, double-double
/// intervals (about 106 bits), MPFI from about 108 bits up, exact rationals.
enum class PrecisionLevel : int {
  DoubleInterval = 0,
  DoubleDouble = 1,
  Multiprecision = 2,
  Exact = 2 + kMultiprecisionLevels
};
inline constexpr int kPrecisionLevelCount = 3 + kMultiprecisionLevels;

/// Name of level index i: "double", "double_double", "mpfi108", ..., "exact".
std::string precisionLevelName(int level);

/// Per predicate kind: how many signs each precision level decided, how many were
/// identities (exactly zero, confirmed exactly or by a combinatorial rule), and the
/// time spent in the levels above double intervals (double-interval evaluations are
/// too short to time one by one; benchmarks measure them).
class PredicateStatistics {
 public:
  struct KindCounts {
    std::array<std::uint64_t, kPrecisionLevelCount> decided{};
    std::uint64_t identities = 0;
    double escalatedSeconds = 0;

    std::uint64_t total() const;
  };

  void recordDecision(PredicateKind kind, int level) { counts_[index(kind)].decided[level]++; }
  void recordIdentity(PredicateKind kind) { counts_[index(kind)].identities++; }
  void recordEscalatedTime(PredicateKind kind, double seconds) { counts_[index(kind)].escalatedSeconds += seconds; }

  const KindCounts& counts(PredicateKind kind) const { return counts_[index(kind)]; }
  /// Sums another thread's statistics into this one.
  void merge(const PredicateStatistics& other);
  /// Fraction of all decisions taken in double intervals (1 when there were none).
  double doubleIntervalFraction() const;
  /// A table, one line per kind that was used.
  std::string toText() const;

 private:
  static std::size_t index(PredicateKind kind) { return static_cast<std::size_t>(kind); }
  std::array<KindCounts, static_cast<std::size_t>(PredicateKind::Count)> counts_{};
};

/// Adds the time from its construction to its destruction to the escalated time of
/// a predicate kind: put one in scope where a predicate leaves double intervals.
class EscalationTimer {
 public:
  EscalationTimer(PredicateStatistics& statistics, PredicateKind kind)
      : statistics_(statistics), kind_(kind), start_(std::chrono::steady_clock::now()) {}
  ~EscalationTimer() {
    statistics_.recordEscalatedTime(kind_,
                                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  EscalationTimer(const EscalationTimer&) = delete;
  EscalationTimer& operator=(const EscalationTimer&) = delete;

 private:
  PredicateStatistics& statistics_;
  PredicateKind kind_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace freespace
