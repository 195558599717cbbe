#include "rectangle_union.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "polygon_triangulation.h"

namespace freespace::detail {
namespace {

std::vector<double> sortedUnique(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

std::size_t indexOf(const std::vector<double>& sorted, double value) {
  return static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), value) - sorted.begin());
}

/// The union rasterised on the grid of all rectangle coordinates: cell (i, j) spans
/// [xs[i], xs[i+1]] x [ys[j], ys[j+1]] and is either inside the union or outside.
class UnionGrid {
 public:
  explicit UnionGrid(const std::vector<Box2>& rectangles) {
    std::vector<double> xs, ys;
    for (const Box2& r : rectangles) {
      if (r.isEmpty() || r.volume() <= 0) continue;
      xs.insert(xs.end(), {r.min().x(), r.max().x()});
      ys.insert(ys.end(), {r.min().y(), r.max().y()});
    }
    xs_ = sortedUnique(xs);
    ys_ = sortedUnique(ys);
    inside_.assign(cellColumns() * cellRows(), false);
    for (const Box2& r : rectangles) {
      if (r.isEmpty() || r.volume() <= 0) continue;
      for (std::size_t i = indexOf(xs_, r.min().x()); i < indexOf(xs_, r.max().x()); ++i) {
        for (std::size_t j = indexOf(ys_, r.min().y()); j < indexOf(ys_, r.max().y()); ++j) inside_[cell(i, j)] = true;
      }
    }
  }

  std::size_t cellColumns() const { return xs_.empty() ? 0 : xs_.size() - 1; }
  std::size_t cellRows() const { return ys_.empty() ? 0 : ys_.size() - 1; }

  /// Cells outside the grid count as outside the union.
  bool inside(std::ptrdiff_t i, std::ptrdiff_t j) const {
    if (i < 0 || j < 0 || i >= static_cast<std::ptrdiff_t>(cellColumns()) ||
        j >= static_cast<std::ptrdiff_t>(cellRows())) {
      return false;
    }
    return inside_[cell(static_cast<std::size_t>(i), static_cast<std::size_t>(j))];
  }

  Point2 gridPoint(std::size_t i, std::size_t j) const { return {xs_[i], ys_[j]}; }

 private:
  std::size_t cell(std::size_t i, std::size_t j) const { return i * cellRows() + j; }

  std::vector<double> xs_;
  std::vector<double> ys_;
  std::vector<bool> inside_;
};

using GridPoint = std::pair<std::size_t, std::size_t>;

/// Unit edges of the grid between a cell inside and a cell outside the union,
/// directed with the inside on the left, keyed by their start point.
std::map<GridPoint, GridPoint> boundaryEdges(const UnionGrid& grid) {
  std::map<GridPoint, GridPoint> edges;
  auto add = [&](GridPoint from, GridPoint to) {
    if (!edges.emplace(from, to).second) {
      throw std::invalid_argument("rectangle union: pieces touch at a single corner");
    }
  };
  for (std::size_t i = 0; i < grid.cellColumns(); ++i) {
    for (std::size_t j = 0; j < grid.cellRows(); ++j) {
      const auto si = static_cast<std::ptrdiff_t>(i);
      const auto sj = static_cast<std::ptrdiff_t>(j);
      if (!grid.inside(si, sj)) continue;
      if (!grid.inside(si, sj - 1)) add({i, j}, {i + 1, j});
      if (!grid.inside(si + 1, sj)) add({i + 1, j}, {i + 1, j + 1});
      if (!grid.inside(si, sj + 1)) add({i + 1, j + 1}, {i, j + 1});
      if (!grid.inside(si - 1, sj)) add({i, j + 1}, {i, j});
    }
  }
  return edges;
}

/// Chains the boundary edges into closed outlines, keeping only the corners where
/// the outline turns.
std::vector<Polygon2> traceOutlines(const UnionGrid& grid, std::map<GridPoint, GridPoint> edges) {
  std::vector<Polygon2> outlines;
  while (!edges.empty()) {
    std::vector<GridPoint> loop;
    GridPoint at = edges.begin()->first;
    while (edges.count(at) != 0) {
      loop.push_back(at);
      const GridPoint next = edges.at(at);
      edges.erase(at);
      at = next;
    }
    Polygon2 outline;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Point2 previous = grid.gridPoint(loop[(k + loop.size() - 1) % loop.size()].first,
                                             loop[(k + loop.size() - 1) % loop.size()].second);
      const Point2 here = grid.gridPoint(loop[k].first, loop[k].second);
      const Point2 next = grid.gridPoint(loop[(k + 1) % loop.size()].first, loop[(k + 1) % loop.size()].second);
      const Point2 in = here - previous;
      const Point2 out = next - here;
      if (in.x() * out.y() - in.y() * out.x() != 0) outline.push_back(here);
    }
    outlines.push_back(std::move(outline));
  }
  return outlines;
}

/// Crossing-number test for a point that is not on the polygon's boundary.
bool strictlyInside(const Polygon2& polygon, const Point2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace

std::vector<PolygonWithHoles> rectangleUnionRegions(const std::vector<Box2>& rectangles) {
  const UnionGrid grid(rectangles);
  std::vector<PolygonWithHoles> regions;
  std::vector<Polygon2> holes;
  for (Polygon2& outline : traceOutlines(grid, boundaryEdges(grid))) {
    if (twiceSignedArea(outline) > 0) {
      regions.push_back({std::move(outline), {}});
    } else {
      holes.push_back(std::move(outline));
    }
  }
  // A hole belongs to the smallest outer outline around it. Outlines never share a
  // corner, so any corner of the hole tells.
  for (Polygon2& hole : holes) {
    PolygonWithHoles* owner = nullptr;
    for (PolygonWithHoles& region : regions) {
      if (strictlyInside(region.outer, hole.front()) &&
          (owner == nullptr || twiceSignedArea(region.outer) < twiceSignedArea(owner->outer))) {
        owner = &region;
      }
    }
    if (owner == nullptr) throw std::logic_error("rectangle union: a hole outside every outline");
    owner->holes.push_back(std::move(hole));
  }
  return regions;
}

}  // namespace freespace::detail
