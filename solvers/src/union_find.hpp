// Private: disjoint sets over indices, with a deterministic root (the smallest index), for
// aggregating boxes into connected groups.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace genmod::detail {

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace genmod::detail
