#include "soup_boundary.h"

#include <algorithm>
#include <map>
#include <set>

#include "disjoint_sets.h"

namespace freespace::detail {

namespace {

using Index = std::uint32_t;
using Edge = std::pair<Index, Index>;

// A coordinate that CGAL approximates by a single double is that double; the point
// is evaluated exactly only for the others (CGAL's coordinate accessors would add a
// node to its graph of constructions for each, evaluated on its own).
Point3 rounded(const ExactPoint& point) {
  const auto& approximation = CGAL::approx(point);
  Point3 result;
  for (int axis = 0; axis < 3; ++axis) {
    const auto& interval = approximation[axis];
    result[axis] = interval.inf() == interval.sup() ? interval.inf() : CGAL::to_double(CGAL::exact(point)[axis]);
  }
  return result;
}

// The boundary's components: faces joined by pairings, numbered in face order.
class Components {
 public:
  Components(const std::vector<BoundaryFace>& faces, const std::vector<BoundaryPairing>& pairings,
             std::size_t complexFaces)
      : joined_(complexFaces) {
    for (const BoundaryPairing& pairing : pairings) joined_.unite(pairing.first, pairing.second);
    for (const BoundaryFace& face : faces) number_.emplace(joined_.find(face.face), number_.size());
  }

  Index of(Index face) { return number_.at(joined_.find(face)); }
  std::size_t count() const { return number_.size(); }

 private:
  DisjointSets joined_;
  std::map<Index, Index> number_;  // first face of a component -> its number
};

// Where components touch themselves along edges: for each (component, vertex) at the
// end of such an edge, the fan of each face there (faces joined by pairings at edges
// of that vertex), numbered from 0.
class Fans {
 public:
  Fans(const SoupComplex& complex, const std::vector<BoundaryFace>& faces, const std::vector<BoundaryPairing>& pairings,
       Components& components) {
    std::map<std::pair<Index, Edge>, int> facesAtEdge;  // (component, edge) -> boundary faces there
    for (const BoundaryFace& face : faces) {
      const TriangleIndices& corners = complex.faces[face.face];
      for (int i = 0; i < 3; ++i) {
        const Edge edge{std::min(corners[i], corners[(i + 1) % 3]), std::max(corners[i], corners[(i + 1) % 3])};
        ++facesAtEdge[{components.of(face.face), edge}];
      }
    }
    std::set<std::pair<Index, Index>> split;  // (component, vertex)
    for (const auto& [key, count] : facesAtEdge) {
      if (count <= 2) continue;
      ++pinchedEdges_;
      split.insert({key.first, key.second.first});
      split.insert({key.first, key.second.second});
    }
    for (const auto& [component, vertex] : split) numberFans(complex, faces, pairings, components, component, vertex);
  }

  /// The fan of `face` at `vertex`: 0 unless the vertex was split.
  int of(Index face, Index vertex) const {
    const auto found = fan_.find({face, vertex});
    return found == fan_.end() ? 0 : found->second;
  }

  int pinchedEdges() const { return pinchedEdges_; }

 private:
  void numberFans(const SoupComplex& complex, const std::vector<BoundaryFace>& faces,
                  const std::vector<BoundaryPairing>& pairings, Components& components, Index component, Index vertex) {
    std::vector<Index> around;  // the component's boundary faces at the vertex
    for (const BoundaryFace& face : faces) {
      const TriangleIndices& corners = complex.faces[face.face];
      if (components.of(face.face) == component && std::find(corners.begin(), corners.end(), vertex) != corners.end()) {
        around.push_back(face.face);
      }
    }
    std::map<Index, Index> position;
    for (Index i = 0; i < around.size(); ++i) position[around[i]] = i;
    DisjointSets fans(around.size());
    for (const BoundaryPairing& pairing : pairings) {
      if (pairing.edge.first != vertex && pairing.edge.second != vertex) continue;
      const auto a = position.find(pairing.first), b = position.find(pairing.second);
      if (a != position.end() && b != position.end()) fans.unite(a->second, b->second);
    }
    std::map<Index, int> number;  // first face's position -> fan number
    for (Index i = 0; i < around.size(); ++i) {
      const auto [found, inserted] = number.emplace(fans.find(i), static_cast<int>(number.size()));
      fan_[{around[i], vertex}] = found->second;
    }
  }

  std::map<std::pair<Index, Index>, int> fan_;  // (face, vertex) -> fan
  int pinchedEdges_ = 0;
};

// The direction from `vertex` towards the other corners of its fan's faces: into the
// fan's own wedge of solid, roughly, for a fan of a pinched edge.
Point3 towardsFan(const SoupComplex& complex, const std::vector<BoundaryFace>& faces, const Fans& fans, Index vertex,
                  int fan) {
  Point3 sum = Point3::Zero();
  const Point3 origin = rounded(complex.points[vertex]);
  for (const BoundaryFace& face : faces) {
    const TriangleIndices& corners = complex.faces[face.face];
    if (std::find(corners.begin(), corners.end(), vertex) == corners.end() || fans.of(face.face, vertex) != fan)
      continue;
    for (Index corner : corners) {
      if (corner != vertex) sum += (rounded(complex.points[corner]) - origin).normalized();
    }
  }
  return sum.normalized();
}

}  // namespace

void assembleBoundary(const SoupComplex& complex, const std::vector<BoundaryFace>& faces,
                      const std::vector<BoundaryPairing>& pairings, double separation, EnclosedSolid& solid) {
  Components components(faces, pairings, complex.faces.size());
  const Fans fans(complex, faces, pairings, components);
  std::map<std::tuple<Index, Index, int>, Index> copies;  // (component, complex point, fan) -> boundary vertex
  for (const BoundaryFace& face : faces) {
    TriangleIndices corners = complex.faces[face.face];
    if (face.flip) std::swap(corners[1], corners[2]);
    const Index component = components.of(face.face);
    for (Index& corner : corners) {
      const int fan = fans.of(face.face, corner);
      const auto [found, inserted] =
          copies.emplace(std::make_tuple(component, corner, fan), solid.boundary.vertices.size());
      if (inserted) {
        Point3 position = rounded(complex.points[corner]);
        if (fan > 0) position += separation * towardsFan(complex, faces, fans, corner, fan);
        solid.boundary.vertices.push_back(position);
      }
      corner = found->second;
    }
    solid.boundary.triangles.push_back(corners);
    solid.boundaryComponent.push_back(component);
  }
  solid.components = components.count();
  solid.separatedEdges = static_cast<std::size_t>(fans.pinchedEdges());
}

}  // namespace freespace::detail
