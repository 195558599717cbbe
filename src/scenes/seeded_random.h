#pragma once

#include <cmath>
#include <cstdint>
#include <random>

namespace freespace::detail {

/// Random choices that are the same on every platform for a given seed: the
/// standard's distributions are implementation-defined, so only the raw output of
/// mt19937_64 (which the standard fixes) is used.
class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  /// A whole number in [low, high].
  std::int64_t integer(std::int64_t low, std::int64_t high) {
    const auto span = static_cast<std::uint64_t>(high - low) + 1;
    return low + static_cast<std::int64_t>(engine_() % span);
  }

  /// A multiple of `step` in [low, high] (both multiples of `step`).
  double onGrid(double low, double high, double step) {
    return low + step * static_cast<double>(integer(0, std::llround((high - low) / step)));
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace freespace::detail
