#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace freespace {

using Point3 = Eigen::Vector3d;
using TriangleIndices = std::array<std::uint32_t, 3>;
using Box3 = Eigen::AlignedBox3d;

/// Triangles as read from a file, before any checking: vertex positions (all node
/// transforms applied) and index triples into them. Vertices may be duplicated.
struct TriangleSoup {
  std::vector<Point3> vertices;
  std::vector<TriangleIndices> triangles;
  /// Optional: the object of the file each triangle belongs to (a mesh of a COLLADA
  /// node, a group of an OBJ file), numbered from 0; empty when not known.
  std::vector<std::uint32_t> pieces = {};
};

/// How Mesh::fromSoup tells which triangles share a vertex.
enum class VertexWelding {
  identicalPositions,  // vertices at the same position are one vertex
  asIndexed,           // by index only: copies of a point stay apart (interpretSolid's components)
};

/// Whether Mesh::fromSoup checks that no component's surface meets itself (the
/// costliest check), or the caller has (interpretSolid does).
enum class SelfIntersectionCheck { perform, alreadyDone };

/// A checked triangle mesh: finite coordinates, identical vertices welded, no
/// zero-area triangle, a closed edge-manifold surface, every connected component
/// consistently oriented with outward normals (a component that was inside-out is
/// flipped), no component whose surface meets itself (two of its triangles crossing
/// or touching away from the vertices they share). The solid it bounds is the union
/// of the solids of its components, which may overlap.
///
/// Numbering, in the result and in error messages (all 0-based):
/// - a non-finite coordinate and an index out of range are reported with the soup's
///   own vertex index (they are found before welding);
/// - every other vertex index is an index into vertices(): the welded vertices, i.e.
///   the distinct positions used by some triangle, ordered by their first appearance
///   in the soup's vertex list (a file whose vertices are distinct and all used keeps
///   its numbering); messages also give the coordinates of the vertices they name;
/// - triangles keep the soup's order, so a triangle number is its position in the
///   soup (and in triangles());
/// - components are numbered in the order of their first triangle.
class Mesh {
 public:
  Mesh() = default;

  /// Checks and cleans a soup. Throws InputError naming `sourceName` and the defect.
  /// Repairs that change the input (flipped components) are appended to `warnings`.
  /// With VertexWelding::asIndexed the soup's vertex indices say which triangles
  /// share vertices (unused vertices are dropped) and no positions are merged.
  static Mesh fromSoup(const TriangleSoup& soup, const std::string& sourceName,
                       std::vector<std::string>* warnings = nullptr,
                       VertexWelding welding = VertexWelding::identicalPositions,
                       SelfIntersectionCheck selfIntersection = SelfIntersectionCheck::perform);

  const std::vector<Point3>& vertices() const { return vertices_; }
  const std::vector<TriangleIndices>& triangles() const { return triangles_; }

  std::size_t componentCount() const { return componentBounds_.size(); }
  /// Connected component (through shared edges) of each triangle.
  const std::vector<std::uint32_t>& triangleComponents() const { return triangleComponent_; }
  /// One vertex index of each component.
  const std::vector<std::uint32_t>& componentRepresentatives() const { return componentVertex_; }
  const std::vector<Box3>& componentBounds() const { return componentBounds_; }
  Box3 bounds() const;
  /// The largest distance of a vertex from the vertical axis x = y = 0: how far a
  /// point of the body moves per radian it turns about that axis.
  double horizontalReach() const;

  /// Sum of the absolute enclosed volumes of the components.
  double volume() const;
  /// The same mesh moved by (dx, dy, dz), with the same vertices; the result is
  /// checked again.
  Mesh translated(const Point3& offset, const std::string& sourceName) const;

 private:
  std::vector<Point3> vertices_;
  std::vector<TriangleIndices> triangles_;
  std::vector<std::uint32_t> triangleComponent_;
  std::vector<std::uint32_t> componentVertex_;
  std::vector<Box3> componentBounds_;
  std::vector<double> componentVolume_;
};

}  // namespace freespace
