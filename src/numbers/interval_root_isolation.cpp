#include "interval_root_isolation.h"

#include <algorithm>

#include "freespace/numbers/angle_polynomial.h"

namespace freespace::detail {

namespace {

/// Bisection depth after which the isolation gives up (roots closer than about 2^-40).
constexpr int kMaximumDepth = 40;

/// Replaces the coefficients of c(y) by those of c(y + s) (Taylor shift by Horner's
/// scheme, in place).
template <class T>
void taylorShift(std::vector<T>& c, const T& s) {
  const std::size_t n = c.size() - 1;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = n; j-- > i;) c[j] = c[j] + s * c[j + 1];
  }
}

/// (x + 1)^n p((a x + b) / (x + 1)) = sum of c_i (a x + b)^i (x + 1)^(n - i). With
/// r(y) = p(b + (a - b) y) and R the reversal of r, it is the reversal of R(z + 1):
/// two Taylor shifts and a scaling on one vector.
template <class T>
Polynomial<T> descartesTransform(const Polynomial<T>& p, double a, double b) {
  std::vector<T> c = p.coefficients();
  taylorShift(c, T(b));
  const T scale = T(a) - T(b);
  T power(1);
  for (std::size_t i = 1; i < c.size(); ++i) {
    power = power * scale;
    c[i] = c[i] * power;
  }
  std::reverse(c.begin(), c.end());
  taylorShift(c, T(1));
  std::reverse(c.begin(), c.end());
  return Polynomial<T>(std::move(c));
}

/// Sign variations of the coefficients, skipping exact zeros; nothing when a
/// coefficient's sign is uncertain.
template <class T>
std::optional<int> signVariations(const Polynomial<T>& q) {
  int variations = 0;
  Sign previous = Sign::Zero;
  for (const T& coefficient : q.coefficients()) {
    const std::optional<Sign> sign = certainSign(coefficient);
    if (!sign) return std::nullopt;
    if (*sign == Sign::Zero) continue;
    if (previous != Sign::Zero && *sign != previous) ++variations;
    previous = *sign;
  }
  return variations;
}

template <class T>
std::optional<Sign> nonzeroSignAt(const Polynomial<T>& p, double t) {
  const std::optional<Sign> sign = certainSign(p.evaluate(T(t)));
  if (!sign || *sign == Sign::Zero) return std::nullopt;
  return sign;
}

/// Appends the enclosures of the roots in (a, b) to `roots`; false when the interval
/// arithmetic of T cannot decide.
template <class T>
bool isolate(const Polynomial<T>& p, double a, double b, int depth, std::vector<Interval>& roots) {
  const std::optional<int> variations = signVariations(descartesTransform(p, a, b));
  if (!variations) return false;
  if (*variations == 0) return true;
  if (*variations == 1) {
    // One simple root: p changes sign over (a, b), which the end signs confirm.
    const std::optional<Sign> atA = nonzeroSignAt(p, a), atB = nonzeroSignAt(p, b);
    if (!atA || !atB || *atA == *atB) return false;
    roots.emplace_back(a, b);
    return true;
  }
  const double middle = 0.5 * (a + b);
  if (depth == kMaximumDepth || !(middle > a && middle < b) || !nonzeroSignAt(p, middle)) return false;
  return isolate(p, a, middle, depth + 1, roots) && isolate(p, middle, b, depth + 1, roots);
}

template <class T>
std::optional<std::vector<Interval>> isolateRoots(const Polynomial<T>& p, double low, double high) {
  if (p.size() < 2 || !certainSign(p.coefficients().back()) || *certainSign(p.coefficients().back()) == Sign::Zero) {
    return std::nullopt;  // the degree itself is uncertain
  }
  if (!nonzeroSignAt(p, low) || !nonzeroSignAt(p, high)) return std::nullopt;
  std::vector<Interval> roots;
  if (!isolate(p, low, high, 0, roots)) return std::nullopt;
  return roots;
}

}  // namespace

std::optional<std::vector<Interval>> isolateRootsInDoubles(const Polynomial<Interval>& p, double low, double high) {
  return isolateRoots(p, low, high);
}

std::optional<std::vector<Interval>> isolateRootsInDoubleDoubles(const Polynomial<DoubleDoubleInterval>& p, double low,
                                                                 double high) {
  return isolateRoots(p, low, high);
}

}  // namespace freespace::detail
