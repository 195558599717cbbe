#pragma once

// The solid a triangle soup encloses (docs/design.md section 9); the
// exact arrangement behind it is in soup_complex.h.

#include <cstdint>
#include <utility>
#include <vector>

#include "freespace/geometry/mesh.h"

namespace freespace::detail {

/// A face that encloses nothing: the soup triangles it lies in (has area in) and a
/// box holding it.
struct OpenFace {
  std::vector<std::uint32_t> sourceTriangles;
  Box3 bounds;
};

/// The solid a soup encloses: the complement of the unbounded region of space
/// minus the faces (docs/design.md section 9).
struct EnclosedSolid {
  /// The faces between the solid and the unbounded region, turned to face it, as
  /// closed edge-manifold components: around an edge where several pieces of the
  /// solid meet, faces are paired across the solid, so pieces that touch along an
  /// edge or at a vertex are separate components. Each component has its own
  /// vertices (rounded to doubles): vertices are never shared between components.
  TriangleSoup boundary;
  std::vector<std::uint32_t> boundaryComponent;  // of each boundary triangle
  std::size_t components = 0;
  std::size_t separatedEdges = 0;     // edges where a component touched itself, its pieces moved apart
  std::size_t meetingPairs = 0;       // pairs of soup triangles meeting beyond shared vertices and edges
  std::size_t refinedTriangles = 0;   // soup triangles split along their intersections
  std::size_t boundedCells = 0;       // connected regions of space enclosed by the faces
  std::size_t internalFaces = 0;      // faces with the solid on both sides (dropped)
  std::size_t capFaces = 0;           // boundary faces that lie in caps
  /// Faces with the unbounded region on both sides (they enclose nothing).
  std::vector<OpenFace> openFaces;
};

/// The solid that a soup's triangles enclose, with caps for its planar openings
/// (faces a modeller left out, such as the bottoms of walls): in each plane where two
/// open edges (edges of one triangle) meet at an angle, the bounded regions that the
/// soup's edges in that plane cut out, that no triangle covers and that an open edge
/// borders, are offered as caps. A cap's pieces are kept only where they separate an
/// enclosed region from the outside, and only when caps make up less than half of
/// that region's boundary (a missing face of a convex piece always does; a courtyard
/// capped at its floor and its sky does not, and stays open); they are never counted
/// as open or internal. Points within `tolerance` of a plane count as lying
/// in it, and open faces no thicker than `tolerance` (slivers that float noise leaves
/// between faces meant to meet) are dropped without counting.
EnclosedSolid enclosedSolid(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
                            double tolerance);

}  // namespace freespace::detail
