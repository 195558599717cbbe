#include "polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace freespace::detail {
namespace {

/// A closed boundary as indices into the region's corner list.
using Ring = std::vector<std::uint32_t>;

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }
double orientation(const Point2& a, const Point2& b, const Point2& c) { return cross(b - a, c - a); }
int sign(double value) { return (value > 0) - (value < 0); }

/// Whether p, known to lie on the line through a and b, lies strictly between them.
bool strictlyBetween(const Point2& a, const Point2& b, const Point2& p) {
  return (p - a).dot(b - a) > 0 && (p - b).dot(a - b) > 0;
}

/// Whether segment cd meets segment ab anywhere but at a or b.
bool meetsAwayFromEnds(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int c_side = sign(orientation(a, b, c));
  const int d_side = sign(orientation(a, b, d));
  if (c_side * d_side < 0 && sign(orientation(c, d, a)) * sign(orientation(c, d, b)) < 0) return true;
  return (c_side == 0 && strictlyBetween(a, b, c)) || (d_side == 0 && strictlyBetween(a, b, d));
}

/// Whether the direction `d` leaves corner v of a boundary (coming from `previous`,
/// going to `next`, the region on the left) into the region.
bool entersRegion(const Point2& previous, const Point2& v, const Point2& next, const Point2& d) {
  const Point2 out = next - v;
  const Point2 back = previous - v;
  const double turn = cross(out, back);
  if (turn > 0) return cross(out, d) > 0 && cross(d, back) > 0;  // convex corner
  if (turn < 0) return cross(out, d) > 0 || cross(d, back) > 0;  // reflex corner
  return out.dot(back) < 0 && cross(out, d) > 0;                 // straight corner
}

class RegionTriangulator {
 public:
  RegionTriangulator(const Polygon2& outer, const std::vector<Polygon2>& holes) {
    ring_ = appendCorners(outer);
    for (const Polygon2& hole : holes) holes_.push_back(appendCorners(hole));
    // Bridging the hole that reaches furthest in +x first guarantees that some
    // vertex of the boundary built so far is visible from its rightmost corner.
    std::sort(holes_.begin(), holes_.end(),
              [&](const Ring& a, const Ring& b) { return at(a[rightmost(a)]).x() > at(b[rightmost(b)]).x(); });
  }

  std::vector<TriangleIndices> triangulate() {
    for (std::size_t h = 0; h < holes_.size(); ++h) bridgeHole(h);
    return clipEars();
  }

 private:
  Ring appendCorners(const Polygon2& polygon) {
    Ring ring;
    for (const Point2& corner : polygon) {
      ring.push_back(static_cast<std::uint32_t>(corners_.size()));
      corners_.push_back(corner);
    }
    return ring;
  }

  const Point2& at(std::uint32_t corner) const { return corners_[corner]; }

  /// The corner of `ring` with the largest x (then the largest y).
  std::size_t rightmost(const Ring& ring) const {
    auto key = [&](std::size_t i) { return std::make_pair(at(ring[i]).x(), at(ring[i]).y()); };
    std::size_t best = 0;
    for (std::size_t i = 1; i < ring.size(); ++i) {
      if (key(i) > key(best)) best = i;
    }
    return best;
  }

  static std::size_t before(const Ring& ring, std::size_t i) { return (i + ring.size() - 1) % ring.size(); }
  static std::size_t after(const Ring& ring, std::size_t i) { return (i + 1) % ring.size(); }

  /// Whether the segment from corner i of `ring` towards `target` starts into the region.
  bool headsIntoRegion(const Ring& ring, std::size_t i, const Point2& target) const {
    return entersRegion(at(ring[before(ring, i)]), at(ring[i]), at(ring[after(ring, i)]), target - at(ring[i]));
  }

  /// Whether the segment ab crosses or touches an edge of the boundary built so far
  /// or of a hole not yet bridged (holes_[firstOpenHole...]) away from a and b.
  bool blocked(const Point2& a, const Point2& b, std::size_t firstOpenHole) const {
    auto ringBlocks = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        if (meetsAwayFromEnds(a, b, at(ring[i]), at(ring[after(ring, i)]))) return true;
      }
      return false;
    };
    if (ringBlocks(ring_)) return true;
    return std::any_of(holes_.begin() + static_cast<std::ptrdiff_t>(firstOpenHole), holes_.end(), ringBlocks);
  }

  /// Joins hole h to the boundary by a bridge from its rightmost corner m to the
  /// nearest boundary corner v it sees; the boundary then runs
  /// ... v, m, (around the hole), m, v, ...
  void bridgeHole(std::size_t h) {
    const Ring& hole = holes_[h];
    const std::size_t m = rightmost(hole);
    const Point2& mPoint = at(hole[m]);
    std::vector<std::size_t> candidates(ring_.size());
    std::iota(candidates.begin(), candidates.end(), 0);
    std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
      return (at(ring_[a]) - mPoint).squaredNorm() < (at(ring_[b]) - mPoint).squaredNorm();
    });
    for (std::size_t v : candidates) {
      const Point2& vPoint = at(ring_[v]);
      if (vPoint == mPoint || !headsIntoRegion(ring_, v, mPoint) || !headsIntoRegion(hole, m, vPoint) ||
          blocked(mPoint, vPoint, h)) {
        continue;
      }
      Ring bridged(ring_.begin(), ring_.begin() + static_cast<std::ptrdiff_t>(v) + 1);
      for (std::size_t k = 0; k <= hole.size(); ++k) bridged.push_back(hole[(m + k) % hole.size()]);
      bridged.insert(bridged.end(), ring_.begin() + static_cast<std::ptrdiff_t>(v), ring_.end());
      ring_ = std::move(bridged);
      return;
    }
    throw std::logic_error("polygon triangulation: no boundary corner is visible from a hole");
  }

  /// Ear clipping on the bridged boundary. A corner is an ear when it is strictly
  /// convex and no other corner lies in or on its triangle (corners at the same
  /// place as the triangle's own, which bridges create, do not count).
  std::vector<TriangleIndices> clipEars() const {
    const std::size_t n = ring_.size();
    std::vector<std::size_t> previous(n);
    std::vector<std::size_t> next(n);
    for (std::size_t i = 0; i < n; ++i) {
      previous[i] = before(ring_, i);
      next[i] = after(ring_, i);
    }
    auto corner = [&](std::size_t i) -> const Point2& { return at(ring_[i]); };
    auto isEar = [&](std::size_t i) {
      const Point2& a = corner(previous[i]);
      const Point2& b = corner(i);
      const Point2& c = corner(next[i]);
      if (orientation(a, b, c) <= 0) return false;
      for (std::size_t j = next[next[i]]; j != previous[i]; j = next[j]) {
        const Point2& p = corner(j);
        if (p == a || p == b || p == c) continue;
        if (orientation(a, b, p) >= 0 && orientation(b, c, p) >= 0 && orientation(c, a, p) >= 0) return false;
      }
      return true;
    };

    std::vector<TriangleIndices> triangles;
    std::size_t current = 0;
    std::size_t remaining = n;
    std::size_t triedSinceLastEar = 0;
    while (remaining > 3) {
      if (isEar(current)) {
        triangles.push_back({ring_[previous[current]], ring_[current], ring_[next[current]]});
        next[previous[current]] = next[current];
        previous[next[current]] = previous[current];
        current = next[current];
        --remaining;
        triedSinceLastEar = 0;
      } else if (++triedSinceLastEar > remaining) {
        throw std::logic_error("polygon triangulation: no ear left (polygon not simple?)");
      } else {
        current = next[current];
      }
    }
    if (orientation(corner(previous[current]), corner(current), corner(next[current])) <= 0) {
      throw std::logic_error("polygon triangulation: degenerate last triangle");
    }
    triangles.push_back({ring_[previous[current]], ring_[current], ring_[next[current]]});
    return triangles;
  }

  std::vector<Point2> corners_;
  Ring ring_;
  std::vector<Ring> holes_;
};

}  // namespace

double twiceSignedArea(const Polygon2& polygon) {
  double sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) sum += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return sum;
}

Polygon2 counterClockwise(Polygon2 polygon) {
  if (twiceSignedArea(polygon) < 0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

Polygon2 clockwise(Polygon2 polygon) {
  if (twiceSignedArea(polygon) > 0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

std::vector<TriangleIndices> triangulateRegion(const Polygon2& outer, const std::vector<Polygon2>& holes) {
  double expectedArea = twiceSignedArea(outer);
  if (outer.size() < 3 || expectedArea <= 0) {
    throw std::logic_error("polygon triangulation: the outer polygon must be counter-clockwise");
  }
  for (const Polygon2& hole : holes) {
    const double holeArea = twiceSignedArea(hole);
    if (hole.size() < 3 || holeArea >= 0) throw std::logic_error("polygon triangulation: holes must be clockwise");
    expectedArea += holeArea;
  }
  std::vector<TriangleIndices> triangles = RegionTriangulator(outer, holes).triangulate();

  // Every triangle is counter-clockwise, so overlapping or missing pieces show in
  // the total area (exact for coordinates on the scene grid).
  std::vector<Point2> corners(outer);
  for (const Polygon2& hole : holes) corners.insert(corners.end(), hole.begin(), hole.end());
  double area = 0;
  for (const TriangleIndices& t : triangles) area += orientation(corners[t[0]], corners[t[1]], corners[t[2]]);
  if (std::abs(area - expectedArea) > 1e-9 * expectedArea) {
    throw std::logic_error("polygon triangulation: triangles do not cover the region exactly");
  }
  return triangles;
}

}  // namespace freespace::detail
