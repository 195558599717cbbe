#include "freespace/numbers/predicate_statistics.h"

#include <numeric>
#include <sstream>

#include <boost/multiprecision/detail/digits.hpp>

namespace freespace {

const char* predicateKindName(PredicateKind kind) {
  switch (kind) {
    case PredicateKind::Orientation: return "orientation";
    case PredicateKind::EdgeFacet: return "ef";
    case PredicateKind::SpiralFacet: return "sf";
    case PredicateKind::ThreePatch: return "fff";
    case PredicateKind::SignAtRoot: return "sign_at_root";
    case PredicateKind::RootOrder: return "root_order";
    case PredicateKind::CrossingOrder: return "crossing_order";
    case PredicateKind::EdgeCrossSection: return "edge_cross_section";
    case PredicateKind::Other: return "other";
    case PredicateKind::Count: break;
  }
  return "unknown";
}

std::string precisionLevelName(int level) {
  if (level == static_cast<int>(PrecisionLevel::DoubleInterval)) return "double";
  if (level == static_cast<int>(PrecisionLevel::DoubleDouble)) return "double_double";
  if (level == static_cast<int>(PrecisionLevel::Exact)) return "exact";
  const unsigned digits = kMultiprecisionDigits[level - static_cast<int>(PrecisionLevel::Multiprecision)];
  return "mpfi" + std::to_string(boost::multiprecision::detail::digits10_2_2(digits));
}

std::uint64_t PredicateStatistics::KindCounts::total() const {
  return std::accumulate(decided.begin(), decided.end(), std::uint64_t{0});
}

void PredicateStatistics::merge(const PredicateStatistics& other) {
  for (std::size_t kind = 0; kind < counts_.size(); ++kind) {
    for (int level = 0; level < kPrecisionLevelCount; ++level) {
      counts_[kind].decided[level] += other.counts_[kind].decided[level];
    }
    counts_[kind].identities += other.counts_[kind].identities;
    counts_[kind].escalatedSeconds += other.counts_[kind].escalatedSeconds;
  }
}

double PredicateStatistics::doubleIntervalFraction() const {
  std::uint64_t all = 0, inDouble = 0;
  for (const KindCounts& kind : counts_) {
    all += kind.total();
    inDouble += kind.decided[static_cast<int>(PrecisionLevel::DoubleInterval)];
  }
  return all == 0 ? 1.0 : static_cast<double>(inDouble) / static_cast<double>(all);
}

std::string PredicateStatistics::toText() const {
  std::ostringstream out;
  out << "kind";
  for (int level = 0; level < kPrecisionLevelCount; ++level) out << " " << precisionLevelName(level);
  out << " identities escalated_seconds\n";
  for (std::size_t kind = 0; kind < counts_.size(); ++kind) {
    const KindCounts& counts = counts_[kind];
    if (counts.total() == 0 && counts.identities == 0) continue;
    out << predicateKindName(static_cast<PredicateKind>(kind));
    for (std::uint64_t decided : counts.decided) out << " " << decided;
    out << " " << counts.identities << " " << counts.escalatedSeconds << "\n";
  }
  return out.str();
}

}  // namespace freespace
