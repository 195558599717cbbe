#pragma once

#include <optional>

namespace freespace {

enum class Sign : int { Negative = -1, Zero = 0, Positive = 1 };

inline Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }

inline Sign operator*(Sign a, Sign b) { return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b)); }

/// The sign of an integer (a comparison result, GMP's sign()).
inline Sign signOf(int value) { return value > 0 ? Sign::Positive : (value < 0 ? Sign::Negative : Sign::Zero); }

/// True when one of the signs is Positive and another Negative.
inline bool mixedSigns(Sign a, Sign b, Sign c) {
  const bool anyPositive = a == Sign::Positive || b == Sign::Positive || c == Sign::Positive;
  const bool anyNegative = a == Sign::Negative || b == Sign::Negative || c == Sign::Negative;
  return anyPositive && anyNegative;
}

/// Two strict signs that are equal (both Positive or both Negative).
inline bool sameStrictSign(Sign a, Sign b) { return a != Sign::Zero && a == b; }

}  // namespace freespace
