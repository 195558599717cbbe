#pragma once

#include <cstdint>
#include <vector>

#include "freespace/geometry/mesh.h"
#include "freespace/numbers/adaptive_sign.h"
#include "freespace/numbers/predicate_statistics.h"

namespace freespace::detail {

/// Exact signs of the determinants of ClosedTriangleTests on mesh vertices: the
/// orientations filtered in doubles first, every sign then at rising precision. The
/// caller rounds to nearest (a NearestRoundingScope) while it asks.
class VertexPredicates {
 public:
  VertexPredicates(const std::vector<Point3>& vertices, PredicateStatistics& statistics)
      : vertices_(vertices), engine_(statistics) {}

  Sign orient3d(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d);
  Sign orient2d(std::uint32_t a, std::uint32_t b, std::uint32_t c, int droppedAxis);
  Sign between(std::uint32_t a, std::uint32_t b, std::uint32_t c, int droppedAxis);
  Sign compare(std::uint32_t a, std::uint32_t b, int axis);

 private:
  template <class Determinant>
  Sign decide(const Determinant& determinant);

  const std::vector<Point3>& vertices_;
  AdaptiveSignEngine engine_;
};

}  // namespace freespace::detail
