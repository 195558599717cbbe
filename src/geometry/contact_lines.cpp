#include "contact_vectors.h"
#include "freespace/geometry/patch.h"

namespace freespace {

namespace {

using detail::cross;
using detail::dot;
using detail::difference;
using detail::pointOf;
using detail::rotatedDot;
using detail::Vector3T;

/// VF: n . (R p + d - q0) with points (p, q0, q1, q2).
template <class T>
PatchLine<T> vertexFacetLine(const ContactPoints& contact) {
  const Vector3T<T> p = pointOf<T>(contact.points[0]);
  const Vector3T<T> n = detail::normalOf<T>({contact.points[1], contact.points[2], contact.points[3]});
  const Vector3T<T> q0 = pointOf<T>(contact.points[1]);
  const TrigLinear<T> rotated = rotatedDot(p, n);
  return {T(0), T(0), n.x, n.y, rotated.s, rotated.c, rotated.k - dot(n, q0)};
}

/// FV: (R m) . (q - R p0 - d) with points (q, p0, p1, p2).
template <class T>
PatchLine<T> facetVertexLine(const ContactPoints& contact) {
  const Vector3T<T> q = pointOf<T>(contact.points[0]);
  const Vector3T<T> m = detail::normalOf<T>({contact.points[1], contact.points[2], contact.points[3]});
  const Vector3T<T> p0 = pointOf<T>(contact.points[1]);
  const TrigLinear<T> rotated = rotatedDot(m, q);
  return {-m.x, -m.y, T(0), T(0), rotated.s, rotated.c, rotated.k - dot(m, p0)};
}

/// EE with points (a0, a1, b0, b1): N_xy = R a1 + a2 with a1 = v_z (u_y, -u_x),
/// a2 = u_z (-v_y, v_x), and the constant
/// (R a0 - b0) . N = det(R a0, R u, v) - det(b0, R u, v)
///                 = (R (a0 x u)) . v - (R u) . (v x b0),
/// all multiplied by -sigma.
template <class T>
PatchLine<T> edgeEdgeLine(const ContactPoints& contact) {
  const Vector3T<T> a0 = pointOf<T>(contact.points[0]);
  const Vector3T<T> b0 = pointOf<T>(contact.points[2]);
  const Vector3T<T> u = difference(pointOf<T>(contact.points[1]), a0);
  const Vector3T<T> v = difference(pointOf<T>(contact.points[3]), b0);
  const TrigLinear<T> first = rotatedDot(cross(a0, u), v);
  const TrigLinear<T> second = rotatedDot(u, cross(v, b0));
  const T sign(-contact.side);
  return {sign * v.z * u.y,          -sign * v.z * u.x,         -sign * u.z * v.y,         sign * u.z * v.x,
          sign * (first.s - second.s), sign * (first.c - second.c), sign * (first.k - second.k)};
}

template <class T>
PatchLine<T> computedLine(const ContactPoints& contact) {
  switch (contact.kind) {
    case ContactKind::VertexFacet: return vertexFacetLine<T>(contact);
    case ContactKind::FacetVertex: return facetVertexLine<T>(contact);
    case ContactKind::EdgeEdge: break;
  }
  return edgeEdgeLine<T>(contact);
}

/// The contact's points, without the cached line.
ContactPoints pointsOfContact(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                              const Mesh& world, const MeshTopology& worldTopology);

}  // namespace

ContactPoints contactPoints(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                            const Mesh& world, const MeshTopology& worldTopology) {
  ContactPoints points = pointsOfContact(contact, robot, robotTopology, world, worldTopology);
  cacheApproximateLine(points);
  return points;
}

namespace {

ContactPoints pointsOfContact(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                            const Mesh& world, const MeshTopology& worldTopology) {
  const auto pointsOf = [&contact](const Mesh& first, std::array<std::uint32_t, 2> firstVertices, const Mesh& second,
                                   std::array<std::uint32_t, 2> secondVertices) {
    ContactPoints points{contact.kind, contact.side, {}, {}, std::nullopt};
    for (int i = 0; i < 2; ++i) {
      points.vertices[i] = firstVertices[i];
      points.points[i] = first.vertices()[firstVertices[i]];
      points.vertices[2 + i] = secondVertices[i];
      points.points[2 + i] = second.vertices()[secondVertices[i]];
    }
    return points;
  };
  const auto vertexAndFacet = [&contact](const Mesh& vertexMesh, std::uint32_t vertex, const Mesh& facetMesh,
                                         std::uint32_t triangle) {
    const TriangleIndices& t = facetMesh.triangles()[triangle];
    return ContactPoints{contact.kind,
                         contact.side,
                         {vertexMesh.vertices()[vertex], facetMesh.vertices()[t[0]], facetMesh.vertices()[t[1]],
                          facetMesh.vertices()[t[2]]},
                         {vertex, t[0], t[1], t[2]},
                         std::nullopt};
  };
  switch (contact.kind) {
    case ContactKind::VertexFacet: return vertexAndFacet(robot, contact.robot, world, contact.world);
    case ContactKind::FacetVertex: return vertexAndFacet(world, contact.world, robot, contact.robot);
    case ContactKind::EdgeEdge: break;
  }
  const MeshEdge& a = robotTopology.edges()[contact.robot];
  const MeshEdge& b = worldTopology.edges()[contact.world];
  return pointsOf(robot, {a.from, a.to}, world, {b.from, b.to});
}

}  // namespace

template <class T>
PatchLine<T> lineOf(const ContactPoints& contact) {
  return computedLine<T>(contact);
}

template <>
PatchLine<Interval> lineOf<Interval>(const ContactPoints& contact) {
  return contact.approximateLine ? *contact.approximateLine : computedLine<Interval>(contact);
}

void cacheApproximateLine(ContactPoints& contact) {
  const RoundingScope rounding;
  contact.approximateLine = computedLine<Interval>(contact);
}
template PatchLine<Rational> lineOf<Rational>(const ContactPoints&);
template PatchLine<DoubleDoubleInterval> lineOf<DoubleDoubleInterval>(const ContactPoints&);
// The adaptive engine's ladder, for predicates that use patch lines.
template PatchLine<MultiprecisionInterval<kMultiprecisionDigits[0]>> lineOf(const ContactPoints&);
template PatchLine<MultiprecisionInterval<kMultiprecisionDigits[1]>> lineOf(const ContactPoints&);
template PatchLine<MultiprecisionInterval<kMultiprecisionDigits[2]>> lineOf(const ContactPoints&);
template PatchLine<MultiprecisionInterval<kMultiprecisionDigits[3]>> lineOf(const ContactPoints&);

}  // namespace freespace
