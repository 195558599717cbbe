#include "contact_vectors.h"
#include "freespace/geometry/patch.h"

namespace freespace {

namespace {

using detail::cross;
using detail::dot;
using detail::edgeVector;
using detail::pointOf;
using detail::rotatedDot;
using detail::triangleNormal;
using detail::Vector3T;

template <class T>
PatchLine<T> vertexFacetLine(const Contact& contact, const Mesh& robot, const Mesh& world) {
  const Vector3T<T> p = pointOf<T>(robot.vertices()[contact.robot]);
  const Vector3T<T> n = triangleNormal<T>(world, contact.world);
  const Vector3T<T> q0 = pointOf<T>(world.vertices()[world.triangles()[contact.world][0]]);
  const TrigLinear<T> rotated = rotatedDot(p, n);
  return {T(0), T(0), n.x, n.y, rotated.s, rotated.c, rotated.k - dot(n, q0)};
}

template <class T>
PatchLine<T> facetVertexLine(const Contact& contact, const Mesh& robot, const Mesh& world) {
  const Vector3T<T> q = pointOf<T>(world.vertices()[contact.world]);
  const Vector3T<T> m = triangleNormal<T>(robot, contact.robot);
  const Vector3T<T> p0 = pointOf<T>(robot.vertices()[robot.triangles()[contact.robot][0]]);
  const TrigLinear<T> rotated = rotatedDot(m, q);
  return {-m.x, -m.y, T(0), T(0), rotated.s, rotated.c, rotated.k - dot(m, p0)};
}

/// N_xy = R a1 + a2 with a1 = v_z (u_y, -u_x), a2 = u_z (-v_y, v_x), and the constant
/// (R a0 - b0) . N = det(R a0, R u, v) - det(b0, R u, v)
///                 = (R (a0 x u)) . v - (R u) . (v x b0),
/// all multiplied by -sigma.
template <class T>
PatchLine<T> edgeEdgeLine(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                          const Mesh& world, const MeshTopology& worldTopology) {
  const MeshEdge& robotEdge = robotTopology.edges()[contact.robot];
  const MeshEdge& worldEdge = worldTopology.edges()[contact.world];
  const Vector3T<T> a0 = pointOf<T>(robot.vertices()[robotEdge.from]);
  const Vector3T<T> b0 = pointOf<T>(world.vertices()[worldEdge.from]);
  const Vector3T<T> u = edgeVector<T>(robot, robotEdge.from, robotEdge.to);
  const Vector3T<T> v = edgeVector<T>(world, worldEdge.from, worldEdge.to);
  const TrigLinear<T> first = rotatedDot(cross(a0, u), v);
  const TrigLinear<T> second = rotatedDot(u, cross(v, b0));
  const T sign(-contact.side);
  return {sign * v.z * u.y,          -sign * v.z * u.x,         -sign * u.z * v.y,         sign * u.z * v.x,
          sign * (first.s - second.s), sign * (first.c - second.c), sign * (first.k - second.k)};
}

}  // namespace

template <class T>
PatchLine<T> contactLine(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                         const Mesh& world, const MeshTopology& worldTopology) {
  switch (contact.kind) {
    case ContactKind::VertexFacet: return vertexFacetLine<T>(contact, robot, world);
    case ContactKind::FacetVertex: return facetVertexLine<T>(contact, robot, world);
    case ContactKind::EdgeEdge: break;
  }
  return edgeEdgeLine<T>(contact, robot, robotTopology, world, worldTopology);
}

template PatchLine<Interval> contactLine<Interval>(const Contact&, const Mesh&, const MeshTopology&, const Mesh&,
                                                   const MeshTopology&);
template PatchLine<Rational> contactLine<Rational>(const Contact&, const Mesh&, const MeshTopology&, const Mesh&,
                                                   const MeshTopology&);
// The adaptive engine's ladder, for predicates that use patch lines.
template PatchLine<MultiprecisionInterval<kMultiprecisionDigits[0]>> contactLine(const Contact&, const Mesh&,
                                                                                 const MeshTopology&, const Mesh&,
                                                                                 const MeshTopology&);
template PatchLine<MultiprecisionInterval<kMultiprecisionDigits[1]>> contactLine(const Contact&, const Mesh&,
                                                                                 const MeshTopology&, const Mesh&,
                                                                                 const MeshTopology&);
template PatchLine<MultiprecisionInterval<kMultiprecisionDigits[2]>> contactLine(const Contact&, const Mesh&,
                                                                                 const MeshTopology&, const Mesh&,
                                                                                 const MeshTopology&);
template PatchLine<MultiprecisionInterval<kMultiprecisionDigits[3]>> contactLine(const Contact&, const Mesh&,
                                                                                 const MeshTopology&, const Mesh&,
                                                                                 const MeshTopology&);

}  // namespace freespace
