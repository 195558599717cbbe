// The cells of space a soup complex bounds, and the solid it encloses
// (soup_complex.h; docs/design.md section 9).
//
// Sides. Face f = (a, b, c) has a front side, the one its normal (b - a) x (c - a)
// points to, and a back side: side 2f and 2f + 1. Around an edge from its lower vertex
// u to its higher vertex v, order the faces by the angle of their third vertex w about
// the axis u -> v (right-handed). A face that runs along the edge from u to v has its
// normal pointing towards rising angles, so its front side faces the wedge after it;
// one that runs from v to u has its back side there. The wedge between consecutive
// faces is one region of space: the side of the first facing forward and the side of
// the second facing backward belong to one cell. Sides joined this way around every
// edge form shells; one cell may have several shells (one inside another), which a
// ray joins: from a point of a face, off one side, to the first face it meets (see
// Cells for which cells are bounded).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include <CGAL/Interval_nt.h>
#include <CGAL/intersections.h>

#include "disjoint_sets.h"
#include "soup_boundary.h"
#include "soup_complex.h"
#include "surface_self_intersection.h"

namespace freespace::detail {

namespace {

using Index = std::uint32_t;
using ExactTriangle = ExactKernel::Triangle_3;
using ExactVector = ExactKernel::Vector_3;
using ExactRay = ExactKernel::Ray_3;

Index frontSide(Index face) { return 2 * face; }
Index backSide(Index face) { return 2 * face + 1; }
Index faceOf(Index side) { return side / 2; }
bool isFront(Index side) { return side % 2 == 0; }

// A face at an edge: which face, and whether it runs along the edge from its lower
// vertex to its higher one.
struct EdgeFace {
  Index face;
  bool forward;
};

Index risingSide(const EdgeFace& entry) { return entry.forward ? frontSide(entry.face) : backSide(entry.face); }
Index fallingSide(const EdgeFace& entry) { return entry.forward ? backSide(entry.face) : frontSide(entry.face); }

// The edge two faces that meet around it share, as (lower, higher) vertex.
std::pair<Index, Index> sharedEdge(const TriangleIndices& a, const TriangleIndices& b) {
  std::vector<Index> shared;
  for (Index corner : a) {
    if (std::find(b.begin(), b.end(), corner) != b.end()) shared.push_back(corner);
  }
  return {std::min(shared[0], shared[1]), std::max(shared[0], shared[1])};
}

Index thirdVertex(const TriangleIndices& face, Index u, Index v) {
  return *std::find_if(face.begin(), face.end(), [&](Index corner) { return corner != u && corner != v; });
}

// The faces around each edge, in the order of their angle about the edge.
class EdgeFans {
 public:
  // Fans in the order of their edges (lower vertex, then higher), each fan's faces
  // first in face order.
  explicit EdgeFans(const SoupComplex& complex) : complex_(complex) {
    std::vector<std::pair<std::uint64_t, EdgeFace>> uses;  // (edge: lower vertex, higher vertex), face
    uses.reserve(3 * complex.faces.size());
    for (Index f = 0; f < complex.faces.size(); ++f) {
      const TriangleIndices& face = complex.faces[f];
      for (int corner = 0; corner < 3; ++corner) {
        const Index from = face[corner], to = face[(corner + 1) % 3];
        uses.push_back({(std::uint64_t{std::min(from, to)} << 32) | std::max(from, to), {f, from < to}});
      }
    }
    std::stable_sort(uses.begin(), uses.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto first = uses.begin(); first != uses.end();) {
      const std::uint64_t edge = first->first;
      const auto last = std::find_if(first, uses.end(), [&](const auto& use) { return use.first != edge; });
      std::vector<EdgeFace> fan;
      for (auto use = first; use != last; ++use) fan.push_back(use->second);
      if (fan.size() > 2) sortByAngle(static_cast<Index>(edge >> 32), static_cast<Index>(edge), fan);
      fans_.push_back(std::move(fan));
      first = last;
    }
  }

  const std::vector<std::vector<EdgeFace>>& fans() const { return fans_; }

 private:
  // Angles measured from the first face's half-plane: (0, pi) where the first face's
  // normal (as if it ran from u to v) points, (pi, 2 pi) on the other side, and pi in
  // its plane (an angle of 0 would mean two faces overlapping, which a complex has not).
  void sortByAngle(Index u, Index v, std::vector<EdgeFace>& fan) const {
    const std::vector<ExactPoint>& p = complex_.points;
    const auto apex = [&](const EdgeFace& entry) { return p[thirdVertex(complex_.faces[entry.face], u, v)]; };
    const ExactPoint reference = apex(fan.front());
    const auto half = [&](const EdgeFace& entry) {
      if (entry.face == fan.front().face) return 0;
      const CGAL::Orientation side = CGAL::orientation(p[u], p[v], reference, apex(entry));
      return side == CGAL::POSITIVE ? 1 : (side == CGAL::ZERO ? 2 : 3);
    };
    std::sort(fan.begin() + 1, fan.end(), [&](const EdgeFace& a, const EdgeFace& b) {
      const int halfA = half(a), halfB = half(b);
      if (halfA != halfB) return halfA < halfB;
      return CGAL::orientation(p[u], p[v], apex(a), apex(b)) == CGAL::POSITIVE;
    });
  }

  const SoupComplex& complex_;
  std::vector<std::vector<EdgeFace>> fans_;
};

// Where a ray first meets the complex: the side of the face it meets, or nothing.
struct RayHit {
  bool degenerate = false;  // through an edge or a vertex, or along a face: try another ray
  std::optional<Index> side;
};

// Rays through the complex: faces in an R-tree of boxes in doubles, widened by a
// margin that covers the difference between a ray and its rounded copy; candidates
// are met exactly, in the order the rounded ray enters their boxes, until the
// nearest meeting so far lies before the next box.
class RayCaster {
 public:
  explicit RayCaster(const SoupComplex& complex) {
    triangles_.reserve(complex.faces.size());
    for (const TriangleIndices& face : complex.faces) {
      triangles_.emplace_back(complex.points[face[0]], complex.points[face[1]], complex.points[face[2]]);
    }
    CGAL::Bbox_3 scene;
    for (const ExactTriangle& triangle : triangles_) scene += triangle.bbox();
    const double diagonal =
        std::hypot(scene.xmax() - scene.xmin(), scene.ymax() - scene.ymin(), scene.zmax() - scene.zmin());
    margin_ = kRelativeMargin * diagonal + std::numeric_limits<double>::min();
    reach_ = 4 * diagonal + margin_;
    std::vector<TreeEntry> entries;
    entries.reserve(triangles_.size());
    for (Index face = 0; face < triangles_.size(); ++face) {
      const CGAL::Bbox_3 box = triangles_[face].bbox();
      entries.emplace_back(TreeBox(TreePoint(box.xmin() - margin_, box.ymin() - margin_, box.zmin() - margin_),
                                   TreePoint(box.xmax() + margin_, box.ymax() + margin_, box.zmax() + margin_)),
                           face);
    }
    tree_ = TriangleTree(entries.begin(), entries.end());
  }

  // The side of the first face that a ray from the centre of `side`'s face, leaving
  // towards that side, meets; nothing if it escapes.
  std::optional<Index> firstHit(Index side) const {
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
      const RayHit hit = cast(side, attempt);
      if (!hit.degenerate) return hit.side;
    }
    throw std::logic_error("soup cells: every ray from a face met an edge or a vertex");
  }

 private:
  static constexpr int kAttempts = 32;
  static constexpr double kRelativeMargin = 1e-9;

  // The face's normal on the side's side, tilted after the first attempt by a
  // smaller amount each time (so the ray stays on that side).
  ExactVector direction(const ExactTriangle& face, bool front, int attempt) const {
    ExactVector normal = CGAL::normal(face[0], face[1], face[2]);
    if (!front) normal = -normal;
    if (attempt == 0) return normal;
    const ExactVector along = face[1] - face[0], across = face[2] - face[0];
    const double scale = 1.0 / (4 * (attempt + 1));
    return normal + along * (scale * ((attempt % 3) - 1)) + across * (scale * ((attempt % 5) - 2) / 2);
  }

  // Where the ray from `from` along the unit vector `direction` enters `box` (slabs,
  // in doubles), or nothing if it misses the box.
  static std::optional<double> entryDistance(const TreeBox& box, const Point3& from, const Point3& direction) {
    double entry = 0, exit = std::numeric_limits<double>::infinity();
    const double low[3] = {bg::get<0>(box.min_corner()), bg::get<1>(box.min_corner()), bg::get<2>(box.min_corner())};
    const double high[3] = {bg::get<0>(box.max_corner()), bg::get<1>(box.max_corner()), bg::get<2>(box.max_corner())};
    for (int axis = 0; axis < 3; ++axis) {
      if (direction[axis] == 0) {
        if (from[axis] < low[axis] || from[axis] > high[axis]) return std::nullopt;
        continue;
      }
      const double a = (low[axis] - from[axis]) / direction[axis], b = (high[axis] - from[axis]) / direction[axis];
      entry = std::max(entry, std::min(a, b));
      exit = std::min(exit, std::max(a, b));
    }
    if (entry > exit) return std::nullopt;
    return entry;
  }

  // The boxes the ray may meet, ordered by where its rounded copy enters them; every
  // face, unordered, where doubles cannot hold the rounded ray (coordinates near the
  // largest or the smallest double).
  std::vector<std::pair<double, Index>> candidates(const ExactPoint& origin, const ExactVector& towards,
                                                   Index face) const {
    const Point3 from(CGAL::to_double(origin.x()), CGAL::to_double(origin.y()), CGAL::to_double(origin.z()));
    const Point3 direction =
        Point3(CGAL::to_double(towards.x()), CGAL::to_double(towards.y()), CGAL::to_double(towards.z())).normalized();
    const Point3 to = from + reach_ * direction;
    std::vector<std::pair<double, Index>> ordered;
    if (!to.allFinite() || !direction.allFinite() || direction.squaredNorm() == 0) {
      for (Index other = 0; other < triangles_.size(); ++other) {
        if (other != face) ordered.emplace_back(0, other);
      }
      return ordered;
    }
    // The boxes that meet the rounded ray's box, then the ray itself (Boost.Geometry's
    // segment test misses boxes of models a few 1e-20 across).
    std::vector<TreeEntry> near;
    const TreeBox around(TreePoint(std::min(from.x(), to.x()), std::min(from.y(), to.y()), std::min(from.z(), to.z())),
                         TreePoint(std::max(from.x(), to.x()), std::max(from.y(), to.y()), std::max(from.z(), to.z())));
    tree_.query(bgi::intersects(around), std::back_inserter(near));
    for (const auto& [box, other] : near) {
      if (other == face) continue;
      if (const std::optional<double> entry = entryDistance(box, from, direction)) {
        ordered.emplace_back(*entry - margin_, other);
      }
    }
    std::sort(ordered.begin(), ordered.end());
    return ordered;
  }

  // The nearest face the ray meets decides: faces of a complex meet only in shared
  // edges and vertices, so a point inside one face lies on no other.
  RayHit cast(Index side, int attempt) const {
    const Index face = faceOf(side);
    const ExactTriangle& triangle = triangles_[face];
    const ExactPoint origin = CGAL::centroid(triangle[0], triangle[1], triangle[2]);
    const ExactVector towards = direction(triangle, isFront(side), attempt);
    const ExactRay ray(origin, towards);
    std::optional<ExactPoint> nearest;
    Index nearestFace = 0;
    std::optional<ExactKernel::FT> nearestDistance;          // squared
    double bound = std::numeric_limits<double>::infinity();  // above the nearest distance
    for (const auto& [entry, other] : candidates(origin, towards, face)) {
      if (entry > bound) break;
      const auto where = CGAL::intersection(ray, triangles_[other]);
      if (!where) continue;
      const ExactPoint* point = boost::get<ExactPoint>(&*where);
      if (!point) return {true, std::nullopt};  // along a face
      const ExactKernel::FT distance = CGAL::squared_distance(origin, *point);
      if (nearestDistance && distance == *nearestDistance) return {true, std::nullopt};
      if (nearestDistance && distance > *nearestDistance) continue;
      nearest = *point;
      nearestFace = other;
      nearestDistance = distance;
      bound = std::sqrt(CGAL::to_interval(distance).second) * (1 + 1e-9) + margin_;
    }
    if (!nearest) return {};
    if (onBoundary(triangles_[nearestFace], *nearest)) return {true, std::nullopt};
    const ExactTriangle& hit = triangles_[nearestFace];
    const ExactVector normal = CGAL::normal(hit[0], hit[1], hit[2]);
    return {false, CGAL::scalar_product(normal, towards) < 0 ? frontSide(nearestFace) : backSide(nearestFace)};
  }

  static bool onBoundary(const ExactTriangle& triangle, const ExactPoint& point) {
    for (int i = 0; i < 3; ++i) {
      if (CGAL::collinear(triangle[i], triangle[(i + 1) % 3], point)) return true;
    }
    return false;
  }

  std::vector<ExactTriangle> triangles_;
  TriangleTree tree_;
  double margin_ = 0;  // widens the boxes
  double reach_ = 0;   // the rounded ray's length, beyond the scene
};

// The sign of the volume a shell bounds, its faces turned towards the shell's cell:
// negative when the cell lies inside the shell (the shell is the cell's outer
// boundary), positive when outside (the shell bounds a hole of the cell), zero for a
// shell that encloses nothing (both sides of a sheet). Summed in intervals, exactly
// when those cannot tell.
class ShellVolumes {
 public:
  explicit ShellVolumes(const SoupComplex& complex) : complex_(complex) {}

  CGAL::Sign sign(const std::vector<Index>& sides) const {
    if (const std::optional<CGAL::Sign> sign = intervalSign(sides)) return *sign;
    return exactSign(sides);
  }

 private:
  // The face's corners in the order that turns its normal towards the side.
  std::array<Index, 3> corners(Index side) const {
    const TriangleIndices& face = complex_.faces[faceOf(side)];
    return isFront(side) ? std::array<Index, 3>{face[0], face[1], face[2]}
                         : std::array<Index, 3>{face[0], face[2], face[1]};
  }

  std::optional<CGAL::Sign> intervalSign(const std::vector<Index>& sides) const {
    using Interval = CGAL::Interval_nt<false>;
    const CGAL::Protect_FPU_rounding<true> rounding;
    const ExactPoint& origin = complex_.points[corners(sides.front())[0]];
    const auto relative = [&](Index point, int axis) {
      return Interval(CGAL::to_interval(complex_.points[point][axis])) - Interval(CGAL::to_interval(origin[axis]));
    };
    Interval total = 0;
    for (Index side : sides) {
      const std::array<Index, 3> c = corners(side);
      Interval m[3][3];
      for (int row = 0; row < 3; ++row) {
        for (int axis = 0; axis < 3; ++axis) m[row][axis] = relative(c[row], axis);
      }
      total += m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    }
    if (total.inf() > 0) return CGAL::POSITIVE;
    if (total.sup() < 0) return CGAL::NEGATIVE;
    return std::nullopt;
  }

  CGAL::Sign exactSign(const std::vector<Index>& sides) const {
    using Exact = std::decay_t<decltype(CGAL::exact(ExactKernel::FT()))>;
    const ExactPoint& origin = complex_.points[corners(sides.front())[0]];
    Exact total = 0;
    for (Index side : sides) {
      const std::array<Index, 3> c = corners(side);
      Exact m[3][3];
      for (int row = 0; row < 3; ++row) {
        for (int axis = 0; axis < 3; ++axis) {
          m[row][axis] = CGAL::exact(complex_.points[c[row]][axis]) - CGAL::exact(origin[axis]);
        }
      }
      total += m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    }
    return CGAL::sign(total);
  }

  const SoupComplex& complex_;
};

// Cells: sides joined around edges into shells, shells into cells by rays. A cell is
// bounded exactly when one of its shells is its outer boundary (negative volume): the
// unbounded cell has none. So a shell needs a ray only when it bounds a hole of its
// cell (or nothing), to find the cell's other shells; a ray that meets its own shell
// again is tried from other faces of the shell. A hole's shell whose rays find no
// other shell stays a cell of its own, counted unbounded: that can only happen inside
// the solid, where such a shell then bounds a closed piece that overlaps the solid.
class Cells {
 public:
  Cells(const SoupComplex& complex, const EdgeFans& fans) : sides_(2 * complex.faces.size()) {
    for (const std::vector<EdgeFace>& fan : fans.fans()) {
      for (std::size_t i = 0; i < fan.size(); ++i) sides_.unite(risingSide(fan[i]), fallingSide(fan[(i + 1) % fan.size()]));
    }
    std::vector<std::pair<Index, Index>> shellOfSide;  // (shell: a side of it, side), by shell then side
    for (Index side = 0; side < 2 * complex.faces.size(); ++side) shellOfSide.emplace_back(sides_.find(side), side);
    std::sort(shellOfSide.begin(), shellOfSide.end());
    std::vector<std::pair<Index, std::vector<Index>>> shells;  // shell -> its sides
    for (const auto& [shell, side] : shellOfSide) {
      if (shells.empty() || shells.back().first != shell) shells.emplace_back(shell, std::vector<Index>{});
      shells.back().second.push_back(side);
    }
    const ShellVolumes volumes(complex);
    const RayCaster rays(complex);
    std::vector<Index> outerShells;
    for (const auto& [first, members] : shells) {
      if (volumes.sign(members) == CGAL::NEGATIVE) {
        outerShells.push_back(first);
      } else {
        linkByRay(first, members, rays);
      }
    }
    bounded_.assign(2 * complex.faces.size(), false);
    for (Index shell : outerShells) bounded_[sides_.find(shell)] = true;
  }

  bool isOutside(Index side) { return !bounded_[sides_.find(side)]; }
  Index cellOf(Index side) { return sides_.find(side); }

  std::size_t boundedCount() { return static_cast<std::size_t>(std::count(bounded_.begin(), bounded_.end(), true)); }

 private:
  static constexpr std::size_t kFacesTried = 8;

  void linkByRay(Index shell, const std::vector<Index>& members, const RayCaster& rays) {
    const std::size_t step = std::max<std::size_t>(1, members.size() / kFacesTried);
    for (std::size_t i = 0; i < members.size(); i += step) {
      const std::optional<Index> hit = rays.firstHit(members[i]);
      if (!hit) return;  // escaped: an unbounded cell, which needs no link
      if (sides_.find(*hit) != shell) {
        sides_.unite(shell, *hit);
        return;
      }
    }
  }

  DisjointSets sides_;
  std::vector<bool> bounded_;
};

// Whether two triangles share an area, decided exactly.
bool shareArea(const ExactKernel::Triangle_3& first, const ExactKernel::Triangle_3& second) {
  const auto intersection = CGAL::intersection(first, second);
  return intersection && hasArea(*intersection);
}

OpenFace openFace(const SoupComplex& complex, Index face) {
  const Index source = complex.sourceTriangle[face];
  OpenFace open{{source}, {}};
  const ExactKernel::Triangle_3 faceTriangle = exactTriangle(complex.points, complex.faces[face]);
  if (complex.clusterOf[face] != SoupComplex::kNoCluster) {
    for (const auto& [member, corners] : complex.clusters[complex.clusterOf[face]]) {
      if (member != source && shareArea(faceTriangle, exactTriangle(complex.points, corners))) {
        open.sourceTriangles.push_back(member);
      }
    }
  }
  for (Index corner : complex.faces[face]) {
    const ExactPoint& point = complex.points[corner];
    open.bounds.extend(Point3(CGAL::to_double(point.x()), CGAL::to_double(point.y()), CGAL::to_double(point.z())));
  }
  return open;
}

// The complex without the faces of withdrawn caps (soup triangles from firstCap on).
SoupComplex withoutWithdrawnCaps(const SoupComplex& complex, Index firstCap, const std::vector<bool>& withdrawn) {
  SoupComplex kept;
  kept.points = complex.points;
  kept.clusters = complex.clusters;
  for (Index face = 0; face < complex.faces.size(); ++face) {
    const Index source = complex.sourceTriangle[face];
    if (source >= firstCap && withdrawn[source - firstCap]) continue;
    kept.faces.push_back(complex.faces[face]);
    kept.sourceTriangle.push_back(source);
    kept.clusterOf.push_back(complex.clusterOf[face]);
  }
  return kept;
}

double approximateArea(const SoupComplex& complex, Index face) {
  const TriangleIndices& corners = complex.faces[face];
  return std::sqrt(CGAL::to_double(CGAL::squared_area(complex.points[corners[0]], complex.points[corners[1]],
                                                      complex.points[corners[2]])));
}

// Withdraws the caps of every enclosed region whose caps make up half its boundary or
// more: a missing face of a convex piece is always less than the others together,
// while a courtyard capped at its floor and its sky is mostly caps. A region's
// boundary is every face side in it, whatever lies on the other side. Returns whether
// it withdrew any.
bool withdrawDominantCaps(const SoupComplex& complex, Cells& cells, Index firstCap, std::vector<bool>& withdrawn) {
  struct Areas {
    double caps = 0;
    double total = 0;
    std::vector<Index> capSources;
  };
  std::map<Index, Areas> areasOfCell;  // bounded cell -> its boundary's areas
  for (Index side = 0; side < 2 * complex.faces.size(); ++side) {
    if (cells.isOutside(side)) continue;
    Areas& areas = areasOfCell[cells.cellOf(side)];
    const double area = approximateArea(complex, faceOf(side));
    areas.total += area;
    const Index source = complex.sourceTriangle[faceOf(side)];
    if (source < firstCap) continue;
    areas.caps += area;
    areas.capSources.push_back(source - firstCap);
  }
  bool any = false;
  for (const auto& [cell, areas] : areasOfCell) {
    if (areas.capSources.empty() || areas.caps < areas.total / 2) continue;
    for (Index cap : areas.capSources) withdrawn[cap] = true;
    any = true;
  }
  return any;
}

// A face whose corners all lie within the tolerance of one line.
bool isSliver(const SoupComplex& complex, Index face, double tolerance) {
  Point3 corners[3];
  for (int i = 0; i < 3; ++i) {
    const ExactPoint& point = complex.points[complex.faces[face][i]];
    corners[i] = Point3(CGAL::to_double(point.x()), CGAL::to_double(point.y()), CGAL::to_double(point.z()));
  }
  const double longest = std::max({(corners[1] - corners[0]).norm(), (corners[2] - corners[1]).norm(),
                                   (corners[0] - corners[2]).norm()});
  return (corners[1] - corners[0]).cross(corners[2] - corners[0]).norm() <= tolerance * longest;
}

// The faces of a complex whose cells are known, sorted into boundary, internal and
// open ones; boundary faces are paired across the solid: around an edge, each wedge
// of solid between two boundary faces (other faces left out) pairs them.
EnclosedSolid classifiedFaces(const SoupComplex& complex, const EdgeFans& fans, Cells& cells, Index firstCap,
                              double tolerance) {
  EnclosedSolid solid;
  solid.boundedCells = cells.boundedCount();
  const auto isBoundary = [&](Index face) { return cells.isOutside(frontSide(face)) != cells.isOutside(backSide(face)); };
  std::vector<BoundaryPairing> pairings;
  for (const std::vector<EdgeFace>& fan : fans.fans()) {
    std::vector<EdgeFace> boundary;
    std::copy_if(fan.begin(), fan.end(), std::back_inserter(boundary), [&](const EdgeFace& entry) { return isBoundary(entry.face); });
    for (std::size_t i = 0; i < boundary.size(); ++i) {
      if (cells.isOutside(risingSide(boundary[i]))) continue;
      const TriangleIndices& corners = complex.faces[boundary[i].face];
      const Index next = boundary[(i + 1) % boundary.size()].face;
      pairings.push_back({boundary[i].face, next, sharedEdge(corners, complex.faces[next])});
    }
  }
  std::vector<BoundaryFace> boundaryFaces;
  for (Index face = 0; face < complex.faces.size(); ++face) {
    const bool frontOutside = cells.isOutside(frontSide(face)), backOutside = cells.isOutside(backSide(face));
    const bool cap = complex.sourceTriangle[face] >= firstCap;
    if (frontOutside != backOutside) {
      if (cap) ++solid.capFaces;
      boundaryFaces.push_back({face, backOutside});
    } else if (!cap && !frontOutside) {
      ++solid.internalFaces;
    } else if (!cap && !isSliver(complex, face, tolerance)) {
      solid.openFaces.push_back(openFace(complex, face));
    }
  }
  assembleBoundary(complex, boundaryFaces, pairings, tolerance, solid);
  return solid;
}

}  // namespace

EnclosedSolid enclosedSolid(const SoupComplex& complex, Index firstCap, double tolerance) {
  const Index sources = complex.sourceTriangle.empty()
                            ? 0
                            : *std::max_element(complex.sourceTriangle.begin(), complex.sourceTriangle.end()) + 1;
  std::vector<bool> withdrawn(std::max(sources, firstCap) - firstCap, false);
  for (;;) {
    const SoupComplex kept = withoutWithdrawnCaps(complex, firstCap, withdrawn);
    const EdgeFans fans(kept);
    Cells cells(kept, fans);
    if (!withdrawDominantCaps(kept, cells, firstCap, withdrawn)) {
      return classifiedFaces(kept, fans, cells, firstCap, tolerance);
    }
  }
}

EnclosedSolid enclosedSolid(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles,
                            double tolerance) {
  const PlanarCaps caps = planarCaps(vertices, triangles, tolerance);
  std::vector<ExactPoint> points;
  points.reserve(vertices.size() + caps.newPoints.size());
  for (const Point3& vertex : vertices) points.emplace_back(vertex.x(), vertex.y(), vertex.z());
  points.insert(points.end(), caps.newPoints.begin(), caps.newPoints.end());
  std::vector<TriangleIndices> all = triangles;
  all.insert(all.end(), caps.triangles.begin(), caps.triangles.end());

  const Index firstCap = static_cast<Index>(triangles.size());
  std::vector<std::pair<Index, Index>> pairs = meetingPairs(vertices, triangles);
  const std::size_t soupPairs = pairs.size();
  const std::vector<std::pair<Index, Index>> withCaps = capMeetingPairs(points, all, firstCap);
  pairs.insert(pairs.end(), withCaps.begin(), withCaps.end());

  const SoupComplex complex = refineSoup(vertices, points, all, pairs, firstCap);
  EnclosedSolid solid = enclosedSolid(complex, firstCap, tolerance);
  solid.meetingPairs = soupPairs;
  solid.refinedTriangles = complex.refinedTriangles;
  return solid;
}

}  // namespace freespace::detail
