#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "freespace/geometry/cancellation.h"
#include "freespace/geometry/mesh.h"
#include "freespace/geometry/mesh_topology.h"
#include "freespace/numbers/algebraic_angle.h"
#include "freespace/numbers/angle_polynomial.h"

namespace freespace {

enum class ContactKind {
  VertexFacet,  // a robot vertex on an environment triangle
  FacetVertex,  // an environment vertex on a robot triangle
  EdgeEdge,     // a robot edge crossing an environment edge
};

/// The two features in contact (docs/design.md section 3): indices of a vertex, a
/// triangle or an edge (MeshTopology::edges()) of the robot and of the environment.
struct Contact {
  ContactKind kind = ContactKind::VertexFacet;
  std::uint32_t robot = 0;
  std::uint32_t world = 0;
  /// EE only: which side of N = (R u) x v the environment lies on, +1 or -1 (u and v
  /// run from each edge's `from` to its `to`); VF and FV: +1.
  int side = 1;
};

/// Whether two contacts are of one facet with two vertices of the other body (VF
/// with one environment triangle, or FV with one robot triangle): their lines have
/// the same normal n = R a1 + a2 at every angle (docs/design.md section 4), computed from
/// the same coordinates, so they are parallel at every angle.
inline bool shareFacet(const Contact& a, const Contact& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == ContactKind::VertexFacet) return a.world == b.world;
  if (a.kind == ContactKind::FacetVertex) return a.robot == b.robot;
  return false;
}

/// The input points that determine a contact's line, copied from the meshes (a
/// value: the angle functions built from it outlive the meshes):
///   VF: robot vertex p, environment triangle (q0, q1, q2)
///   FV: environment vertex q, robot triangle (p0, p1, p2)
///   EE: robot edge (a0, a1) and environment edge (b0, b1), from `from` to `to`.
struct ContactPoints {
  ContactKind kind = ContactKind::VertexFacet;
  int side = 1;
  std::array<Point3, 4> points;
  /// The points' vertex indices in their meshes.
  std::array<std::uint32_t, 4> vertices;
  /// The line in double intervals once computed (cacheApproximateLine), which
  /// lineOf<Interval> then returns instead of computing it again: it is asked for
  /// at every filtered predicate on the patch.
  std::optional<PatchLine<Interval>> approximateLine;
};

/// Computes and keeps the contact's line in double intervals.
void cacheApproximateLine(ContactPoints& contact);

ContactPoints contactPoints(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                            const Mesh& world, const MeshTopology& worldTopology);

/// The patch line of a contact as the signed contact function: positive on the free
/// side (docs/design.md section 3), with coefficients computed from the input points in
/// the number type T of the evaluation (instantiated for Interval, the
/// MultiprecisionInterval ladder and Rational):
///   VF, robot vertex p, environment triangle (q0, q1, q2), n = (q1 - q0) x (q2 - q0):
///     n . (R p + d - q0) = n_xy . d + (p x n) sin + (p . n)_xy cos + p_z n_z - n . q0
///   FV, environment vertex q, robot triangle (p0, p1, p2), m = (p1 - p0) x (p2 - p0):
///     (R m) . (q - R p0 - d) = -(R m_xy) . d + (m x q) sin + (m . q)_xy cos + m_z q_z - m . p0
///   EE, robot edge a0 + s u, environment edge b0 + s v, N = (R u) x v, side sigma:
///     -sigma N . (R a0 + d - b0); sigma N separates: the robot lies on its negative
///     side, the environment on its positive side.
template <class T>
PatchLine<T> lineOf(const ContactPoints& contact);
template <>
PatchLine<Interval> lineOf<Interval>(const ContactPoints& contact);

template <class T>
PatchLine<T> contactLine(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                         const Mesh& world, const MeshTopology& worldTopology) {
  return lineOf<T>(contactPoints(contact, robot, robotTopology, world, worldTopology));
}

/// A patch: the compatible contacts of one feature pair, over its range of angles.
struct Patch {
  Contact contact;
  AngleSet range;
};

/// Every VF and FV patch with a non-empty range. A VF contact needs a pointed robot
/// vertex strictly inside the triangle's z range and every robot edge leaving the
/// vertex pointing out of the triangle's plane, (R u) . n > 0; FV is the same with
/// the roles exchanged. Each condition is an EF angle function; the range is where
/// all are positive (closed).
std::vector<Patch> vertexFacetPatches(const Mesh& robot, const MeshTopology& robotTopology, const Mesh& world,
                                      const MeshTopology& worldTopology, AngleAlgebra& algebra,
                                      const Cancellation& cancellation = {});

/// Every EE patch with a non-empty range: a convex robot edge and a convex
/// environment edge whose open z ranges overlap, for each side sigma. With the
/// robot's face normals (m1, m2) and the environment's (n1, n2) ordered so that
/// det(u, m1, m2) > 0 and det(v, n1, n2) > 0, sigma N lies in the robot wedge's
/// normal cone and -sigma N in the environment's (their interiors are then apart)
/// exactly when
///   sigma (R m1) . v > 0, -sigma (R m2) . v > 0, sigma (R u) . n1 > 0, -sigma (R u) . n2 > 0
/// (from (a x b) . (c x d) = (a . c)(b . d) - (a . d)(b . c) and m_i . u = n_i . v = 0).
std::vector<Patch> edgeEdgePatches(const Mesh& robot, const MeshTopology& robotTopology, const Mesh& world,
                                   const MeshTopology& worldTopology, AngleAlgebra& algebra,
                                   const Cancellation& cancellation = {});

}  // namespace freespace
