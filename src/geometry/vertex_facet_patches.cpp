#include <algorithm>
#include <array>

#include "freespace/geometry/patch.h"

namespace freespace {

namespace {

template <class T>
struct Vector3T {
  T x, y, z;
};

template <class T>
Vector3T<T> pointOf(const Point3& p) {
  return {T(p.x()), T(p.y()), T(p.z())};
}

template <class T>
Vector3T<T> difference(const Vector3T<T>& a, const Vector3T<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

/// (b - a) x (c - a): the outward normal of a triangle of a checked mesh.
template <class T>
Vector3T<T> triangleNormal(const Mesh& mesh, std::uint32_t triangle) {
  const TriangleIndices& t = mesh.triangles()[triangle];
  const Vector3T<T> a = pointOf<T>(mesh.vertices()[t[0]]);
  const Vector3T<T> u = difference(pointOf<T>(mesh.vertices()[t[1]]), a);
  const Vector3T<T> v = difference(pointOf<T>(mesh.vertices()[t[2]]), a);
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}

template <class T>
T dot(const Vector3T<T>& a, const Vector3T<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// (R a) . b = cos (a . b)_xy + sin (a x b)_xy + a_z b_z, as a form in sin and cos.
template <class T>
TrigLinear<T> rotatedDot(const Vector3T<T>& a, const Vector3T<T>& b) {
  return {a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y, a.z * b.z};
}

/// The compatibility condition "the edge from `vertex` to `other` of the moving
/// mesh (robot) or the fixed one points out of the other body's facet plane" as an
/// angle function: (R u) . n > 0 for a robot edge u and environment normal n,
/// (R m) . v > 0 for a robot normal m and environment edge v.
std::shared_ptr<const AngleFunction> edgeOutOfFacet(const Contact& contact, const Mesh& robot, const Mesh& world,
                                                    std::uint32_t vertex, std::uint32_t other) {
  return std::make_shared<AngleFunction>([contact, &robot, &world, vertex, other](auto type, int chart) {
    using T = typename decltype(type)::type;
    if (contact.kind == ContactKind::VertexFacet) {
      const auto u = difference(pointOf<T>(robot.vertices()[other]), pointOf<T>(robot.vertices()[vertex]));
      return tangentPolynomial(rotatedDot(u, triangleNormal<T>(world, contact.world)), chart);
    }
    const auto v = difference(pointOf<T>(world.vertices()[other]), pointOf<T>(world.vertices()[vertex]));
    return tangentPolynomial(rotatedDot(triangleNormal<T>(robot, contact.robot), v), chart);
  });
}

/// Whether z lies strictly between the lowest and highest vertex of the triangle.
bool strictlyWithinHeights(const Mesh& mesh, std::uint32_t triangle, double z) {
  const TriangleIndices& t = mesh.triangles()[triangle];
  const double low = std::min({mesh.vertices()[t[0]].z(), mesh.vertices()[t[1]].z(), mesh.vertices()[t[2]].z()});
  const double high = std::max({mesh.vertices()[t[0]].z(), mesh.vertices()[t[1]].z(), mesh.vertices()[t[2]].z()});
  return low < z && z < high;
}

/// The patches of one body's pointed vertices against the other body's triangles.
void addPatches(ContactKind kind, const Mesh& vertexMesh, const MeshTopology& vertexTopology, const Mesh& facetMesh,
                const Mesh& robot, const Mesh& world, AngleAlgebra& algebra, std::vector<Patch>& patches) {
  for (std::uint32_t vertex = 0; vertex < vertexMesh.vertices().size(); ++vertex) {
    if (!vertexTopology.isPointed(vertex)) continue;
    const double z = vertexMesh.vertices()[vertex].z();
    for (std::uint32_t triangle = 0; triangle < facetMesh.triangles().size(); ++triangle) {
      if (!strictlyWithinHeights(facetMesh, triangle, z)) continue;
      const Contact contact = kind == ContactKind::VertexFacet ? Contact{kind, vertex, triangle}
                                                               : Contact{kind, triangle, vertex};
      std::vector<std::shared_ptr<const AngleFunction>> conditions;
      for (std::uint32_t edge : vertexTopology.vertexEdges(vertex)) {
        conditions.push_back(edgeOutOfFacet(contact, robot, world, vertex, vertexTopology.otherEnd(edge, vertex)));
      }
      AngleSet range = algebra.positiveSet(conditions, PredicateKind::EdgeFacet);
      if (!range.empty()) patches.push_back({contact, std::move(range)});
    }
  }
}

}  // namespace

template <class T>
PatchLine<T> contactLine(const Contact& contact, const Mesh& robot, const Mesh& world) {
  if (contact.kind == ContactKind::VertexFacet) {
    const TriangleIndices& facet = world.triangles()[contact.world];
    const Vector3T<T> p = pointOf<T>(robot.vertices()[contact.robot]);
    const Vector3T<T> n = triangleNormal<T>(world, contact.world);
    const TrigLinear<T> rotated = rotatedDot(p, n);
    return {T(0), T(0), n.x, n.y, rotated.s, rotated.c, rotated.k - dot(n, pointOf<T>(world.vertices()[facet[0]]))};
  }
  const TriangleIndices& facet = robot.triangles()[contact.robot];
  const Vector3T<T> q = pointOf<T>(world.vertices()[contact.world]);
  const Vector3T<T> m = triangleNormal<T>(robot, contact.robot);
  const TrigLinear<T> rotated = rotatedDot(m, q);
  return {-m.x, -m.y, T(0), T(0), rotated.s, rotated.c, rotated.k - dot(m, pointOf<T>(robot.vertices()[facet[0]]))};
}

template PatchLine<double> contactLine<double>(const Contact&, const Mesh&, const Mesh&);
template PatchLine<Interval> contactLine<Interval>(const Contact&, const Mesh&, const Mesh&);
template PatchLine<Rational> contactLine<Rational>(const Contact&, const Mesh&, const Mesh&);

std::vector<Patch> vertexFacetPatches(const Mesh& robot, const MeshTopology& robotTopology, const Mesh& world,
                                      const MeshTopology& worldTopology, AngleAlgebra& algebra) {
  std::vector<Patch> patches;
  addPatches(ContactKind::VertexFacet, robot, robotTopology, world, robot, world, algebra, patches);
  addPatches(ContactKind::FacetVertex, world, worldTopology, robot, robot, world, algebra, patches);
  return patches;
}

}  // namespace freespace
