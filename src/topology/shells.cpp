#include "freespace/topology/shells.h"

#include <boost/pending/disjoint_sets.hpp>
#include <unordered_map>

namespace freespace {

Shells::Shells(const std::vector<PatchSubdivision>& subdivisions, const std::vector<const SubFaceGluing*>& gluings) {
  std::size_t count = 0;
  for (const PatchSubdivision& subdivision : subdivisions) {
    firstFace_.push_back(static_cast<std::uint32_t>(count));
    count += subdivision.faceCount;
  }
  std::vector<std::size_t> rank(count), parent(count);
  boost::disjoint_sets<std::size_t*, std::size_t*> sets(rank.data(), parent.data());
  for (std::size_t i = 0; i < count; ++i) sets.make_set(i);
  const auto index = [&](SubFaceId face) { return static_cast<std::size_t>(firstFace_[face.patch] + face.face); };
  for (const SubFaceGluing* gluing : gluings) {
    for (const SubFaceGlue& glue : gluing->glues) sets.union_set(index(glue.first), index(glue.second));
  }
  std::unordered_map<std::size_t, std::uint32_t> shellOfRoot;
  for (std::size_t i = 0; i < count; ++i) {
    const auto found = shellOfRoot.emplace(sets.find_set(i), static_cast<std::uint32_t>(shellOfRoot.size()));
    shellOfFace_.push_back(found.first->second);
  }
  closed_.assign(shellOfRoot.size(), true);
  for (const SubFaceGluing* gluing : gluings) {
    for (const SubFaceId& face : gluing->unmatched) closed_[shellOfFace_[index(face)]] = false;
  }
}

}  // namespace freespace
