// A bounding-volume hierarchy over the skeleton boxes of a culled field's elements
// (culled_field.hpp). Internal to operators/.
//
// Each node keeps the bounding box of its elements' skeletons, the largest cull distance
// among them and the largest remainder parameters (weight, radius, taper) of those that leave
// a remainder when culled. A box whose distance from a node's box is at least that node's cull
// distance is at least every element's own cull distance from each of them, so the whole
// subtree is culled with one test. Built once, top down, by median splits on the longest axis
// of the element centres (ties broken by index: the same input gives the same tree).
#pragma once

#include "genmod/kernel/interval.hpp"
#include "genmod/operators/skeletal.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace genmod::detail {

// A lower bound of the squared distance between a box and the axis-aligned box [lo, hi], in
// plain double arithmetic: each subtraction, square and sum is rounded with relative error
// <= 2^-52 in any rounding mode (the subtraction of two doubles is exact or correctly
// rounded), so the result shrunk by 1e-12 is below the exact one.
inline double box_distance2_below(const Point3& lo, const Point3& hi, std::span<const Interval> box) {
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    double gap = 0;
    if (box[i].lo() > hi[i]) gap = box[i].lo() - hi[i];
    else if (box[i].hi() < lo[i]) gap = lo[i] - box[i].hi();
    sum += gap * gap;
  }
  return sum * (1 - 1e-12);
}

struct BvhItem {
  std::uint32_t index;            // the element's index in the field
  Point3 lo, hi;                  // its skeleton's bounding box
  double cull2;                   // culled where a box is at least this far (squared); finite
  bool remainder;                 // leaves a remainder when culled (Gaussian kinds)
  double weight, radius, taper;   // the remainder's parameters (when `remainder`)
};

struct BvhNode {
  Point3 lo, hi;                  // the skeletons' bounding box
  double cull2;                   // the largest cull2 of the subtree
  std::uint32_t begin, end;       // its items, [begin, end) of ElementBvh::items()
  std::uint32_t child;            // the first of two children (child + 1 the second); 0: a leaf
  std::uint32_t remainders;       // the number of items with a remainder
  double weight, radius, taper;   // the largest of those items' parameters
  double compact2;                // the largest cull2 of the items without one (0: none)
};

class ElementBvh {
 public:
  ElementBvh() = default;
  explicit ElementBvh(std::vector<BvhItem> items);

  bool empty() const noexcept { return items_.empty(); }
  std::span<const BvhItem> items() const noexcept { return items_; }
  std::span<const BvhNode> nodes() const noexcept { return nodes_; }

  // Visits the hierarchy for `box`: culled(node, d2, count) for each culled subtree or, in a
  // leaf, for the `count` culled items with a remainder that the leaf holds (d2 a lower bound
  // of the squared distance from the box to all of them); near(item) for every item the box may
  // be nearer than its cull distance. Iterative (an explicit stack).
  template <class Culled, class Near>
  void query(std::span<const Interval> box, Culled&& culled, Near&& near) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[kMaxDepth + 2];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const BvhNode& n = nodes_[stack[--top]];
      const double d2 = box_distance2_below(n.lo, n.hi, box);
      if (d2 >= n.cull2) {
        if (n.remainders > 0) culled(n, d2, n.remainders);
        continue;
      }
      if (n.child != 0) {
        stack[top++] = n.child + 1;
        stack[top++] = n.child;
        continue;
      }
      std::uint32_t count = 0;
      for (std::uint32_t k = n.begin; k < n.end; ++k) {
        const BvhItem& it = items_[k];
        if (box_distance2_below(it.lo, it.hi, box) >= it.cull2) count += it.remainder ? 1 : 0;
        else near(it);
      }
      if (count > 0) culled(n, d2, count);
    }
  }

  // The same walk with the caller's tests instead of the cull distances (a point's evaluation
  // skips by its own threshold): a subtree is skipped when skip_node(node, d2) is true, an item
  // of a leaf when skip_item(item, d2) is true (d2 a lower bound of the squared distance from
  // the box to it); near(item) for every other item.
  template <class SkipNode, class SkipItem, class Near>
  void visit(std::span<const Interval> box, SkipNode&& skip_node, SkipItem&& skip_item, Near&& near) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[kMaxDepth + 2];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const BvhNode& n = nodes_[stack[--top]];
      if (skip_node(n, box_distance2_below(n.lo, n.hi, box))) continue;
      if (n.child != 0) {
        stack[top++] = n.child + 1;
        stack[top++] = n.child;
        continue;
      }
      for (std::uint32_t k = n.begin; k < n.end; ++k) {
        const BvhItem& it = items_[k];
        if (!skip_item(it, box_distance2_below(it.lo, it.hi, box))) near(it);
      }
    }
  }

  static constexpr int kLeafSize = 4;
  static constexpr int kMaxDepth = 62;  // median splits: depth <= log2(n) + 1

 private:
  std::vector<BvhItem> items_;
  std::vector<BvhNode> nodes_;
};

}  // namespace genmod::detail
