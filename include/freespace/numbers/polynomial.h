#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace freespace {

/// A univariate polynomial c[0] + c[1] t + ... + c[n-1] t^(n-1), stored as given.
///
/// Generic in the coefficient type: exact rationals, doubles, double intervals and
/// multiprecision intervals. Nothing here compares a coefficient with zero (for an
/// interval that is not decidable), so leading zeros are kept; the exact functions of
/// exact_polynomial.h trim them. No coefficients is the zero polynomial.
template <class T>
class Polynomial {
 public:
  Polynomial() = default;
  explicit Polynomial(std::vector<T> coefficients) : coefficients_(std::move(coefficients)) {}

  const std::vector<T>& coefficients() const { return coefficients_; }
  std::size_t size() const { return coefficients_.size(); }

  /// The value at t by Horner's rule, in the number type of t (each coefficient is
  /// converted to U, e.g. double coefficients evaluated at an interval). Interval
  /// types need their rounding set up by the caller, as for any arithmetic on them.
  template <class U>
  U evaluate(const U& t) const {
    U value(0);
    for (auto coefficient = coefficients_.rbegin(); coefficient != coefficients_.rend(); ++coefficient) {
      value *= t;
      value += as<U>(*coefficient);
    }
    return value;
  }

  /// d/dt, with one coefficient fewer (the zero polynomial for a constant).
  Polynomial derivative() const {
    std::vector<T> result;
    for (std::size_t power = 1; power < coefficients_.size(); ++power) {
      result.emplace_back(coefficients_[power] * T(static_cast<int>(power)));
    }
    return Polynomial(std::move(result));
  }

 private:
  /// The coefficient itself when U is T (no copy), a converted copy otherwise.
  template <class U>
  static decltype(auto) as(const T& coefficient) {
    if constexpr (std::is_same_v<T, U>) {
      return (coefficient);
    } else {
      return U(coefficient);
    }
  }

  std::vector<T> coefficients_;
};

}  // namespace freespace
