#pragma once

// The arrangement of a triangle soup's triangles (docs/design.md section 9),
// in CGAL's filtered exact kernel: the project's own predicates decide signs
// of determinants of input coordinates, but refining triangles along their
// intersections needs new points (exact constructions), which CGAL provides.

#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <boost/variant/get.hpp>

#include "soup_enclosure.h"
#include "triangle_box_tree.h"

namespace freespace::detail {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = ExactKernel::Point_3;

/// The triangle on three of `points` (exact points by index).
template <class Points>
ExactKernel::Triangle_3 exactTriangle(const Points& points, const TriangleIndices& corners) {
  return {points[corners[0]], points[corners[1]], points[corners[2]]};
}

/// Whether CGAL's intersection of two triangles (one that is not empty) has an area:
/// a triangle or a polygon, where triangles in one plane overlap.
template <class Intersection>
bool hasArea(const Intersection& intersection) {
  return boost::get<ExactKernel::Triangle_3>(&intersection) || boost::get<std::vector<ExactPoint>>(&intersection);
}

/// A box in the soup's R-trees that holds exact points for certain (CGAL's boxes
/// enclose its lazy points), so every box of input doubles that may hold them meets it.
inline TreeBox boxAround(std::initializer_list<const ExactPoint*> points) {
  CGAL::Bbox_3 box;
  for (const ExactPoint* point : points) box += point->bbox();
  return {TreePoint(box.xmin(), box.ymin(), box.zmin()), TreePoint(box.xmax(), box.ymax(), box.zmax())};
}

/// Triangles that meet only in shared vertices and whole shared edges, covering the
/// same point set as the soup they come from: each soup triangle that meets another
/// beyond their shared features is split along the intersections (coplanar
/// triangles that overlap are triangulated together, so their common parts become
/// one face).
struct SoupComplex {
  static constexpr std::uint32_t kNoCluster = ~std::uint32_t{0};

  std::vector<ExactPoint> points;  // the soup's vertices (same indices), then new points
  std::vector<TriangleIndices> faces;
  std::vector<std::uint32_t> sourceTriangle;  // the soup triangle each face lies in (one of them, if several)
  /// A face of coplanar soup triangles triangulated together (they overlap, or
  /// continue one another across a seam: soup_seams.h) may lie in several of them:
  /// its cluster (an index into `clusters`, else kNoCluster), each cluster's soup
  /// triangles with their corners.
  std::vector<std::uint32_t> clusterOf;
  std::vector<std::vector<std::pair<std::uint32_t, TriangleIndices>>> clusters;
  std::size_t refinedTriangles = 0;  // soup triangles that were split
};

/// `pairs` lists every pair of the triangles (on `points`) that meet beyond their
/// shared features; the other triangles become faces as they are. The first points
/// are `vertices` (the soup's, in doubles); the others are new. Triangles from
/// `firstCap` on are caps, never the sides of a seam (soup_seams.h).
SoupComplex refineSoup(const std::vector<Point3>& vertices, const std::vector<ExactPoint>& points,
                       const std::vector<TriangleIndices>& triangles,
                       const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs, std::uint32_t firstCap);

/// Triangles that would close a soup's planar openings (see enclosedSolid), on the
/// soup's vertices and new points where its edges cross in the plane.
struct PlanarCaps {
  std::vector<ExactPoint> newPoints;  // numbered after the soup's vertices
  std::vector<TriangleIndices> triangles;
};

PlanarCaps planarCaps(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
                      double tolerance);

/// The pairs (i, j), i < j, of `triangles` on `points` that meet beyond their shared
/// vertices and edge, with i or j at least `firstCap`, decided exactly.
std::vector<std::pair<std::uint32_t, std::uint32_t>> capMeetingPairs(const std::vector<ExactPoint>& points,
                                                                     const std::vector<TriangleIndices>& triangles,
                                                                     std::uint32_t firstCap);

/// The solid a complex encloses; faces of soup triangles from `firstCap` on are caps
/// (see enclosedSolid in soup_enclosure.h).
EnclosedSolid enclosedSolid(const SoupComplex& complex, std::uint32_t firstCap, double tolerance);

}  // namespace freespace::detail
