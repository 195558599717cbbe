#include "freespace/geometry/patch_segment.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>

#include "freespace/input_error.h"
#include "freespace/numbers/adaptive_sign.h"

namespace freespace {

namespace {

std::array<std::uint32_t, 2> sortedEdge(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

bool straddles(const Mesh& mesh, std::uint32_t a, std::uint32_t b, double z) {
  const double za = mesh.vertices()[a].z(), zb = mesh.vertices()[b].z();
  return std::min(za, zb) < z && z < std::max(za, zb);
}

/// A vertex on the two edges of a triangle that cross the vertex's height.
std::array<SegmentEnd, 2> crossSectionEnds(bool robotVertex, std::uint32_t vertex, const Mesh& vertexMesh,
                                           const Mesh& facetMesh, std::uint32_t triangle) {
  const double z = vertexMesh.vertices()[vertex].z();
  const TriangleIndices& corners = facetMesh.triangles()[triangle];
  std::vector<SegmentEnd> ends;
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t a = corners[i], b = corners[(i + 1) % 3];
    if (straddles(facetMesh, a, b, z)) ends.push_back({robotVertex, vertex, sortedEdge(a, b)});
  }
  if (ends.size() != 2) throw std::logic_error("patchSegment: a vertex at the height of a triangle corner");
  return {ends[0], ends[1]};
}

/// The end of an EE segment at the bottom (`top` false) or top of the two edges'
/// common height range: the vertex of the edge whose range ends there, on the
/// other edge.
SegmentEnd edgeEdgeEnd(const MeshEdge& robotEdge, const Mesh& robot, const MeshEdge& worldEdge, const Mesh& world,
                       bool top) {
  const auto extreme = [top](const Mesh& mesh, const MeshEdge& edge) {
    const bool fromIsHigher = mesh.vertices()[edge.from].z() > mesh.vertices()[edge.to].z();
    return fromIsHigher == top ? edge.from : edge.to;
  };
  const std::uint32_t robotVertex = extreme(robot, robotEdge), worldVertex = extreme(world, worldEdge);
  const double robotZ = robot.vertices()[robotVertex].z(), worldZ = world.vertices()[worldVertex].z();
  if (robotZ == worldZ) throw std::logic_error("patchSegment: edges end at the same height");
  const bool robotEndsFirst = top ? robotZ < worldZ : robotZ > worldZ;
  if (robotEndsFirst) return {true, robotVertex, sortedEdge(worldEdge.from, worldEdge.to)};
  return {false, worldVertex, sortedEdge(robotEdge.from, robotEdge.to)};
}

std::array<SegmentEnd, 2> unorderedEnds(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                                        const Mesh& world, const MeshTopology& worldTopology) {
  switch (contact.kind) {
    case ContactKind::VertexFacet: return crossSectionEnds(true, contact.robot, robot, world, contact.world);
    case ContactKind::FacetVertex: return crossSectionEnds(false, contact.world, world, robot, contact.robot);
    case ContactKind::EdgeEdge: break;
  }
  const MeshEdge& robotEdge = robotTopology.edges()[contact.robot];
  const MeshEdge& worldEdge = worldTopology.edges()[contact.world];
  return {edgeEdgeEnd(robotEdge, robot, worldEdge, world, false), edgeEdgeEnd(robotEdge, robot, worldEdge, world, true)};
}

/// n x (end1 - end0) at the rational angle with the given cosine and sine: positive
/// when the ends are in the order PatchSegment promises. It is +-|n| |end1 - end0|,
/// so its sign changes only where the segment or the normal vanishes (for VF and
/// FV never; for EE where the rotated edges are parallel).
struct SegmentOrientation {
  const Contact* contact;
  const Mesh *robot, *world;
  const MeshTopology *robotTopology, *worldTopology;
  const std::array<SegmentEnd, 2>* ends;
  int cosine, sine;  // a point of the unit circle with integer coordinates

  template <class T>
  T operator()(NumberType<T>) const {
    const PatchLine<T> line = contactLine<T>(*contact, *robot, *robotTopology, *world, *worldTopology);
    const T c(cosine), s(sine);
    const LineAtAngle<T> atAngle = lineAtAngle(line, c, s);
    const auto first = spiralPoint(spiralOf<T>((*ends)[0], *robot, *world), c, s);
    const auto second = spiralPoint(spiralOf<T>((*ends)[1], *robot, *world), c, s);
    return atAngle.nx * (second[1] - first[1]) - atAngle.ny * (second[0] - first[0]);
  }
};

}  // namespace

PatchSegment patchSegment(const Contact& contact, const Mesh& robot, const MeshTopology& robotTopology,
                          const Mesh& world, const MeshTopology& worldTopology, PredicateStatistics& statistics) {
  std::array<SegmentEnd, 2> ends = unorderedEnds(contact, robot, robotTopology, world, worldTopology);
  AdaptiveSignEngine engine(statistics);
  // Any angle where the orientation does not vanish gives the order at all angles;
  // it can vanish only at the isolated angles where two edges are parallel.
  for (const auto& [cosine, sine] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{-1, 0}}) {
    const Sign sign = engine.sign(PredicateKind::Orientation, SegmentOrientation{&contact, &robot, &world, &robotTopology,
                                                                                 &worldTopology, &ends, cosine, sine});
    if (sign == Sign::Zero) continue;
    if (sign == Sign::Negative) std::swap(ends[0], ends[1]);
    return {ends};
  }
  throw std::logic_error("patchSegment: the segment degenerates at three angles");
}

void requireDistinctHeights(const Mesh& robot, const Mesh& world, const std::string& sceneName) {
  std::map<double, std::string> seen;
  const auto check = [&](const Mesh& mesh, const char* body) {
    for (std::uint32_t i = 0; i < mesh.vertices().size(); ++i) {
      std::ostringstream name;
      name << body << " vertex " << i;
      const auto [where, inserted] = seen.emplace(mesh.vertices()[i].z(), name.str());
      if (inserted) continue;
      std::ostringstream problem;
      problem.precision(17);
      problem << where->second << " and " << name.str() << " are at the same height " << where->first
              << "; the construction needs distinct heights (switch perturbation on)";
      throw InputError(sceneName, problem.str());
    }
  };
  check(robot, "robot");
  check(world, "environment");
}

}  // namespace freespace
