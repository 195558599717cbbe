#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace freespace::detail {

/// Union-find over 0 .. size - 1 in which every set's representative is its smallest
/// element (so that a set's representative is the element that comes first).
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t size) : parent_(size) {
    for (std::uint32_t i = 0; i < size; ++i) parent_[i] = i;
  }

  std::uint32_t find(std::uint32_t element) {
    while (parent_[element] != element) {
      parent_[element] = parent_[parent_[element]];
      element = parent_[element];
    }
    return element;
  }

  void unite(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t rootA = find(a);
    const std::uint32_t rootB = find(b);
    parent_[std::max(rootA, rootB)] = std::min(rootA, rootB);
  }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace freespace::detail
