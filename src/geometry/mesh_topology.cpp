#include "freespace/geometry/mesh_topology.h"

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "freespace/geometry/determinants.h"
#include "freespace/numbers/adaptive_sign.h"

// Conventions. Edges are numbered in the order of their first appearance (triangles in
// order, each triangle's sides 0-1, 1-2, 2-0) and stored with from < to.
//
// Convexity. With a the third vertex of `left` (which runs from -> to, so its outward
// normal is (to - from) x (a - from)) and b the third vertex of `right`, the edge is
// convex exactly when b lies strictly on the inner side of left's plane:
// orient3d(from, to, a, b) < 0. Zero is a flat edge, positive a reflex one.
//
// Pointedness. Near a vertex v the solid is v + K for a closed cone K; v is pointed when
// K minus the origin lies in an open half space. The triangles around v form one or more
// fans: cycles of triangles joined through the edges at v (several where components or
// sheets of the surface touch at v). The triangles of a fan cut a closed polygon (its
// link) from the unit sphere around v, with corners at the fan's edge directions and
// sides shorter than pi; for an embedded surface it is a simple curve, and the fan's part
// K_f of K is the closure of one of its two sides. The rule is:
//   (1) for every fan, the convex cone C_f spanned by its edge directions is pointed and
//       full-dimensional, and the edge along one extreme ray of C_f is convex;
//   (2) with several fans, the cone spanned by all edge directions at v is pointed.
// Why (1) holds exactly when K_f lies in an open half space: if it does, so do the edge
// directions, and C_f cannot be flat (a link in one plane bounds a half space). If C_f is
// pointed, central projection from v onto a plane cutting all its rays maps the link to a
// simple polygon and C_f to that polygon's convex hull. K_f is either the polygon's
// bounded side (inside C_f: in an open half space) or the side containing the whole
// opposite hemisphere (in no open half space). At a corner of the convex hull the bounded
// side's angle is below pi, and that angle is the solid's dihedral angle at the edge: the
// edge is convex exactly when K_f is the bounded side. Given (1), K is the union of the
// K_f, inside the cone of all edge directions, which (2) makes pointed; conversely a
// pointed K contains all edge directions. All edges convex is not required: the apex of a
// pyramid over an L-shaped base is pointed though its edge to the inner corner is reflex.
// A vertex inside a flat region (all directions in one plane) or on a straight run of
// edges (two opposite directions: a wedge) fails (1).

namespace freespace {

namespace {

/// Exact signs of orient3dDeterminant on mesh vertices, counted as Orientation.
class VertexOrientation {
 public:
  VertexOrientation(const std::vector<Point3>& vertices, PredicateStatistics& statistics)
      : vertices_(vertices), engine_(statistics) {}

  /// Positive when d lies on the side of the plane (a, b, c) that (b - a) x (c - a)
  /// points to. A repeated vertex is a known identity (zero without evaluation).
  Sign operator()(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    if (a == b || a == c || a == d || b == c || b == d || c == d) {
      return engine_.knownIdentity(PredicateKind::Orientation);
    }
    return engine_.sign(PredicateKind::Orientation, [&](auto numberType) {
      using T = typename decltype(numberType)::type;
      return orient3dDeterminant(point<T>(a), point<T>(b), point<T>(c), point<T>(d));
    });
  }

 private:
  template <class T>
  Vec3T<T> point(std::uint32_t vertex) const {
    const Point3& p = vertices_[vertex];
    return {T(p.x()), T(p.y()), T(p.z())};
  }

  const std::vector<Point3>& vertices_;
  AdaptiveSignEngine engine_;
};

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

std::uint32_t otherEndOf(const MeshEdge& edge, std::uint32_t vertex) {
  return edge.from == vertex ? edge.to : edge.from;
}

std::uint32_t thirdVertex(const TriangleIndices& triangle, std::uint32_t a, std::uint32_t b) {
  return *std::find_if(triangle.begin(), triangle.end(), [&](std::uint32_t v) { return v != a && v != b; });
}

/// The triangle at an edge that runs from `vertex` to the other end.
std::uint32_t triangleLeaving(const MeshEdge& edge, std::uint32_t vertex) {
  return edge.from == vertex ? edge.left : edge.right;
}

/// The edges of a closed, consistently oriented mesh, found by their end points.
struct EdgeTable {
  std::vector<MeshEdge> edges;
  std::unordered_map<std::uint64_t, std::uint32_t> indexByKey;

  std::uint32_t find(std::uint32_t a, std::uint32_t b) const { return indexByKey.at(edgeKey(a, b)); }
};

EdgeTable collectEdges(const std::vector<TriangleIndices>& triangles) {
  EdgeTable table;
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    for (int side = 0; side < 3; ++side) {
      const std::uint32_t tail = triangles[t][side], head = triangles[t][(side + 1) % 3];
      const auto [entry, added] =
          table.indexByKey.try_emplace(edgeKey(tail, head), static_cast<std::uint32_t>(table.edges.size()));
      if (added) table.edges.push_back(MeshEdge{std::min(tail, head), std::max(tail, head)});
      MeshEdge& edge = table.edges[entry->second];
      (tail < head ? edge.left : edge.right) = t;
    }
  }
  return table;
}

bool isConvex(const MeshEdge& edge, const std::vector<TriangleIndices>& triangles, VertexOrientation& orientation) {
  const std::uint32_t leftApex = thirdVertex(triangles[edge.left], edge.from, edge.to);
  const std::uint32_t rightApex = thirdVertex(triangles[edge.right], edge.from, edge.to);
  return orientation(edge.from, edge.to, leftApex, rightApex) == Sign::Negative;
}

std::vector<std::vector<std::uint32_t>> incidentEdges(const std::vector<MeshEdge>& edges, std::size_t vertexCount) {
  std::vector<std::vector<std::uint32_t>> incident(vertexCount);
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    incident[edges[e].from].push_back(e);
    incident[edges[e].to].push_back(e);
  }
  return incident;
}

/// The fans around `vertex`, each given by the far ends of its edges in turning order:
/// the triangle leaving `vertex` towards ends[i] is (vertex, ends[i], ends[i + 1]), so
/// any two consecutive ends span a triangle with `vertex`.
std::vector<std::vector<std::uint32_t>> fansAround(std::uint32_t vertex, const std::vector<std::uint32_t>& incident,
                                                   const EdgeTable& table,
                                                   const std::vector<TriangleIndices>& triangles) {
  std::vector<std::vector<std::uint32_t>> fans;
  std::unordered_set<std::uint32_t> visited;
  for (const std::uint32_t start : incident) {
    if (visited.count(start) != 0) continue;
    std::vector<std::uint32_t>& ends = fans.emplace_back();
    for (std::uint32_t e = start; visited.insert(e).second;) {
      const MeshEdge& edge = table.edges[e];
      ends.push_back(otherEndOf(edge, vertex));
      e = table.find(vertex, thirdVertex(triangles[triangleLeaving(edge, vertex)], vertex, ends.back()));
    }
  }
  return fans;
}

/// Widens a pointed cone, given by its extreme rays from `apex` (named by their end
/// points) in an order that keeps every ray x of the cone on the non-negative side of
/// each two consecutive ones, orient3d(apex, corner[i], corner[i + 1], x) >= 0, by the
/// ray towards `end`. False when the result would contain a line (the opposite ray is in
/// the cone already).
bool addRay(std::uint32_t apex, std::uint32_t end, std::vector<std::uint32_t>& corners,
            VertexOrientation& orientation) {
  const std::size_t n = corners.size();
  std::vector<Sign> sides(n);
  for (std::size_t i = 0; i < n; ++i) sides[i] = orientation(apex, corners[i], corners[(i + 1) % n], end);
  const auto has = [&](Sign sign) { return std::find(sides.begin(), sides.end(), sign) != sides.end(); };
  if (!has(Sign::Negative)) return true;
  if (!has(Sign::Positive)) return false;
  // Projected centrally onto a plane that cuts every ray (one exists, as the widened
  // cone is pointed), the cone is a convex polygon and `end` a point outside it: the
  // sides that do not have `end` strictly on their inner side form one cyclic run, whose
  // inner corners give way to `end`.
  std::size_t first = 0;
  while (sides[first] == Sign::Positive || sides[(first + n - 1) % n] != Sign::Positive) ++first;
  std::rotate(corners.begin(), corners.begin() + first, corners.end());
  std::rotate(sides.begin(), sides.begin() + first, sides.end());
  const auto afterRun = std::find(sides.begin(), sides.end(), Sign::Positive) - sides.begin();
  corners.erase(corners.begin() + 1, corners.begin() + afterRun);
  corners.insert(corners.begin() + 1, end);
  return true;
}

/// The extreme rays of the cone spanned by the rays from `apex` to `ends`, when that
/// cone is pointed and full-dimensional. ends[0] and ends[1] must span a triangle with
/// `apex`.
std::optional<std::vector<std::uint32_t>> pointedConeCorners(std::uint32_t apex,
                                                             const std::vector<std::uint32_t>& ends,
                                                             VertexOrientation& orientation) {
  const std::uint32_t a = ends[0], b = ends[1];
  std::vector<std::uint32_t> corners;
  for (const std::uint32_t c : ends) {
    const Sign side = orientation(apex, a, b, c);
    if (side != Sign::Zero) {
      corners = side == Sign::Positive ? std::vector<std::uint32_t>{a, b, c} : std::vector<std::uint32_t>{a, c, b};
      break;
    }
  }
  if (corners.empty()) return std::nullopt;  // flat: every ray in one plane
  for (const std::uint32_t end : ends) {
    if (!addRay(apex, end, corners, orientation)) return std::nullopt;
  }
  return corners;
}

/// The pointedness rule of the comment at the top of this file.
bool isPointedVertex(std::uint32_t vertex, const std::vector<std::vector<std::uint32_t>>& fans, const EdgeTable& table,
                     VertexOrientation& orientation) {
  for (const std::vector<std::uint32_t>& ends : fans) {
    const std::optional<std::vector<std::uint32_t>> corners = pointedConeCorners(vertex, ends, orientation);
    if (!corners || !table.edges[table.find(vertex, corners->front())].convex) return false;
  }
  if (fans.size() == 1) return true;
  std::vector<std::uint32_t> allEnds;
  for (const std::vector<std::uint32_t>& ends : fans) allEnds.insert(allEnds.end(), ends.begin(), ends.end());
  return pointedConeCorners(vertex, allEnds, orientation).has_value();
}

}  // namespace

MeshTopology::MeshTopology(const Mesh& mesh, PredicateStatistics& statistics) {
  VertexOrientation orientation(mesh.vertices(), statistics);
  EdgeTable table = collectEdges(mesh.triangles());
  for (MeshEdge& edge : table.edges) edge.convex = isConvex(edge, mesh.triangles(), orientation);
  vertexEdges_ = incidentEdges(table.edges, mesh.vertices().size());
  pointed_.resize(mesh.vertices().size());
  for (std::uint32_t v = 0; v < pointed_.size(); ++v) {
    pointed_[v] = isPointedVertex(v, fansAround(v, vertexEdges_[v], table, mesh.triangles()), table, orientation);
  }
  edges_ = std::move(table.edges);
}

std::uint32_t MeshTopology::otherEnd(std::uint32_t edge, std::uint32_t vertex) const {
  return otherEndOf(edges_[edge], vertex);
}

}  // namespace freespace
