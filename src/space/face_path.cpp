#include "freespace/space/face_path.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <deque>
#include <map>

namespace freespace {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
/// Each triangle keeps how many of the face's loops lie around it (-1: not yet known).
using FaceBase =
    CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>;
using Triangulation = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<Kernel>, FaceBase>,
    CGAL::Exact_intersections_tag>;
using Face = Triangulation::Face_handle;

Kernel::Point_2 pointOf(const std::array<double, 2>& p) { return {p[0], p[1]}; }

/// Flood fill from the infinite face: a triangle's nesting level is the number of
/// constraints crossed to reach it.
void markNesting(Triangulation& triangulation) {
  for (Face face : triangulation.all_face_handles()) face->info() = -1;
  std::deque<std::pair<Face, int>> border{{triangulation.infinite_face(), 0}};
  while (!border.empty()) {
    const auto [start, level] = border.front();
    border.pop_front();
    if (start->info() != -1) continue;
    std::deque<Face> queue{start};
    start->info() = level;
    while (!queue.empty()) {
      const Face face = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        const Face next = face->neighbor(i);
        if (next->info() != -1) continue;
        if (face->is_constrained(i)) {
          border.push_back({next, level + 1});
        } else {
          next->info() = level;
          queue.push_back(next);
        }
      }
    }
  }
}

}  // namespace

std::optional<std::vector<std::array<double, 2>>> pathInFace(const SliceFace& face, const std::array<double, 2>& from,
                                                             const std::array<double, 2>& to) {
  if (face.loops.empty()) return std::vector<std::array<double, 2>>{from, to};
  Triangulation triangulation;
  for (const SliceLoop& loop : face.loops) {
    for (std::size_t i = 0; i < loop.corners.size(); ++i) {
      const auto& a = loop.corners[i];
      const auto& b = loop.corners[(i + 1) % loop.corners.size()];
      if (a != b) triangulation.insert_constraint(pointOf(a), pointOf(b));
    }
  }
  // Corners of a box around everything, so that both ends lie inside the hull (the
  // unbounded face reaches past its loops).
  double low[2] = {std::min(from[0], to[0]), std::min(from[1], to[1])};
  double high[2] = {std::max(from[0], to[0]), std::max(from[1], to[1])};
  for (const SliceLoop& loop : face.loops) {
    for (const auto& corner : loop.corners) {
      for (int axis : {0, 1})
        low[axis] = std::min(low[axis], corner[axis]), high[axis] = std::max(high[axis], corner[axis]);
    }
  }
  const double margin = 1 + (high[0] - low[0]) + (high[1] - low[1]);
  for (const double x : {low[0] - margin, high[0] + margin}) {
    for (const double y : {low[1] - margin, high[1] + margin}) triangulation.insert(Kernel::Point_2(x, y));
  }
  markNesting(triangulation);
  const int inside = face.unbounded ? 0 : 1;
  const auto inFace = [&](Face f) { return !triangulation.is_infinite(f) && f->info() == inside; };
  const Face first = triangulation.locate(pointOf(from)), last = triangulation.locate(pointOf(to));
  if (!inFace(first) || !inFace(last)) return std::nullopt;
  // Breadth-first over the triangles of the face, across edges off its boundary.
  std::map<Face, std::pair<Face, int>> reachedFrom{{first, {first, -1}}};
  std::deque<Face> queue{first};
  while (!queue.empty() && !reachedFrom.count(last)) {
    const Face f = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i) {
      const Face next = f->neighbor(i);
      if (f->is_constrained(i) || !inFace(next) || reachedFrom.count(next)) continue;
      reachedFrom[next] = {f, i};
      queue.push_back(next);
    }
  }
  if (!reachedFrom.count(last)) return std::nullopt;
  std::vector<std::array<double, 2>> path{to};
  for (Face at = last; at != first;) {
    const auto [previous, edge] = reachedFrom.at(at);
    const Kernel::Point_2 a = previous->vertex(Triangulation::cw(edge))->point();
    const Kernel::Point_2 b = previous->vertex(Triangulation::ccw(edge))->point();
    path.push_back({CGAL::to_double((a.x() + b.x()) / 2), CGAL::to_double((a.y() + b.y()) / 2)});
    at = previous;
  }
  path.push_back(from);
  return std::vector<std::array<double, 2>>(path.rbegin(), path.rend());
}

}  // namespace freespace
