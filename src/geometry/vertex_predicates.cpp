#include "vertex_predicates.h"

#include <cmath>
#include <optional>

#include "freespace/geometry/determinants.h"

namespace freespace::detail {

namespace {

/// The sign of a determinant evaluated in doubles (rounding to nearest) when its
/// rounding error, at most `errorFactor` times the permanent (the same sum over the
/// absolute values of its products), cannot reach zero; nothing near underflow, where
/// that bound does not hold, or for values that are not finite.
std::optional<Sign> certainInDoubles(double determinant, double permanent, double errorFactor) {
  constexpr double kSmallestPermanent = 1e-250;
  if (!(permanent > kSmallestPermanent) || !std::isfinite(permanent)) return std::nullopt;
  const double bound = errorFactor * permanent;
  if (determinant > bound) return Sign::Positive;
  if (determinant < -bound) return Sign::Negative;
  return std::nullopt;
}

// Forward error bounds of the 2x2 and 3x3 orientation determinants of coordinate
// differences in doubles (Shewchuk, "Adaptive precision floating-point arithmetic and
// fast robust geometric predicates", 1997: ccwerrboundA and o3derrboundA), with
// epsilon = 2^-53.
constexpr double kEpsilon = 0x1p-53;
constexpr double kOrient2dError = (3 + 16 * kEpsilon) * kEpsilon;
constexpr double kOrient3dError = (7 + 56 * kEpsilon) * kEpsilon;

/// Whether x * y - z * w of exact numbers is zero because each product has a zero
/// factor (a difference of doubles rounds to zero only when it is zero, so the
/// rounded differences answer for the exact ones). Points on axis-aligned walls are
/// decided here, without the slower stages.
bool productsVanish(double x, double y, double z, double w) { return (x == 0 || y == 0) && (z == 0 || w == 0); }

}  // namespace

/// The sign of a determinant written once over the vertices' coordinates, at
/// rising precision.
template <class Determinant>
Sign VertexPredicates::decide(const Determinant& determinant) {
  return engine_.sign(PredicateKind::Orientation, [&](auto numberType) {
    using T = typename decltype(numberType)::type;
    return determinant([&](std::uint32_t vertex) {
      const Point3& p = vertices_[vertex];
      return Vec3T<T>{T(p.x()), T(p.y()), T(p.z())};
    });
  });
}

Sign VertexPredicates::orient3d(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  const Point3 &pa = vertices_[a], b0 = vertices_[b] - pa, c0 = vertices_[c] - pa, d0 = vertices_[d] - pa;
  const double m1 = c0.y() * d0.z(), m2 = c0.z() * d0.y(), m3 = c0.x() * d0.z(), m4 = c0.z() * d0.x(),
               m5 = c0.x() * d0.y(), m6 = c0.y() * d0.x();
  const double determinant = b0.x() * (m1 - m2) - b0.y() * (m3 - m4) + b0.z() * (m5 - m6);
  const double permanent = std::abs(b0.x()) * (std::abs(m1) + std::abs(m2)) +
                           std::abs(b0.y()) * (std::abs(m3) + std::abs(m4)) +
                           std::abs(b0.z()) * (std::abs(m5) + std::abs(m6));
  if (const auto sign = certainInDoubles(determinant, permanent, kOrient3dError)) return *sign;
  if ((b0.x() == 0 || productsVanish(c0.y(), d0.z(), c0.z(), d0.y())) &&
      (b0.y() == 0 || productsVanish(c0.x(), d0.z(), c0.z(), d0.x())) &&
      (b0.z() == 0 || productsVanish(c0.x(), d0.y(), c0.y(), d0.x()))) {
    return Sign::Zero;
  }
  return decide([&](auto point) { return orient3dDeterminant(point(a), point(b), point(c), point(d)); });
}

Sign VertexPredicates::orient2d(std::uint32_t a, std::uint32_t b, std::uint32_t c, int droppedAxis) {
  const int u = (droppedAxis + 1) % 3, v = (droppedAxis + 2) % 3;
  const Point3 &pa = vertices_[a], b0 = vertices_[b] - pa, c0 = vertices_[c] - pa;
  const double left = b0[u] * c0[v], right = b0[v] * c0[u];
  if (const auto sign = certainInDoubles(left - right, std::abs(left) + std::abs(right), kOrient2dError)) {
    return *sign;
  }
  if (productsVanish(b0[u], c0[v], b0[v], c0[u])) return Sign::Zero;
  return decide([&](auto point) { return orient2dDeterminant(point(a), point(b), point(c), droppedAxis); });
}

Sign VertexPredicates::between(std::uint32_t a, std::uint32_t b, std::uint32_t c, int droppedAxis) {
  return decide([&](auto point) { return projectedBetweenDeterminant(point(a), point(b), point(c), droppedAxis); });
}

Sign VertexPredicates::compare(std::uint32_t a, std::uint32_t b, int axis) {
  return decide([&](auto point) { return point(a)[axis] - point(b)[axis]; });
}

}  // namespace freespace::detail
