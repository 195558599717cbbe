#include <algorithm>
#include <array>

#include "angle_bounds.h"
#include "contact_vectors.h"
#include "freespace/geometry/patch.h"
#include "freespace/numbers/trig_linear_function.h"

namespace freespace {

namespace {

using detail::difference;
using detail::pointOf;
using detail::rotatedDot;

/// The compatibility condition "the edge from `vertex` to `other` points out of
/// the other body's facet plane" as an angle function: (R u) . n > 0 for a robot
/// edge u and an environment facet normal n, (R m) . v > 0 for a robot facet normal
/// m and an environment edge v. Coordinates are copied: the function outlives the
/// meshes in the patches' angles. `key` names the edge and the facet (see
/// detail::edgeFacetKey).
template <class T>
TrigLinear<T> edgeOutOfFacetForm(ContactKind kind, const Point3& vertex, const Point3& other,
                                 const detail::Corners& facet) {
  const auto edge = difference(pointOf<T>(other), pointOf<T>(vertex));
  const auto normal = detail::normalOf<T>(facet);
  return kind == ContactKind::VertexFacet ? rotatedDot(edge, normal) : rotatedDot(normal, edge);
}

/// The condition as an angle function, given its form in double intervals
/// (edgeOutOfFacetForm<Interval>, already computed for the quick test).
std::shared_ptr<const AngleFunction> edgeOutOfFacet(ContactKind kind, const Point3& vertex, const Point3& other,
                                                    const detail::Corners& facet, AngleFunction::RootKey key,
                                                    const TrigLinear<Interval>& approximateForm) {
  const auto form = [kind, vertex, other, facet](auto type) {
    using T = typename decltype(type)::type;
    return edgeOutOfFacetForm<T>(kind, vertex, other, facet);
  };
  return trigLinearFunction(form, key, approximateForm);
}

/// Whether z lies strictly between the lowest and highest vertex of the triangle.
bool strictlyWithinHeights(const Mesh& mesh, std::uint32_t triangle, double z) {
  const TriangleIndices& t = mesh.triangles()[triangle];
  const double low = std::min({mesh.vertices()[t[0]].z(), mesh.vertices()[t[1]].z(), mesh.vertices()[t[2]].z()});
  const double high = std::max({mesh.vertices()[t[0]].z(), mesh.vertices()[t[1]].z(), mesh.vertices()[t[2]].z()});
  return low < z && z < high;
}

/// The conditions' forms in double intervals, one per edge at the vertex (in the
/// order of vertexEdges).
std::vector<TrigLinear<Interval>> conditionForms(ContactKind kind, const Mesh& vertexMesh,
                                                 const MeshTopology& vertexTopology, std::uint32_t vertex,
                                                 const detail::Corners& facet) {
  std::vector<TrigLinear<Interval>> forms;
  RoundingScope rounding;
  for (std::uint32_t edge : vertexTopology.vertexEdges(vertex)) {
    const std::uint32_t other = vertexTopology.otherEnd(edge, vertex);
    forms.push_back(edgeOutOfFacetForm<Interval>(kind, vertexMesh.vertices()[vertex], vertexMesh.vertices()[other], facet));
  }
  return forms;
}

/// Whether every edge at the vertex may point out of the facet's plane at once at
/// some angle, from the conditions' forms (decided in doubles over ranges of angles;
/// true when unsure).
bool mayBeCompatible(const std::vector<TrigLinear<Interval>>& forms) {
  return detail::signPatternMayHold(detail::signMasksOf(forms), std::vector<Sign>(forms.size(), Sign::Positive));
}

/// The patches of one body's pointed vertices against the other body's triangles.
void addPatches(ContactKind kind, const Mesh& vertexMesh, const MeshTopology& vertexTopology, const Mesh& facetMesh,
                AngleAlgebra& algebra, const Cancellation& cancellation, std::vector<Patch>& patches) {
  for (std::uint32_t vertex = 0; vertex < vertexMesh.vertices().size(); ++vertex) {
    if (!vertexTopology.isPointed(vertex)) continue;
    const double z = vertexMesh.vertices()[vertex].z();
    for (std::uint32_t triangle = 0; triangle < facetMesh.triangles().size(); ++triangle) {
      cancellation.check();
      if (!strictlyWithinHeights(facetMesh, triangle, z)) continue;
      const Contact contact = kind == ContactKind::VertexFacet ? Contact{kind, vertex, triangle}
                                                               : Contact{kind, triangle, vertex};
      const detail::Corners facet = detail::cornersOf(facetMesh, triangle);
      const std::vector<TrigLinear<Interval>> forms = conditionForms(kind, vertexMesh, vertexTopology, vertex, facet);
      if (!mayBeCompatible(forms)) continue;
      std::vector<std::shared_ptr<const AngleFunction>> conditions;
      for (std::uint32_t edge : vertexTopology.vertexEdges(vertex)) {
        const std::uint32_t other = vertexTopology.otherEnd(edge, vertex);
        conditions.push_back(edgeOutOfFacet(kind, vertexMesh.vertices()[vertex], vertexMesh.vertices()[other], facet,
                                            detail::edgeFacetKey(kind == ContactKind::VertexFacet, vertex, other,
                                                                 facetMesh.triangles()[triangle]),
                                            forms[conditions.size()]));
      }
      AngleSet range = algebra.positiveSet(conditions, PredicateKind::EdgeFacet);
      if (!range.empty()) patches.push_back({contact, std::move(range)});
    }
  }
}

}  // namespace

std::vector<Patch> vertexFacetPatches(const Mesh& robot, const MeshTopology& robotTopology, const Mesh& world,
                                      const MeshTopology& worldTopology, AngleAlgebra& algebra,
                                      const Cancellation& cancellation) {
  std::vector<Patch> patches;
  addPatches(ContactKind::VertexFacet, robot, robotTopology, world, algebra, cancellation, patches);
  addPatches(ContactKind::FacetVertex, world, worldTopology, robot, algebra, cancellation, patches);
  return patches;
}

}  // namespace freespace
