#pragma once

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "freespace/numbers/sign.h"

#if defined(__x86_64__) && defined(__SSE2__)
#include <xmmintrin.h>
#endif

/// The interval operations are a few instructions each and run in every predicate's
/// inner loop: inlined even where the compiler's size heuristics would call them.
#if defined(__GNUC__)
#define FREESPACE_INTERVAL_INLINE __attribute__((always_inline)) inline
#else
#define FREESPACE_INTERVAL_INLINE inline
#endif

namespace freespace {

namespace detail {

#if defined(__x86_64__) && defined(__SSE2__)
/// The rounding direction of double arithmetic (FE_TONEAREST, FE_UPWARD, ...). On
/// x86-64 doubles are computed by the SSE unit alone, so only its control register
/// is read and set: the C library's fegetround and fesetround also go through the
/// x87 unit, which costs several times more on the hot paths of the predicates (the
/// x87 unit, unused by double arithmetic here, keeps its own mode).
inline int roundingMode() {
  constexpr int kModes[] = {FE_TONEAREST, FE_DOWNWARD, FE_UPWARD, FE_TOWARDZERO};
  return kModes[(_mm_getcsr() >> 13) & 3u];
}

inline void setRoundingMode(int mode) {
  const unsigned bits = mode == FE_DOWNWARD ? 1u : mode == FE_UPWARD ? 2u : mode == FE_TOWARDZERO ? 3u : 0u;
  _mm_setcsr((_mm_getcsr() & ~(3u << 13)) | (bits << 13));
}
#else
inline int roundingMode() { return std::fegetround(); }
inline void setRoundingMode(int mode) { std::fesetround(mode); }
#endif

}  // namespace detail

/// A closed interval of doubles with outward rounding: the double-interval level of
/// the robust predicates (docs/design.md section 5, step 2).
///
/// It stores -lower and upper and does every operation with the FPU rounding upward,
/// so both bounds round outward with no mode switch per operation: the lower bound
/// of x * y is -max((-x_i) * y_j). Multiplication and division take the extremes of
/// the four end-point products branch-free; on predicate streams, whose operand
/// signs are unpredictable, that is about twice as fast as a case analysis on signs
/// (an FFF determinant: 63 ns against Boost.Interval's 138). Arithmetic is valid only
/// while a RoundingScope is alive on the current thread. A NaN anywhere makes the
/// whole interval NaN, whose sign is never certain.
class Interval {
 public:
  Interval() = default;
  Interval(double value) : negatedLower_(-value), upper_(value) {}  // NOLINT: implicit, like a number
  Interval(double lower, double upper) : negatedLower_(-lower), upper_(upper) {}

  double lower() const { return -negatedLower_; }
  double upper() const { return upper_; }
  /// The middle of the bounds, rounded (a point inside for finite bounds).
  double midpoint() const { return 0.5 * lower() + 0.5 * upper(); }

  friend FREESPACE_INTERVAL_INLINE Interval operator+(const Interval& a, const Interval& b) {
    return fromNegatedLower(a.negatedLower_ + b.negatedLower_, a.upper_ + b.upper_);
  }
  friend FREESPACE_INTERVAL_INLINE Interval operator-(const Interval& a, const Interval& b) {
    return fromNegatedLower(a.negatedLower_ + b.upper_, a.upper_ + b.negatedLower_);
  }
  friend FREESPACE_INTERVAL_INLINE Interval operator-(const Interval& a) { return fromNegatedLower(a.upper_, a.negatedLower_); }

  friend FREESPACE_INTERVAL_INLINE Interval operator*(const Interval& a, const Interval& b) {
    const double al = -a.negatedLower_, bl = -b.negatedLower_, ah = a.upper_, bh = b.upper_;
    return extremes(al * bl, al * bh, ah * bl, ah * bh, (-al) * bl, (-al) * bh, (-ah) * bl, (-ah) * bh);
  }

  /// Division by an interval that contains zero is a programming error: no
  /// predicate divides by something that may vanish.
  friend FREESPACE_INTERVAL_INLINE Interval operator/(const Interval& a, const Interval& b) {
    // A negative divisor: a / b = (-a) / (-b).
    const bool negative = b.upper_ < 0;
    const Interval n = negative ? -a : a, d = negative ? -b : b;
    const double bl = -d.negatedLower_, bh = d.upper_;
    if (!(bl > 0)) divisionByZero();
    // For a positive divisor the largest quotient is nh / bl or nh / bh (as nh is
    // positive or not), and the smallest nl / bh or nl / bl.
    const double nl = -n.negatedLower_, nh = n.upper_;
    const double upper = std::max(nh / bl, nh / bh), negatedLower = std::max((-nl) / bl, (-nl) / bh);
    if (std::isnan(upper + negatedLower)) return fromNegatedLower(upper + negatedLower, upper + negatedLower);
    return fromNegatedLower(negatedLower, upper);
  }

  Interval& operator+=(const Interval& other) { return *this = *this + other; }
  Interval& operator-=(const Interval& other) { return *this = *this - other; }
  Interval& operator*=(const Interval& other) { return *this = *this * other; }

  /// The square root of the non-negative part.
  friend Interval sqrt(const Interval& a) {
    const double low = a.lower() > 0 ? std::sqrt(a.lower()) : 0.0;  // rounded up ...
    const double lowDown = low > 0 ? std::nextafter(low, 0.0) : 0.0;  // ... so one step down is below
    return Interval(lowDown, std::sqrt(std::max(a.upper_, 0.0)));
  }

 private:
  [[noreturn, gnu::noinline, gnu::cold]] static void divisionByZero() {
    throw std::domain_error("interval division by an interval that may contain zero");
  }

  FREESPACE_INTERVAL_INLINE static Interval fromNegatedLower(double negatedLower, double upper) {
    Interval result;
    result.negatedLower_ = negatedLower;
    result.upper_ = upper;
    return result;
  }

  /// Upper bound: the largest of p0..p3 (rounded up); lower bound from the largest of
  /// the negated products q0..q3 (each rounded up). std::max would drop a NaN, so
  /// a NaN in any product is checked for and propagated.
  FREESPACE_INTERVAL_INLINE static Interval extremes(double p0, double p1, double p2, double p3, double q0, double q1,
                                                    double q2, double q3) {
    if (std::isnan(p0 + p1 + p2 + p3)) return fromNegatedLower(std::numeric_limits<double>::quiet_NaN(), p0 + p1 + p2 + p3);
    return fromNegatedLower(std::max(std::max(q0, q1), std::max(q2, q3)), std::max(std::max(p0, p1), std::max(p2, p3)));
  }

  double negatedLower_ = 0;
  double upper_ = 0;
};

/// Sets the rounding of double arithmetic to `Mode` and restores the previous mode
/// on destruction; nested scopes cost only a mode read.
template <int Mode>
class ScopedRounding {
 public:
  ScopedRounding() : previous_(detail::roundingMode()) {
    if (previous_ != Mode) detail::setRoundingMode(Mode);
  }
  ~ScopedRounding() {
    if (previous_ != Mode) detail::setRoundingMode(previous_);
  }
  ScopedRounding(const ScopedRounding&) = delete;
  ScopedRounding& operator=(const ScopedRounding&) = delete;

 private:
  int previous_;
};

/// Rounding upward, as Interval needs. Keep scopes tight: ordinary double code inside
/// one rounds upward.
using RoundingScope = ScopedRounding<FE_UPWARD>;

/// Certain sign of an interval, or nothing when it contains zero without being
/// exactly zero (or is NaN).
FREESPACE_INTERVAL_INLINE std::optional<Sign> certainSign(const Interval& value) {
  if (!(value.lower() <= value.upper())) return std::nullopt;
  if (value.lower() > 0) return Sign::Positive;
  if (value.upper() < 0) return Sign::Negative;
  if (value.lower() == 0 && value.upper() == 0) return Sign::Zero;
  return std::nullopt;
}

}  // namespace freespace
