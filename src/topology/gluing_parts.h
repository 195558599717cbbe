#pragma once

// Pieces shared by the gluing of sub-faces across curves, spirals and horizontal
// edges (sub_face_gluing.cpp, horizontal_gluing.cpp).

#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_set>
#include <utility>

#include "freespace/topology/sub_face_gluing.h"

namespace freespace::gluing {

/// Collects glues, each glued pair of sub-faces once (at the first angle it was seen
/// at), and unmatched sub-faces, each once.
class GlueList {
 public:
  void add(SubFaceId a, SubFaceId b, GluedEdge edge, const AlgebraicAngle& at) {
    if (codeOf(b) < codeOf(a)) std::swap(a, b);
    if (seen_.insert(pairCode(a, b)).second) gluing_.glues.push_back({a, b, edge, at});
  }
  /// Whether the pair was glued already (then its angle need not be found).
  bool glued(SubFaceId a, SubFaceId b) const { return seen_.count(pairCode(a, b)) != 0; }
  void addUnmatched(SubFaceId face) {
    if (unmatched_.insert(codeOf(face)).second) gluing_.unmatched.push_back(face);
  }
  SubFaceGluing take() { return std::move(gluing_); }

 private:
  /// A sub-face as one number, ordered by patch, then face.
  static std::uint64_t codeOf(SubFaceId face) { return (std::uint64_t(face.patch) << 32) | face.face; }
  /// A pair of sub-faces as two numbers, the smaller first (either order of a, b).
  static std::pair<std::uint64_t, std::uint64_t> pairCode(SubFaceId a, SubFaceId b) {
    const std::uint64_t first = codeOf(a), second = codeOf(b);
    return first < second ? std::pair(first, second) : std::pair(second, first);
  }
  struct PairHash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& pair) const {
      return std::hash<std::uint64_t>()(pair.first * 0x9e3779b97f4a7c15ULL ^ pair.second);
    }
  };

  std::unordered_set<std::pair<std::uint64_t, std::uint64_t>, PairHash> seen_;
  std::unordered_set<std::uint64_t> unmatched_;
  SubFaceGluing gluing_;
};

/// Glues consecutive rays (or spokes) around a point of a cross-section, given in
/// counterclockwise order, for each of which `facesLeft` tells whether its positive
/// side faces the sector counterclockwise after it: the sector between ray a and the
/// next ray b is faced by a when a faces left and by b when b does not; two facing
/// sides are glued (seen at the angle `atOf(a, b)`), one alone is unmatched.
template <class Ray, class FacesLeft, class FaceOf, class AtOf>
void glueAround(const std::vector<Ray>& counterclockwise, const FacesLeft& facesLeft, const FaceOf& faceOf,
                GluedEdge edge, const AtOf& atOf, GlueList& glues) {
  const std::size_t count = counterclockwise.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Ray &a = counterclockwise[i], &b = counterclockwise[(i + 1) % count];
    const bool aFaces = facesLeft(a), bFaces = !facesLeft(b);
    if (aFaces && bFaces) {
      const SubFaceId first = faceOf(a, true), second = faceOf(b, false);
      if (!glues.glued(first, second)) glues.add(first, second, edge, atOf(a, b));
    } else if (aFaces) {
      glues.addUnmatched(faceOf(a, true));
    } else if (bFaces) {
      glues.addUnmatched(faceOf(b, false));
    }
  }
}

bool holds(const PatchSlab& slab, const AlgebraicAngle& angle, AngleAlgebra& algebra);

/// Whether the patch's range is a whole circle without events: then its only slab
/// has its sample at its ends (a patch with several slabs, or with one from an event
/// around to it, is none).
bool wholeCircleWithoutEvents(const PatchSubdivision& subdivision, AngleAlgebra& algebra);

/// The index of the slab holding `angle`, searched from `start` on (wrapping).
std::optional<std::size_t> slabIndexAt(const PatchSubdivision& subdivision, const AlgebraicAngle& angle,
                                       AngleAlgebra& algebra, std::size_t start);

/// The slab of `subdivision` that ends at `angle` (`ending`), or starts there.
const PatchSlab* slabMeeting(const PatchSubdivision& subdivision, const AlgebraicAngle& angle, bool ending,
                             AngleAlgebra& algebra);

/// Remembers, per patch, where the last search for a slab ended: the gluing asks
/// mostly for rising angles, so the search usually ends at once.
class SlabCursor {
 public:
  SlabCursor(const std::vector<PatchSubdivision>& subdivisions, AngleAlgebra& algebra)
      : subdivisions_(subdivisions), algebra_(algebra), last_(subdivisions.size(), 0) {}

  const PatchSlab* at(std::uint32_t patch, const AlgebraicAngle& angle) {
    const auto found = slabIndexAt(subdivisions_[patch], angle, algebra_, last_[patch]);
    if (!found) return nullptr;
    last_[patch] = *found;
    return &subdivisions_[patch].slabs[*found];
  }

 private:
  const std::vector<PatchSubdivision>& subdivisions_;
  AngleAlgebra& algebra_;
  std::vector<std::size_t> last_;
};

}  // namespace freespace::gluing
