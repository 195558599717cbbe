#pragma once

#include <array>
#include <cstdint>

#include "freespace/geometry/mesh.h"
#include "freespace/geometry/mesh_topology.h"
#include "freespace/geometry/patch.h"
#include "freespace/numbers/angle_polynomial.h"

namespace freespace {

/// An end point of a patch's segment: a vertex of one body on an edge of the other,
/// a spiral point (docs/design.md section 3). Two patches share an end exactly when their
/// ends are equal, which is how shared spirals are recognised combinatorially.
struct SegmentEnd {
  /// True: a robot vertex on an environment edge; false: an environment vertex on a
  /// robot edge.
  bool robotVertex = true;
  std::uint32_t vertex = 0;
  /// The edge's end vertices in the other body, the smaller index first.
  std::array<std::uint32_t, 2> edge{};

  friend bool operator==(const SegmentEnd& a, const SegmentEnd& b) {
    return a.robotVertex == b.robotVertex && a.vertex == b.vertex && a.edge == b.edge;
  }
  friend bool operator!=(const SegmentEnd& a, const SegmentEnd& b) { return !(a == b); }
};

/// The two ends of a patch's segment at every angle of its range. They are ordered
/// so that ends[1] - ends[0] is the line's normal n = R a1 + a2 turned by +90
/// degrees: walking from ends[0] to ends[1], the free side (the line's positive
/// side) is on the right.
struct PatchSegment {
  std::array<SegmentEnd, 2> ends;
};

/// The input points of a segment end, copied from the meshes (a value: the angle
/// functions built from it outlive the meshes): the vertex and the edge's two ends.
struct SpiralPoints {
  bool robotVertex = true;
  std::array<Point3, 3> points;  // vertex, edge from, edge to
};

inline SpiralPoints spiralPoints(const SegmentEnd& end, const Mesh& robot, const Mesh& world) {
  const Mesh& vertexMesh = end.robotVertex ? robot : world;
  const Mesh& edgeMesh = end.robotVertex ? world : robot;
  return {end.robotVertex,
          {vertexMesh.vertices()[end.vertex], edgeMesh.vertices()[end.edge[0]], edgeMesh.vertices()[end.edge[1]]}};
}

/// The moving point of a segment end in number type T:
///   robot vertex p on environment edge e:  d = e(p_z)_xy - R p_xy
///   environment vertex q on robot edge f:  d = q_xy - R f(q_z)_xy
template <class T>
Spiral<T> spiralOf(const SpiralPoints& end) {
  const auto& [vertex, from, to] = end.points;
  return end.robotVertex ? spiralOfRobotVertexOnEdge<T>(vertex.data(), from.data(), to.data())
                         : spiralOfWorldVertexOnEdge<T>(vertex.data(), from.data(), to.data());
}

template <class T>
Spiral<T> spiralOf(const SegmentEnd& end, const Mesh& robot, const Mesh& world) {
  return spiralOf<T>(spiralPoints(end, robot, world));
}

/// The point d = u + R v of a spiral at the angle with the given cosine and sine.
template <class T>
std::array<T, 2> spiralPoint(const Spiral<T>& spiral, const T& cosine, const T& sine) {
  return {spiral.ux + cosine * spiral.vx - sine * spiral.vy, spiral.uy + sine * spiral.vx + cosine * spiral.vy};
}

/// The segment of a patch (docs/design.md section 3). At a fixed angle the contact points
/// of the two features lie at every height both features reach, so the segment
/// runs between the two heights where one feature's range ends:
///   VF: the cross-section of the environment triangle at the robot vertex's height
///       (its ends are the vertex on the two triangle edges crossing that height);
///   FV: the same with the bodies exchanged;
///   EE: the common height range of the two edges; each end is the vertex of the
///       edge that ends there on the other edge.
/// Requires every vertex height to differ from every other body's vertex heights
/// and each body's edges to be non-horizontal where they meet the other body's
/// heights (guaranteed by perturbation; see requireDistinctHeights). The ends are
/// ordered by the sign of an exact orientation, counted in `statistics`.
PatchSegment patchSegment(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                          const Mesh& world, const MeshTopology& worldTopology, PredicateStatistics& statistics);

/// Throws InputError naming `sceneName` unless every vertex height of the robot and
/// the environment is distinct from every other (the general position that
/// perturbation provides, docs/design.md section 5; the construction needs it).
void requireDistinctHeights(const Mesh& robot, const Mesh& world, const std::string& sceneName);

}  // namespace freespace
