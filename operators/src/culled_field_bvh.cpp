// Building the element hierarchy of a culled field (culled_field_bvh.hpp).
#include "culled_field_bvh.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace genmod::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double centre(const BvhItem& it, int axis) { return 0.5 * (it.lo[axis] + it.hi[axis]); }

// The bounds and remainder maxima of items [begin, end).
void summarize(BvhNode& n, std::span<const BvhItem> items) {
  n.lo = {kInf, kInf, kInf};
  n.hi = {-kInf, -kInf, -kInf};
  n.cull2 = 0;
  n.remainders = 0;
  n.weight = n.radius = n.taper = 0;
  n.compact2 = 0;
  for (std::uint32_t k = n.begin; k < n.end; ++k) {
    const BvhItem& it = items[k];
    for (int i = 0; i < 3; ++i) n.lo[i] = std::min(n.lo[i], it.lo[i]), n.hi[i] = std::max(n.hi[i], it.hi[i]);
    n.cull2 = std::max(n.cull2, it.cull2);
    if (!it.remainder) {
      n.compact2 = std::max(n.compact2, it.cull2);
      continue;
    }
    ++n.remainders;
    n.weight = std::max(n.weight, it.weight);
    n.radius = std::max(n.radius, it.radius);
    n.taper = std::max(n.taper, it.taper);
  }
}

}  // namespace

ElementBvh::ElementBvh(std::vector<BvhItem> items) : items_(std::move(items)) {
  if (items_.empty()) return;
  if (items_.size() > std::numeric_limits<std::uint32_t>::max() / 2) throw std::invalid_argument("culled_field: too many elements");
  nodes_.reserve(2 * items_.size() / kLeafSize + 2);
  nodes_.push_back({});
  nodes_[0].begin = 0;
  nodes_[0].end = static_cast<std::uint32_t>(items_.size());
  // Top down with a work list of nodes to split (iterative: no recursion on the depth).
  std::vector<std::uint32_t> work{0};
  while (!work.empty()) {
    const std::uint32_t at = work.back();
    work.pop_back();
    summarize(nodes_[at], items_);
    nodes_[at].child = 0;
    const std::uint32_t begin = nodes_[at].begin, end = nodes_[at].end;
    if (end - begin <= static_cast<std::uint32_t>(kLeafSize)) continue;
    // The longest axis of the centres' bounds; split at the median centre.
    double clo[3] = {kInf, kInf, kInf}, chi[3] = {-kInf, -kInf, -kInf};
    for (std::uint32_t k = begin; k < end; ++k)
      for (int i = 0; i < 3; ++i) clo[i] = std::min(clo[i], centre(items_[k], i)), chi[i] = std::max(chi[i], centre(items_[k], i));
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (chi[i] - clo[i] > chi[axis] - clo[axis]) axis = i;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end, [axis](const BvhItem& a, const BvhItem& b) {
      const double ca = centre(a, axis), cb = centre(b, axis);
      return ca < cb || (ca == cb && a.index < b.index);
    });
    const auto child = static_cast<std::uint32_t>(nodes_.size());
    nodes_[at].child = child;
    BvhNode left{}, right{};
    left.begin = begin, left.end = mid;
    right.begin = mid, right.end = end;
    nodes_.push_back(left);
    nodes_.push_back(right);
    work.push_back(child + 1);
    work.push_back(child);
  }
  // Depth check for the query's fixed stack (median splits halve the count at each level).
  std::vector<std::pair<std::uint32_t, int>> walk{{0, 0}};
  while (!walk.empty()) {
    const auto [n, depth] = walk.back();
    walk.pop_back();
    if (depth > kMaxDepth) throw std::logic_error("culled_field: hierarchy deeper than expected");
    if (nodes_[n].child != 0) walk.push_back({nodes_[n].child, depth + 1}), walk.push_back({nodes_[n].child + 1, depth + 1});
  }
}

}  // namespace genmod::detail
