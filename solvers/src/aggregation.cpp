#include "genmod/solvers/aggregation.hpp"

#include "union_find.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace genmod {

namespace {

using detail::UnionFind;

}  // namespace

bool touches(std::span<const Interval> a, std::span<const Interval> b, double gap) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].is_empty() || b[i].is_empty() || a[i].hi() + gap < b[i].lo() || b[i].hi() + gap < a[i].lo()) return false;
  return true;
}

std::vector<Aggregate> aggregate(std::span<const Box> boxes, double gap) {
  if (!(gap >= 0.0)) throw std::invalid_argument("genmod: aggregate: gap must be >= 0");
  const std::size_t n = boxes.size();
  if (n == 0) return {};
  const std::size_t dim = boxes[0].size();
  for (std::size_t i = 0; i < n; ++i)
    if (boxes[i].size() != dim)
      throw std::invalid_argument("genmod: aggregate: box " + std::to_string(i) + " has " +
                                  std::to_string(boxes[i].size()) + " sides, box 0 has " + std::to_string(dim));
  UnionFind uf(n);
  if (dim == 0) {
    for (std::size_t i = 1; i < n; ++i) uf.unite(0, i);
  } else {
    // Sweep along side 0: only boxes whose side-0 intervals overlap can touch.
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return boxes[a][0].lo() < boxes[b][0].lo() || (boxes[a][0].lo() == boxes[b][0].lo() && a < b);
    });
    for (std::size_t p = 0; p < n; ++p) {
      const Box& a = boxes[order[p]];
      for (std::size_t q = p + 1; q < n && boxes[order[q]][0].lo() <= a[0].hi() + gap; ++q)
        if (touches(a, boxes[order[q]], gap)) uf.unite(order[p], order[q]);
    }
  }
  // Groups, then merge groups whose hulls intersect until none do.
  std::vector<Aggregate> groups;
  std::vector<std::size_t> group_of(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = uf.find(i);
    if (group_of[r] == n) {
      group_of[r] = groups.size();
      groups.push_back({boxes[i], {}});
    }
    Aggregate& g = groups[group_of[r]];
    g.members.push_back(i);
    g.hull = hull(g.hull, boxes[i]);
  }
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t a = 0; a < groups.size(); ++a)
      for (std::size_t b = a + 1; b < groups.size();) {
        if (!touches(groups[a].hull, groups[b].hull, gap)) {
          ++b;
          continue;
        }
        groups[a].hull = hull(groups[a].hull, groups[b].hull);
        groups[a].members.insert(groups[a].members.end(), groups[b].members.begin(), groups[b].members.end());
        groups.erase(groups.begin() + static_cast<std::ptrdiff_t>(b));
        merged = true;
        b = a + 1;  // the hull grew: check the later groups again
      }
  }
  for (Aggregate& g : groups) std::sort(g.members.begin(), g.members.end());
  std::sort(groups.begin(), groups.end(),
            [](const Aggregate& a, const Aggregate& b) { return a.members.front() < b.members.front(); });
  return groups;
}

}  // namespace genmod
