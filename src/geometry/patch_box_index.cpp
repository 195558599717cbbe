#include "freespace/geometry/patch_box_index.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/iterator/function_output_iterator.hpp>

namespace freespace {

namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BoxPoint = bg::model::point<double, 3, bg::cs::cartesian>;
using Box = bg::model::box<BoxPoint>;
using BoxEntry = std::pair<Box, std::uint32_t>;

Box toBox(const PatchBox& box) {
  return {BoxPoint(box.low[0], box.low[1], box.low[2]), BoxPoint(box.high[0], box.high[1], box.high[2])};
}

}  // namespace

struct PatchBoxIndex::Tree {
  bgi::rtree<BoxEntry, bgi::rstar<16>> rtree;
};

PatchBoxIndex::PatchBoxIndex(const std::vector<PatchGeometry>& patches) : tree_(std::make_unique<Tree>()) {
  std::vector<BoxEntry> entries;
  for (std::uint32_t i = 0; i < patches.size(); ++i) {
    for (const PatchBox& box : patchBoxes(patches[i])) {
      boxes_.emplace_back(box, i);
      entries.emplace_back(toBox(box), i);
    }
  }
  tree_->rtree = bgi::rtree<BoxEntry, bgi::rstar<16>>(entries.begin(), entries.end());
}

PatchBoxIndex::~PatchBoxIndex() = default;

std::vector<std::uint32_t> PatchBoxIndex::meeting(const PatchBox& query) const {
  std::vector<BoxEntry> found;
  tree_->rtree.query(bgi::intersects(toBox(query)), std::back_inserter(found));
  std::vector<std::uint32_t> patches;
  for (const BoxEntry& entry : found) patches.push_back(entry.second);
  std::sort(patches.begin(), patches.end());
  patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
  return patches;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> PatchBoxIndex::meetingPairs() const {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& [box, patch] : boxes_) {
    const auto addPair = [&pairs, patch = patch](const BoxEntry& entry) {
      if (patch < entry.second) pairs.emplace_back(patch, entry.second);
    };
    tree_->rtree.query(bgi::intersects(toBox(box)), boost::make_function_output_iterator(addPair));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace freespace
