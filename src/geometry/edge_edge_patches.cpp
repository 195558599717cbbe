#include <algorithm>
#include <array>

#include "angle_bounds.h"
#include "contact_vectors.h"
#include "freespace/geometry/patch.h"
#include "freespace/numbers/trig_linear_function.h"

namespace freespace {

namespace {

using detail::edgeVector;
using detail::rotatedDot;
using detail::triangleNormal;

/// A convex edge with its two face triangles ordered so that
/// det(edge direction, normal of first, normal of second) > 0.
struct OrientedEdge {
  std::uint32_t edge;
  std::array<std::uint32_t, 2> faces;
};

/// det(u, m_left, m_right) for an edge of a mesh, written once for every number type.
struct WedgeOrientation {
  const Mesh* mesh;
  const MeshEdge* edge;
  template <class T>
  T operator()(NumberType<T>) const {
    const auto u = edgeVector<T>(*mesh, edge->from, edge->to);
    return detail::dot(u, detail::cross(triangleNormal<T>(*mesh, edge->left), triangleNormal<T>(*mesh, edge->right)));
  }
};

std::vector<OrientedEdge> convexEdges(const Mesh& mesh, const MeshTopology& topology, AdaptiveSignEngine& engine) {
  std::vector<OrientedEdge> edges;
  for (std::uint32_t i = 0; i < topology.edges().size(); ++i) {
    const MeshEdge& edge = topology.edges()[i];
    if (!edge.convex) continue;
    const bool leftFirst = engine.sign(PredicateKind::Orientation, WedgeOrientation{&mesh, &edge}) == Sign::Positive;
    edges.push_back({i, leftFirst ? std::array<std::uint32_t, 2>{edge.left, edge.right}
                                  : std::array<std::uint32_t, 2>{edge.right, edge.left}});
  }
  return edges;
}

/// The open z range of an edge.
std::pair<double, double> heightRange(const Mesh& mesh, const MeshEdge& edge) {
  const double a = mesh.vertices()[edge.from].z(), b = mesh.vertices()[edge.to].z();
  return {std::min(a, b), std::max(a, b)};
}

/// One of the four conditions, up to its sign: (R m) . v with m a robot face normal
/// and v the environment edge, or (R u) . n with u the robot edge and n an
/// environment face normal. Coordinates are copied: the function outlives the
/// meshes in the patches' angles.
template <class T>
TrigLinear<T> wedgeForm(const std::array<Point3, 2>& robotEdge, const std::array<Point3, 2>& worldEdge, bool robotNormal,
                        const detail::Corners& face) {
  const auto u = detail::difference(detail::pointOf<T>(robotEdge[1]), detail::pointOf<T>(robotEdge[0]));
  const auto v = detail::difference(detail::pointOf<T>(worldEdge[1]), detail::pointOf<T>(worldEdge[0]));
  return robotNormal ? rotatedDot(detail::normalOf<T>(face), v) : rotatedDot(u, detail::normalOf<T>(face));
}

/// The condition as an angle function, given its form in double intervals (wedgeForms,
/// already computed for the quick test).
std::shared_ptr<const AngleFunction> wedgeCondition(const std::array<Point3, 2>& robotEdge,
                                                    const std::array<Point3, 2>& worldEdge, bool robotNormal,
                                                    const detail::Corners& face, AngleFunction::RootKey key,
                                                    const TrigLinear<Interval>& approximateForm) {
  const auto form = [robotEdge, worldEdge, robotNormal, face](auto type) {
    using T = typename decltype(type)::type;
    return wedgeForm<T>(robotEdge, worldEdge, robotNormal, face);
  };
  return trigLinearFunction(form, key, approximateForm);
}

/// The four conditions' forms in double intervals: two robot face normals against the
/// environment edge, then the robot edge against two environment face normals.
std::vector<TrigLinear<Interval>> wedgeForms(const std::array<Point3, 2>& robotEnds,
                                             const std::array<Point3, 2>& worldEnds,
                                             const std::array<detail::Corners, 4>& faces) {
  std::vector<TrigLinear<Interval>> forms;
  RoundingScope rounding;
  for (int k = 0; k < 4; ++k) forms.push_back(wedgeForm<Interval>(robotEnds, worldEnds, k < 2, faces[k]));
  return forms;
}

/// Whether one of the two sign patterns of the wedge conditions may hold somewhere,
/// from their forms (decided in doubles over ranges of angles; true when unsure).
bool mayTouch(const std::vector<TrigLinear<Interval>>& forms, const std::vector<Sign>& pattern) {
  const std::vector<detail::SignMasks> masks = detail::signMasksOf(forms);
  std::vector<Sign> opposite;
  for (Sign sign : pattern) opposite.push_back(-sign);
  return detail::signPatternMayHold(masks, pattern) || detail::signPatternMayHold(masks, opposite);
}

std::array<Point3, 2> endsOf(const Mesh& mesh, const MeshEdge& edge) {
  return {mesh.vertices()[edge.from], mesh.vertices()[edge.to]};
}

}  // namespace

std::vector<Patch> edgeEdgePatches(const Mesh& robot, const MeshTopology& robotTopology, const Mesh& world,
                                   const MeshTopology& worldTopology, AngleAlgebra& algebra,
                                   const Cancellation& cancellation) {
  AdaptiveSignEngine engine(algebra.statistics());
  const std::vector<OrientedEdge> robotEdges = convexEdges(robot, robotTopology, engine);
  const std::vector<OrientedEdge> worldEdges = convexEdges(world, worldTopology, engine);
  std::vector<Patch> patches;
  for (const OrientedEdge& a : robotEdges) {
    const MeshEdge& robotEdge = robotTopology.edges()[a.edge];
    const auto [robotLow, robotHigh] = heightRange(robot, robotEdge);
    for (const OrientedEdge& b : worldEdges) {
      cancellation.check();
      const MeshEdge& worldEdge = worldTopology.edges()[b.edge];
      const auto [worldLow, worldHigh] = heightRange(world, worldEdge);
      if (!(std::max(robotLow, worldLow) < std::min(robotHigh, worldHigh))) continue;
      const auto robotEnds = endsOf(robot, robotEdge), worldEnds = endsOf(world, worldEdge);
      const std::array<detail::Corners, 4> faces{detail::cornersOf(robot, a.faces[0]), detail::cornersOf(robot, a.faces[1]),
                                                 detail::cornersOf(world, b.faces[0]), detail::cornersOf(world, b.faces[1])};
      // Side +1 needs the signs (+, -, +, -), side -1 the opposite ones.
      const std::vector<Sign> pattern{Sign::Positive, Sign::Negative, Sign::Positive, Sign::Negative};
      const std::vector<TrigLinear<Interval>> forms = wedgeForms(robotEnds, worldEnds, faces);
      if (!mayTouch(forms, pattern)) continue;
      // (R m) . v is the EF function of the environment edge and a robot face,
      // (R u) . n that of the robot edge and an environment face.
      const std::array<AngleFunction::RootKey, 4> keys{
          detail::edgeFacetKey(false, worldEdge.from, worldEdge.to, robot.triangles()[a.faces[0]]),
          detail::edgeFacetKey(false, worldEdge.from, worldEdge.to, robot.triangles()[a.faces[1]]),
          detail::edgeFacetKey(true, robotEdge.from, robotEdge.to, world.triangles()[b.faces[0]]),
          detail::edgeFacetKey(true, robotEdge.from, robotEdge.to, world.triangles()[b.faces[1]])};
      std::vector<std::shared_ptr<const AngleFunction>> conditions;
      for (int k = 0; k < 4; ++k) conditions.push_back(wedgeCondition(robotEnds, worldEnds, k < 2, faces[k], keys[k], forms[k]));
      std::array<AngleSet, 2> ranges = algebra.signPatternSets(conditions, pattern, PredicateKind::EdgeFacet);
      for (int which = 0; which < 2; ++which) {
        if (ranges[which].empty()) continue;
        patches.push_back({Contact{ContactKind::EdgeEdge, a.edge, b.edge, which == 0 ? 1 : -1}, std::move(ranges[which])});
      }
    }
  }
  return patches;
}

}  // namespace freespace
