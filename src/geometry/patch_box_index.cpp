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

bool meet(const PatchBox& a, const PatchBox& b) {
  // Theta first: pieces of two patches that meet at all are mostly apart in it.
  for (int axis : {2, 0, 1}) {
    if (a.high[axis] < b.low[axis] || b.high[axis] < a.low[axis]) return false;
  }
  return true;
}

}  // namespace

struct PatchBoxIndex::Tree {
  bgi::rtree<BoxEntry, bgi::rstar<16>> rtree;
};

PatchBoxIndex::PatchBoxIndex(const std::vector<PatchGeometry>& patches, const Cancellation& cancellation)
    : tree_(std::make_unique<Tree>()) {
  std::vector<BoxEntry> entries;
  for (std::uint32_t i = 0; i < patches.size(); ++i) {
    cancellation.check();
    for (const PatchBox& box : patchBoxes(patches[i])) {
      boxes_.emplace_back(box, i);
      entries.emplace_back(toBox(box), i);
    }
    firstPiece_.push_back(pieces_.size());
    const std::vector<PatchBox> pieces = patchBoxes(patches[i], kPieceWidth);
    pieces_.insert(pieces_.end(), pieces.begin(), pieces.end());
  }
  firstPiece_.push_back(pieces_.size());
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
  patches.erase(std::remove_if(patches.begin(), patches.end(),
                               [&](std::uint32_t patch) { return !pieceMeets(patch, query); }),
                patches.end());
  return patches;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> PatchBoxIndex::meetingPairs(const Cancellation& cancellation) const {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& [box, patch] : boxes_) {
    cancellation.check();
    const auto addPair = [&pairs, patch = patch](const BoxEntry& entry) {
      if (patch < entry.second) pairs.emplace_back(patch, entry.second);
    };
    tree_->rtree.query(bgi::intersects(toBox(box)), boost::make_function_output_iterator(addPair));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                             [&](const auto& pair) { return !piecesMeet(pair.first, pair.second); }),
              pairs.end());
  return pairs;
}

bool PatchBoxIndex::pieceMeets(std::uint32_t patch, const PatchBox& query) const {
  return std::any_of(pieces_.begin() + firstPiece_[patch], pieces_.begin() + firstPiece_[patch + 1],
                     [&](const PatchBox& piece) { return meet(piece, query); });
}

bool PatchBoxIndex::piecesMeet(std::uint32_t first, std::uint32_t second) const {
  return std::any_of(pieces_.begin() + firstPiece_[first], pieces_.begin() + firstPiece_[first + 1],
                     [&](const PatchBox& piece) { return pieceMeets(second, piece); });
}

}  // namespace freespace
