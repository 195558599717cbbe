// Random non-convex obstacles: star-shaped prisms at random heights.

#include <cmath>
#include <stdexcept>

#include "freespace/scenes/scene_generator.h"
#include "seeded_random.h"

namespace freespace {
namespace {

constexpr double kPi = 3.14159265358979323846;

double roundToSceneGrid(double value) { return std::round(value / kSceneGrid) * kSceneGrid; }

/// A star polygon: corners at increasing angles around `middle`, alternating between
/// an outer radius (50-70% of maxRadius) and an inner one (20-30%). Rounding a
/// corner to the grid moves it by less than 1/90 unit, which turns it by less than
/// 7 degrees about the middle when maxRadius >= 0.5: corners at least 36 degrees
/// apart keep their order, so the polygon stays star-shaped and simple.
Polygon2 randomStar(const Point2& middle, double maxRadius, detail::SeededRandom& random) {
  const auto points = static_cast<int>(random.integer(3, 5));
  const double firstAngle = 2 * kPi * static_cast<double>(random.integer(0, 99)) / 100;
  Polygon2 star;
  for (int k = 0; k < 2 * points; ++k) {
    const double percent =
        k % 2 == 0 ? static_cast<double>(random.integer(50, 70)) : static_cast<double>(random.integer(20, 30));
    const double radius = maxRadius * percent / 100;
    const double angle = firstAngle + kPi * k / points;
    star.push_back(middle +
                   Point2(roundToSceneGrid(radius * std::cos(angle)), roundToSceneGrid(radius * std::sin(angle))));
  }
  return star;
}

}  // namespace

TriangleSoup makeStarObstacles(const std::vector<Point2>& centres, double maxRadius, double maxTop,
                               std::uint64_t seed) {
  if (maxRadius < 0.5) throw std::invalid_argument("star obstacles: the radius must be at least 0.5");
  for (std::size_t i = 0; i < centres.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if ((centres[i] - centres[j]).norm() <= 2 * maxRadius) {
        throw std::invalid_argument("star obstacles: centres closer than two radii would overlap");
      }
    }
  }
  detail::SeededRandom random(seed);
  // The middle moves by at most a quarter radius; corners stay within 70% of the
  // radius plus the rounding, so each star stays inside its disc.
  const double shift = std::floor(maxRadius / 4 / kSceneGrid) * kSceneGrid;
  const double heightStep = roundToSceneGrid(maxTop / 4);
  std::vector<TriangleSoup> stars;
  for (const Point2& centre : centres) {
    const Point2 middle =
        centre + Point2(random.onGrid(-shift, shift, kSceneGrid), random.onGrid(-shift, shift, kSceneGrid));
    const Polygon2 outline = randomStar(middle, maxRadius, random);
    const double bottom = heightStep * static_cast<double>(random.integer(0, 2));
    const double top = bottom + heightStep * static_cast<double>(random.integer(1, 2));
    stars.push_back(extrudePolygon(outline, bottom, top));
  }
  return joinParts(stars);
}

}  // namespace freespace
