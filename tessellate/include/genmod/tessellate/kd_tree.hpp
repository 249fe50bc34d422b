// n-dimensional kd-trees with kd-addresses (Snyder 1991, §5.2.3.1 and §5.2.4.2; research
// snyder.md §5.3.1 and §5.4.2): the parameter-space subdivision of the adaptive parametric
// mesher and of CSG with trimmed surfaces.
//
// A KdTree subdivides a box (its domain) by binary splits at midpoints, one dimension per
// node. A node may lack one child (a tree may cover only part of its domain); the empty tree
// (NIL) has no nodes. Dimensions are numbered from 0 (the thesis's u = 1, v = 2, s = 3, t = 4
// are 0, 1, 2, 3 here).
//
// A KdAddress names a node independently of the order in which dimensions were split: one bit
// string per dimension, the left (0) / right (1) choices made at the splits in that dimension
// from the root. For the domain [0,1]: 00 -> [0, 0.25], 0010 -> [0.125, 0.1875], and
// (0010, 1100) -> [0.125, 0.1875] x [0.75, 0.8125].
//
// Example:
//   KdTree t = KdTree::full({Interval(0, 1), Interval(0, 1)});
//   auto [low, high] = t.split(t.root(), 1);              // [0,1]x[0,.5] and [0,1]x[.5,1]
//   KdTree s(t.domain());
//   s.insert_addonly(KdAddress::parse({"1", ""}));        // s has the leaf [.5,1]x[0,1]
//   merge_addonly(t, s);                                  // nothing to add: t covers it
//   for (KdTree::Index leaf : t.leaves()) { KdBox b = t.box(leaf); auto n = t.neighbours(leaf); }
//
// Coordinates are exact dyadic arithmetic: the point at index/2^depth of a domain side [a, b]
// is a + (b - a) * (index/2^depth) with the fraction in lowest terms (a and b themselves at 0
// and 1), so every address maps to one double per bound, whichever node computes it, and
// boxes of neighbouring nodes share their faces bitwise. On [0,1] (or any domain with dyadic
// bounds of few bits) the coordinates are exact. Depth is limited to kMaxDepth bits per
// dimension (index and index + 1 fit a double's mantissa).
//
// Node indices are positions in one vector. Building calls (make_root, split, add_child)
// append and keep every index valid; calls that can remove nodes (insert_*, merge_*) renumber
// the nodes (depth-first, low child first) and invalidate earlier indices.
//
// A KdTree is a value: copies are independent, and const members may run on several threads
// at once (there is no hidden cache).
//
// Errors (a dimension mismatch, a malformed or too deep address, a node that does not exist)
// throw std::invalid_argument naming the problem.
#pragma once

#include "genmod/kernel/interval.hpp"

#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace genmod {

// A box, one interval per dimension (the same type as the solvers' Box).
using KdBox = std::vector<Interval>;

// The path from the root to a node, one bit string per dimension.
class KdAddress {
 public:
  // Splits per dimension an address can hold (2^52 cells per side, exact in a double).
  static constexpr int kMaxDepth = 52;

  KdAddress() = default;
  // The root of a `dims`-dimensional tree (every bit string empty).
  explicit KdAddress(std::size_t dims);
  // From bit strings of '0' and '1', one per dimension: parse({"0010", "1100"}).
  static KdAddress parse(const std::vector<std::string>& bit_strings);

  std::size_t dims() const noexcept { return paths_.size(); }
  // Number of bits in dimension d.
  int depth(std::size_t d) const;
  // The bit string of dimension d read as a binary number: the node's side in dimension d is
  // [index, index + 1] / 2^depth of the domain's side.
  std::uint64_t index(std::size_t d) const;
  // Bit i (0 = the first split from the root) of dimension d.
  int bit(std::size_t d, int i) const;

  // The address one split further: side 0 (low) or 1 (high) of dimension d.
  KdAddress child(std::size_t d, int side) const;
  // The address with only the dimensions `keep` (strictly increasing), in that order.
  KdAddress restricted(std::span<const std::size_t> keep) const;
  // True if this address is an ancestor of `other` or equal to it (its bit strings are
  // prefixes of other's in every dimension).
  bool contains(const KdAddress& other) const;

  // "0010,1100" (an empty bit string prints as nothing: the 2-D root is ",").
  std::string to_string() const;

  friend auto operator<=>(const KdAddress&, const KdAddress&) = default;
  friend bool operator==(const KdAddress&, const KdAddress&) = default;

 private:
  friend class KdTree;
  // child() in place (no copy), unchecked: for the tree's own walks.
  void push(std::size_t d, int side) {
    paths_[d].index = paths_[d].index * 2 + static_cast<std::uint64_t>(side);
    ++paths_[d].depth;
  }
  struct Path {
    std::uint64_t index = 0;
    int depth = 0;
    friend auto operator<=>(const Path&, const Path&) = default;
    friend bool operator==(const Path&, const Path&) = default;
  };
  std::vector<Path> paths_;
};

// The box of an address in `domain` (exact dyadic arithmetic, see the header comment).
KdBox address_box(std::span<const Interval> domain, const KdAddress& address);
// The inverse: the address whose box is exactly `box`; throws if `box` is not the box of a
// node of `domain`.
KdAddress box_address(std::span<const Interval> domain, std::span<const Interval> box);

// One split of a tree: the node's address and the dimension it splits.
struct KdSplit {
  KdAddress address;
  std::size_t dim = 0;
  friend auto operator<=>(const KdSplit&, const KdSplit&) = default;
  friend bool operator==(const KdSplit&, const KdSplit&) = default;
};

class KdTree {
 public:
  using Index = std::int32_t;
  static constexpr Index kNone = -1;

  struct Node {
    std::array<Index, 2> child{kNone, kNone};  // low and high half; kNone = empty slot
    Index parent = kNone;
    int split_dim = -1;  // -1 for a leaf; an internal node has at least one child
  };

  // The empty tree over `domain` (finite sides of positive width, at least one dimension).
  explicit KdTree(KdBox domain);
  // A tree with one leaf, the whole domain.
  static KdTree full(KdBox domain);

  std::size_t dims() const noexcept { return domain_.size(); }
  const KdBox& domain() const noexcept { return domain_; }
  bool empty() const noexcept { return root_ == kNone; }
  Index root() const noexcept { return root_; }
  std::size_t num_nodes() const noexcept { return nodes_.size(); }
  const Node& node(Index i) const;
  bool is_leaf(Index i) const { return node(i).split_dim < 0; }

  // Building. make_root: the root leaf of an empty tree. split: a leaf becomes internal with
  // both halves of dimension d as leaves. add_child: one half (side 0 or 1) of dimension d as
  // a new leaf; a leaf becomes internal with that one child, an internal node must be split in
  // d and have that slot empty. Each returns the new node(s).
  Index make_root();
  std::array<Index, 2> split(Index leaf, std::size_t d);
  Index add_child(Index i, std::size_t d, int side);

  // Addresses and boxes.
  KdAddress address(Index i) const;
  // The node with exactly this address, or kNone.
  Index find(const KdAddress& address) const;
  KdBox box(Index i) const;
  // Every internal node as (address, split dimension), sorted.
  std::vector<KdSplit> splits() const;

  // Leaves, depth first, low child first. Together they tile the covered region: their
  // interiors are disjoint.
  std::vector<Index> leaves() const;
  // A leaf whose box contains the point (the low side on a split plane), or kNone if the point
  // is not covered. Throws for a point of the wrong dimension.
  Index leaf_containing(std::span<const double> point) const;
  // The leaves whose boxes share a face of positive (n-1)-dimensional measure with the leaf's
  // box, sorted by index. Throws if `leaf` is not a leaf.
  std::vector<Index> neighbours(Index leaf) const;

  // Adds the parts of X (the node named by `address`) that the tree does not cover yet, as
  // maximal nodes, and never splits an existing leaf: a part of X inside a leaf stays as it is.
  // Descending from the root, an empty slot on X's path gets a chain of nodes down to the part
  // of X in that slot; where X straddles a split, both halves are followed (also below X's own
  // node, so empty slots inside X are filled).
  void insert_addonly(const KdAddress& address);
  // Makes X covered without splitting any existing node: descending along X's path, an empty
  // slot gets a chain down to X, a leaf on the path covers X already, and the first node whose
  // split would cut X (the furthest ancestor of X, or X itself with a subtree below) is
  // collapsed into one leaf.
  void insert_nosubdivide(const KdAddress& address);

 private:
  friend struct KdTreeAccess;
  Index new_node(Index parent);
  void check_index(Index i, const char* who) const;

  KdBox domain_;
  std::vector<Node> nodes_;
  Index root_ = kNone;
};

// insert_addonly of every leaf of t2 into t1 (same domain). The covered region becomes the
// union of both; no leaf of t1 is split. New chains follow t2's order of splits where t2 has
// the node, so they reproduce t2's splits.
void merge_addonly(KdTree& t1, const KdTree& t2);
// insert_nosubdivide of every leaf of t2 into t1 (same domain). The covered region grows to
// contain both; the result has no split that neither input has: a chain is copied from t2
// only as far as t2 has the nodes, and ends in a larger leaf otherwise.
void merge_nosubdivide(KdTree& t1, const KdTree& t2);
// The tree over the dimensions `keep` (strictly increasing; dimension j of the result is
// keep[j]): splits in other dimensions are dropped and their subtrees merged with
// merge_nosubdivide (Fig 5.25), so the result never has a split the source does not have.
KdTree project(const KdTree& tree, std::span<const std::size_t> keep);

}  // namespace genmod
