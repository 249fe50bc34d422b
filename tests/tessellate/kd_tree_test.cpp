// Kd-trees and kd-addresses (snyder.md §5.3.1, §5.4.2, claim 36): the address table, the
// Fig 5.24 merge example, and properties of random trees (tiling, merges, projection,
// neighbours, address <-> box round trips).
#include "genmod/tessellate/kd_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace genmod {
namespace {

using Index = KdTree::Index;

KdBox unit_box(std::size_t dims) { return KdBox(dims, Interval(0.0, 1.0)); }

// A random tree: every node splits with a probability that falls with depth, in a random
// dimension not yet split max_depth times; a split keeps both halves or only one of them.
KdTree random_tree(const KdBox& domain, int max_depth, std::mt19937& rng) {
  const std::size_t n = domain.size();
  KdTree t(domain);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  struct Item {
    Index node;
    std::vector<int> depth;
  };
  std::vector<Item> stack{{t.make_root(), std::vector<int>(n, 0)}};
  while (!stack.empty()) {
    Item it = stack.back();
    stack.pop_back();
    std::vector<std::size_t> open;
    int total = 0;
    for (std::size_t d = 0; d < n; ++d) {
      total += it.depth[d];
      if (it.depth[d] < max_depth) open.push_back(d);
    }
    if (open.empty() || u(rng) > 0.92 - 0.5 * total / (max_depth * static_cast<double>(n))) continue;
    const std::size_t d = open[std::uniform_int_distribution<std::size_t>(0, open.size() - 1)(rng)];
    const double r = u(rng);
    std::vector<int> sides = r < 0.6 ? std::vector<int>{0, 1} : r < 0.8 ? std::vector<int>{0} : std::vector<int>{1};
    for (int s : sides) {
      Item c{t.add_child(it.node, d, s), it.depth};
      ++c.depth[d];
      stack.push_back(c);
    }
  }
  return t;
}

// A random tree that splits its dimensions in turn (0, 1, ..., n-1, 0, ...), as the adaptive
// subdivision of §5.3.1 does; each split keeps both halves or one of them.
KdTree random_cyclic_tree(const KdBox& domain, int max_depth, std::mt19937& rng) {
  const std::size_t n = domain.size();
  KdTree t(domain);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::pair<Index, int>> stack{{t.make_root(), 0}};  // node, number of splits above
  while (!stack.empty()) {
    const auto [node, level] = stack.back();
    stack.pop_back();
    if (level >= max_depth * static_cast<int>(n) || u(rng) > 0.95 - 0.6 * level / (max_depth * static_cast<double>(n)))
      continue;
    const auto d = static_cast<std::size_t>(level) % n;
    const double r = u(rng);
    for (int s = 0; s < 2; ++s)
      if (r < 0.7 || (r < 0.85) == (s == 0)) stack.emplace_back(t.add_child(node, d, s), level + 1);
  }
  return t;
}

// Resolution (bits per side) of the coverage grid: at most 4096 cells, and at least the depth
// of every random tree, so no cell centre lies on a node's boundary.
int grid_bits(std::size_t dims) { return dims == 1 ? 8 : dims == 2 ? 5 : dims == 3 ? 4 : 3; }

struct Grid {
  std::size_t dims;
  int bits;
  std::size_t cells() const { return std::size_t{1} << (bits * static_cast<int>(dims)); }
  std::vector<double> centre(const KdBox& domain, std::size_t c) const {
    std::vector<double> p(dims);
    const std::size_t side = std::size_t{1} << bits;
    for (std::size_t d = 0; d < dims; ++d, c /= side) {
      const double t = (static_cast<double>(c % side) + 0.5) / static_cast<double>(side);
      p[d] = domain[d].lo() + (domain[d].hi() - domain[d].lo()) * t;
    }
    return p;
  }
};

bool box_contains(const KdBox& b, const std::vector<double>& p) {
  for (std::size_t d = 0; d < b.size(); ++d)
    if (!b[d].contains(p[d])) return false;
  return true;
}

double volume(const KdBox& b) {
  double v = 1.0;
  for (const Interval& s : b) v *= s.hi() - s.lo();
  return v;
}

// Which grid cells the tree covers; checks on the way that every covered cell centre lies in
// exactly one leaf box and that leaf_containing finds that leaf.
std::vector<bool> coverage(const KdTree& t, const Grid& g) {
  std::vector<KdBox> boxes;
  const std::vector<Index> leaves = t.leaves();
  for (Index leaf : leaves) boxes.push_back(t.box(leaf));
  std::vector<bool> covered(g.cells());
  for (std::size_t c = 0; c < g.cells(); ++c) {
    const std::vector<double> p = g.centre(t.domain(), c);
    int count = 0;
    Index found = KdTree::kNone;
    for (std::size_t k = 0; k < leaves.size(); ++k)
      if (box_contains(boxes[k], p)) {
        ++count;
        found = leaves[k];
      }
    EXPECT_LE(count, 1) << "leaves overlap at cell " << c;
    EXPECT_EQ(t.leaf_containing(p), found) << "cell " << c;
    covered[c] = count > 0;
  }
  return covered;
}

// Leaves tile the covered region: no overlap at cell centres and at random points, and the
// leaf volumes add up to the covered volume.
void expect_tiling(const KdTree& t, const Grid& g, std::mt19937& rng) {
  const std::vector<bool> covered = coverage(t, g);
  double leaf_volume = 0.0;
  for (Index leaf : t.leaves()) leaf_volume += volume(t.box(leaf));
  const double cell_volume = volume(t.domain()) / static_cast<double>(g.cells());
  const auto n_covered = static_cast<double>(std::count(covered.begin(), covered.end(), true));
  EXPECT_NEAR(leaf_volume, n_covered * cell_volume, 1e-12 * volume(t.domain()));

  std::vector<KdBox> boxes;
  for (Index leaf : t.leaves()) boxes.push_back(t.box(leaf));
  for (int k = 0; k < 200; ++k) {
    std::vector<double> p(t.dims());
    for (std::size_t d = 0; d < t.dims(); ++d)
      p[d] = std::uniform_real_distribution<double>(t.domain()[d].lo(), t.domain()[d].hi())(rng);
    int count = 0;
    for (const KdBox& b : boxes) count += box_contains(b, p) ? 1 : 0;
    EXPECT_LE(count, 1);
    EXPECT_EQ(count == 1, t.leaf_containing(p) != KdTree::kNone);
  }
}

std::set<KdAddress> leaf_addresses(const KdTree& t) {
  std::set<KdAddress> out;
  for (Index leaf : t.leaves()) out.insert(t.address(leaf));
  return out;
}

std::set<KdSplit> split_set(const KdTree& t) {
  const std::vector<KdSplit> s = t.splits();
  return {s.begin(), s.end()};
}

// ---- claim 36: the address table ----------------------------------------------------------

TEST(KdAddress, ThesisTableOnTheUnitInterval) {
  const KdBox unit = unit_box(1);
  const struct {
    const char* bits;
    double lo, hi;
  } table[] = {{"00", 0.0, 0.25}, {"01", 0.25, 0.5}, {"10", 0.5, 0.75}, {"11", 0.75, 1.0}, {"0010", 0.125, 0.1875}};
  for (const auto& row : table) {
    const KdBox b = address_box(unit, KdAddress::parse({row.bits}));
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(b[0].lo(), row.lo) << row.bits;
    EXPECT_EQ(b[0].hi(), row.hi) << row.bits;
  }
}

TEST(KdAddress, ThesisTableOnTheUnitSquare) {
  const KdBox unit = unit_box(2);
  const struct {
    const char* x;
    const char* y;
    double xlo, xhi, ylo, yhi;
  } table[] = {{"00", "00", 0.0, 0.25, 0.0, 0.25},
               {"01", "10", 0.25, 0.5, 0.5, 0.75},
               {"0010", "1100", 0.125, 0.1875, 0.75, 0.8125}};
  for (const auto& row : table) {
    const KdAddress a = KdAddress::parse({row.x, row.y});
    const KdBox b = address_box(unit, a);
    EXPECT_EQ(b[0], Interval(row.xlo, row.xhi)) << a.to_string();
    EXPECT_EQ(b[1], Interval(row.ylo, row.yhi)) << a.to_string();
    EXPECT_EQ(box_address(unit, b), a);
    EXPECT_EQ(a.to_string(), std::string(row.x) + "," + row.y);
  }
}

TEST(KdAddress, BitsIndexAndPrefixes) {
  const KdAddress a = KdAddress::parse({"0010", "1100"});
  EXPECT_EQ(a.dims(), 2u);
  EXPECT_EQ(a.depth(0), 4);
  EXPECT_EQ(a.index(0), 2u);
  EXPECT_EQ(a.index(1), 12u);
  EXPECT_EQ(a.bit(1, 0), 1);
  EXPECT_EQ(a.bit(0, 2), 1);
  EXPECT_TRUE(KdAddress::parse({"00", "1"}).contains(a));
  EXPECT_TRUE(a.contains(a));
  EXPECT_FALSE(KdAddress::parse({"01", ""}).contains(a));
  EXPECT_FALSE(a.contains(KdAddress::parse({"00", "1"})));
  EXPECT_EQ(KdAddress(2).child(0, 0).child(1, 1).child(0, 1), KdAddress::parse({"01", "1"}));
  const std::size_t keep[] = {1};
  EXPECT_EQ(a.restricted(keep), KdAddress::parse({"1100"}));
}

TEST(KdAddress, BadAddressesAreRejectedByName) {
  try {
    (void)KdAddress::parse({"01", "0x1"});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0x1"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)KdAddress::parse({std::string(KdAddress::kMaxDepth + 1, '0')}), std::invalid_argument);
  const KdAddress deep = KdAddress::parse({std::string(KdAddress::kMaxDepth, '1')});
  EXPECT_THROW((void)deep.child(0, 0), std::invalid_argument);
  EXPECT_THROW((void)deep.child(0, 2), std::invalid_argument);
  EXPECT_THROW((void)deep.bit(0, KdAddress::kMaxDepth), std::invalid_argument);
  EXPECT_THROW((void)deep.depth(1), std::invalid_argument);
  EXPECT_THROW((void)address_box(unit_box(2), deep), std::invalid_argument);
  // [0.1, 0.2] is no node's side; [0.25, 0.75] straddles the first split.
  EXPECT_THROW((void)box_address(unit_box(1), KdBox{Interval(0.1, 0.2)}), std::invalid_argument);
  EXPECT_THROW((void)box_address(unit_box(1), KdBox{Interval(0.25, 0.75)}), std::invalid_argument);
}

TEST(KdAddress, DeepestAddressesStayExactOnTheUnitInterval) {
  const std::string bits = "1" + std::string(KdAddress::kMaxDepth - 1, '0');  // 2^51 of 2^52
  const KdBox b = address_box(unit_box(1), KdAddress::parse({bits}));
  EXPECT_EQ(b[0].lo(), 0.5);
  EXPECT_EQ(b[0].hi(), 0.5 + std::ldexp(1.0, -KdAddress::kMaxDepth));
  EXPECT_EQ(box_address(unit_box(1), b), KdAddress::parse({bits}));
}

// ---- claim 36: the Fig 5.24 merge ---------------------------------------------------------

// T1 has the leaf [0,1] x [0,0.5], T2 the leaf [0.5,1] x [0,1].
KdTree fig_5_24_t1() {
  KdTree t(unit_box(2));
  t.add_child(t.make_root(), 1, 0);
  return t;
}
KdTree fig_5_24_t2() {
  KdTree t(unit_box(2));
  t.add_child(t.make_root(), 0, 1);
  return t;
}

TEST(KdTree, Fig524MergeAddOnlyKeepsTheLeafOfT1) {
  KdTree t1 = fig_5_24_t1();
  const KdTree t2 = fig_5_24_t2();
  ASSERT_EQ(t1.leaves().size(), 1u);
  EXPECT_EQ(t1.box(t1.leaves()[0]), (KdBox{Interval(0, 1), Interval(0, 0.5)}));
  EXPECT_EQ(t2.box(t2.leaves()[0]), (KdBox{Interval(0.5, 1), Interval(0, 1)}));
  const KdAddress t1_leaf = t1.address(t1.leaves()[0]);

  merge_addonly(t1, t2);
  const std::vector<Index> leaves = t1.leaves();
  ASSERT_EQ(leaves.size(), 2u);
  const Index kept = t1.find(t1_leaf);
  ASSERT_NE(kept, KdTree::kNone);
  EXPECT_TRUE(t1.is_leaf(kept));  // not subdivided
  std::set<std::vector<double>> boxes;
  for (Index leaf : leaves) {
    const KdBox b = t1.box(leaf);
    boxes.insert({b[0].lo(), b[0].hi(), b[1].lo(), b[1].hi()});
  }
  // The part of T2's leaf that T1 does not cover.
  EXPECT_EQ(boxes, (std::set<std::vector<double>>{{0, 1, 0, 0.5}, {0.5, 1, 0.5, 1}}));
  // They share the face y = 0.5, 0.5 <= x <= 1.
  EXPECT_EQ(t1.neighbours(leaves[0]), std::vector<Index>{leaves[1]});
  EXPECT_EQ(t1.neighbours(leaves[1]), std::vector<Index>{leaves[0]});
}

TEST(KdTree, Fig524MergeNoSubdivideGivesTheRoot) {
  KdTree t1 = fig_5_24_t1();
  merge_nosubdivide(t1, fig_5_24_t2());
  const std::vector<Index> leaves = t1.leaves();
  ASSERT_EQ(leaves.size(), 1u);
  EXPECT_EQ(leaves[0], t1.root());
  EXPECT_EQ(t1.box(leaves[0]), unit_box(2));
  EXPECT_TRUE(t1.splits().empty());
}

// ---- insertions on small trees ------------------------------------------------------------

TEST(KdTree, InsertAddOnlyHangsAChainInAnEmptyTree) {
  KdTree t(unit_box(2));
  const KdAddress x = KdAddress::parse({"01", "1"});
  t.insert_addonly(x);
  ASSERT_EQ(t.leaves().size(), 1u);
  EXPECT_EQ(t.address(t.leaves()[0]), x);
  EXPECT_EQ(t.num_nodes(), 4u);  // root and three splits
  EXPECT_EQ(t.box(t.leaves()[0]), (KdBox{Interval(0.25, 0.5), Interval(0.5, 1)}));
}

TEST(KdTree, InsertAddOnlyInsideALeafChangesNothing) {
  KdTree t = KdTree::full(unit_box(2));
  t.split(t.root(), 0);
  const std::vector<KdSplit> before = t.splits();
  t.insert_addonly(KdAddress::parse({"011", "10"}));
  EXPECT_EQ(t.splits(), before);
  EXPECT_EQ(t.leaves().size(), 2u);
}

TEST(KdTree, InsertAddOnlyFillsTheHolesBelowX) {
  // The root is X itself, split with one hole at the low half of x: addonly fills the hole.
  KdTree t(unit_box(2));
  const Index high = t.add_child(t.make_root(), 0, 1);
  t.add_child(high, 1, 0);
  t.insert_addonly(KdAddress(2));
  EXPECT_EQ(leaf_addresses(t), (std::set<KdAddress>{KdAddress::parse({"0", ""}), KdAddress::parse({"1", "0"}),
                                                   KdAddress::parse({"1", "1"})}));
}

TEST(KdTree, InsertNoSubdivideCollapsesTheSubtreeThatWouldCutX) {
  KdTree t = KdTree::full(unit_box(2));
  const auto [low, high] = t.split(t.root(), 0);
  t.split(low, 1);
  t.split(high, 0);
  // X = the low half of y straddles the root's split in x: the whole tree collapses.
  KdTree a = t;
  a.insert_nosubdivide(KdAddress::parse({"", "0"}));
  EXPECT_EQ(a.num_nodes(), 1u);
  // X = the left half is a node with a subtree: that subtree collapses, the right one stays.
  KdTree b = t;
  b.insert_nosubdivide(KdAddress::parse({"0", ""}));
  EXPECT_EQ(leaf_addresses(b), (std::set<KdAddress>{KdAddress::parse({"0", ""}), KdAddress::parse({"10", ""}),
                                                   KdAddress::parse({"11", ""})}));
  // X inside a leaf: nothing changes.
  KdTree c = t;
  c.insert_nosubdivide(KdAddress::parse({"111", "0"}));
  EXPECT_EQ(c.splits(), t.splits());
}

TEST(KdTree, MergesOfDifferentlyInterleavedTrees) {
  // T1 splits x first and has the leaf x < 0.5; T2 splits y first, then x: leaves (0,0), (1,0).
  KdTree t1(unit_box(2));
  t1.add_child(t1.make_root(), 0, 0);
  KdTree t2(unit_box(2));
  t2.split(t2.add_child(t2.make_root(), 1, 0), 0);
  // addonly adds exactly the missing quarter x > 0.5, y < 0.5.
  KdTree a = t1;
  merge_addonly(a, t2);
  EXPECT_EQ(leaf_addresses(a), (std::set<KdAddress>{KdAddress::parse({"0", ""}), KdAddress::parse({"1", "0"})}));
  // nosubdivide may not split x > 0.5 in y (neither tree has that split): it takes the whole half.
  KdTree b = t1;
  merge_nosubdivide(b, t2);
  EXPECT_EQ(leaf_addresses(b), (std::set<KdAddress>{KdAddress::parse({"0", ""}), KdAddress::parse({"1", ""})}));
  EXPECT_EQ(b.splits(), t1.splits());
}

TEST(KdTree, MergeWithItselfChangesNothing) {
  std::mt19937 rng(77);
  for (int trial = 0; trial < 5; ++trial) {
    const KdTree t = random_tree(unit_box(3), 4, rng);
    KdTree a = t;
    merge_addonly(a, a);
    EXPECT_EQ(a.splits(), t.splits());
    EXPECT_EQ(leaf_addresses(a), leaf_addresses(t));
    KdTree b = t;
    merge_nosubdivide(b, b);
    EXPECT_EQ(b.splits(), t.splits());
    EXPECT_EQ(leaf_addresses(b), leaf_addresses(t));
  }
}

TEST(KdTree, ErrorsNameTheProblem) {
  EXPECT_THROW(KdTree(KdBox{}), std::invalid_argument);
  EXPECT_THROW(KdTree(KdBox{Interval(1, 1)}), std::invalid_argument);
  EXPECT_THROW(KdTree(KdBox{Interval(0, std::numeric_limits<double>::infinity())}), std::invalid_argument);
  KdTree t2 = KdTree::full(unit_box(2));
  const KdTree t3 = KdTree::full(unit_box(3));
  try {
    merge_addonly(t2, t3);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("3-dimensional"), std::string::npos) << e.what();
  }
  EXPECT_THROW(merge_nosubdivide(t2, KdTree::full({Interval(0, 1), Interval(0, 2)})), std::invalid_argument);
  EXPECT_THROW(t2.insert_addonly(KdAddress(3)), std::invalid_argument);
  EXPECT_THROW(t2.insert_nosubdivide(KdAddress(1)), std::invalid_argument);
  EXPECT_THROW((void)t2.find(KdAddress(3)), std::invalid_argument);
  EXPECT_THROW((void)t2.node(5), std::invalid_argument);
  EXPECT_THROW(t2.split(t2.root(), 2), std::invalid_argument);
  EXPECT_THROW(t2.make_root(), std::invalid_argument);
  const auto kids = t2.split(t2.root(), 0);
  EXPECT_THROW(t2.split(t2.root(), 1), std::invalid_argument);    // not a leaf
  EXPECT_THROW(t2.add_child(t2.root(), 0, 0), std::invalid_argument);  // slot taken
  EXPECT_THROW((void)t2.neighbours(t2.root()), std::invalid_argument);
  EXPECT_NO_THROW((void)t2.neighbours(kids[0]));
  const double point[] = {0.5};
  EXPECT_THROW((void)t2.leaf_containing(point), std::invalid_argument);
  const std::size_t bad_order[] = {1, 0};
  const std::size_t out_of_range[] = {0, 3};
  EXPECT_THROW((void)project(t2, bad_order), std::invalid_argument);
  EXPECT_THROW((void)project(t2, out_of_range), std::invalid_argument);
  EXPECT_THROW((void)project(t2, std::span<const std::size_t>{}), std::invalid_argument);
}

TEST(KdTree, DepthLimitIsReported) {
  KdTree t = KdTree::full(unit_box(1));
  Index i = t.root();
  for (int k = 0; k < KdAddress::kMaxDepth; ++k) i = t.add_child(i, 0, 1);
  EXPECT_THROW(t.add_child(i, 0, 0), std::invalid_argument);
  EXPECT_EQ(t.address(i), KdAddress::parse({std::string(KdAddress::kMaxDepth, '1')}));
}

// ---- properties of random trees -----------------------------------------------------------

class RandomKdTrees : public ::testing::TestWithParam<std::size_t> {};

TEST_P(RandomKdTrees, LeavesTileTheCoveredRegion) {
  const std::size_t n = GetParam();
  const Grid g{n, grid_bits(n)};
  std::mt19937 rng(1000 + static_cast<unsigned>(n));
  for (int trial = 0; trial < 8; ++trial) {
    const KdTree t = random_tree(unit_box(n), g.bits, rng);
    expect_tiling(t, g, rng);
  }
}

TEST_P(RandomKdTrees, AddressesAndBoxesRoundTrip) {
  const std::size_t n = GetParam();
  std::mt19937 rng(2000 + static_cast<unsigned>(n));
  KdBox odd_domain;
  for (std::size_t d = 0; d < n; ++d) odd_domain.push_back(Interval(-2.0 + 0.5 * static_cast<double>(d), 3.0));
  for (const KdBox& domain : {unit_box(n), odd_domain}) {
    for (int trial = 0; trial < 6; ++trial) {
      const KdTree t = random_tree(domain, grid_bits(n), rng);
      for (std::size_t i = 0; i < t.num_nodes(); ++i) {
        const auto idx = static_cast<Index>(i);
        const KdAddress a = t.address(idx);
        EXPECT_EQ(t.find(a), idx) << a.to_string();
        const KdBox b = t.box(idx);
        EXPECT_EQ(address_box(domain, a), b);
        EXPECT_EQ(box_address(domain, b), a) << a.to_string();
        // A child's box is one half of its parent's.
        const Index p = t.node(idx).parent;
        if (p != KdTree::kNone) {
          const KdBox pb = t.box(p);
          const auto d = static_cast<std::size_t>(t.node(p).split_dim);
          for (std::size_t e = 0; e < n; ++e) {
            if (e != d) {
              EXPECT_EQ(b[e], pb[e]);
            }
          }
          EXPECT_TRUE(b[d].lo() == pb[d].lo() || b[d].hi() == pb[d].hi());
          EXPECT_EQ(b[d].hi() - b[d].lo(), 0.5 * (pb[d].hi() - pb[d].lo()));
        }
      }
      // Addresses of empty slots are no nodes.
      for (Index leaf : t.leaves()) {
        const KdAddress a = t.address(leaf);
        EXPECT_EQ(t.find(a.child(0, 0)), KdTree::kNone);
      }
    }
  }
}

TEST_P(RandomKdTrees, NeighboursAreSymmetricAndShareAFace) {
  const std::size_t n = GetParam();
  std::mt19937 rng(3000 + static_cast<unsigned>(n));
  KdBox domain;
  for (std::size_t d = 0; d < n; ++d) domain.push_back(Interval(-1.0, 0.5 + static_cast<double>(d)));
  for (int trial = 0; trial < 6; ++trial) {
    const KdTree t = random_tree(domain, grid_bits(n), rng);
    const std::vector<Index> leaves = t.leaves();
    std::vector<KdBox> boxes;
    for (Index leaf : leaves) boxes.push_back(t.box(leaf));
    for (std::size_t a = 0; a < leaves.size(); ++a) {
      // Brute force over the boxes: touching in one dimension, overlapping with positive
      // length in all the others.
      std::vector<Index> expected;
      for (std::size_t b = 0; b < leaves.size(); ++b) {
        if (a == b) continue;
        int touching = 0, overlapping = 0;
        for (std::size_t d = 0; d < n; ++d) {
          const Interval& p = boxes[a][d];
          const Interval& q = boxes[b][d];
          if (p.hi() == q.lo() || q.hi() == p.lo())
            ++touching;
          else if (std::max(p.lo(), q.lo()) < std::min(p.hi(), q.hi()))
            ++overlapping;
        }
        if (touching == 1 && overlapping == static_cast<int>(n) - 1) expected.push_back(leaves[b]);
      }
      std::sort(expected.begin(), expected.end());
      const std::vector<Index> got = t.neighbours(leaves[a]);
      EXPECT_EQ(got, expected);
      for (Index m : got) {
        const std::vector<Index> back = t.neighbours(m);
        EXPECT_TRUE(std::binary_search(back.begin(), back.end(), leaves[a]));
      }
    }
  }
}

TEST_P(RandomKdTrees, MergeAddOnlyCoversTheUnionAndKeepsTheLeavesOfT1) {
  const std::size_t n = GetParam();
  const Grid g{n, grid_bits(n)};
  std::mt19937 rng(4000 + static_cast<unsigned>(n));
  for (int trial = 0; trial < 8; ++trial) {
    const KdTree t1 = random_tree(unit_box(n), g.bits, rng);
    const KdTree t2 = random_tree(unit_box(n), g.bits, rng);
    KdTree m = t1;
    merge_addonly(m, t2);
    const std::vector<bool> c1 = coverage(t1, g), c2 = coverage(t2, g), cm = coverage(m, g);
    for (std::size_t c = 0; c < g.cells(); ++c) EXPECT_EQ(cm[c], c1[c] || c2[c]) << "cell " << c;
    for (const KdAddress& a : leaf_addresses(t1)) {
      const Index i = m.find(a);
      ASSERT_NE(i, KdTree::kNone) << a.to_string();
      EXPECT_TRUE(m.is_leaf(i)) << "leaf " << a.to_string() << " of T1 was split";
    }
    // Every split of T1 survives: addonly only adds.
    const std::set<KdSplit> s1 = split_set(t1), sm = split_set(m);
    EXPECT_TRUE(std::includes(sm.begin(), sm.end(), s1.begin(), s1.end()));
    expect_tiling(m, g, rng);
    // Merging into an empty tree reproduces T2.
    KdTree e(unit_box(n));
    merge_addonly(e, t2);
    EXPECT_EQ(e.splits(), t2.splits());
    EXPECT_EQ(leaf_addresses(e), leaf_addresses(t2));
  }
}

TEST_P(RandomKdTrees, MergeNoSubdivideCreatesNoNewSplit) {
  const std::size_t n = GetParam();
  const Grid g{n, grid_bits(n)};
  std::mt19937 rng(5000 + static_cast<unsigned>(n));
  for (int trial = 0; trial < 8; ++trial) {
    const KdTree t1 = random_tree(unit_box(n), g.bits, rng);
    const KdTree t2 = random_tree(unit_box(n), g.bits, rng);
    KdTree m = t1;
    merge_nosubdivide(m, t2);
    std::set<KdSplit> allowed = split_set(t1);
    for (const KdSplit& s : t2.splits()) allowed.insert(s);
    for (const KdSplit& s : m.splits())
      EXPECT_TRUE(allowed.count(s)) << "split of " << s.address.to_string() << " in dimension " << s.dim;
    const std::vector<bool> c1 = coverage(t1, g), c2 = coverage(t2, g), cm = coverage(m, g);
    for (std::size_t c = 0; c < g.cells(); ++c) {
      if (c1[c] || c2[c]) {
        EXPECT_TRUE(cm[c]) << "cell " << c;
      }
    }
    expect_tiling(m, g, rng);
    // No leaf of either input is subdivided: each lies inside one leaf of the result.
    for (const KdTree* in : {&t1, &t2})
      for (Index leaf : in->leaves()) {
        const KdAddress a = in->address(leaf);
        int containing = 0;
        for (Index r : m.leaves()) containing += m.address(r).contains(a) ? 1 : 0;
        EXPECT_EQ(containing, 1) << a.to_string();
      }
    KdTree e(unit_box(n));
    merge_nosubdivide(e, t2);
    EXPECT_EQ(e.splits(), t2.splits());
  }
}

INSTANTIATE_TEST_SUITE_P(Dims, RandomKdTrees, ::testing::Values(1, 2, 3, 4));

// ---- project ------------------------------------------------------------------------------

TEST(KdTreeProject, SplitsAreASubsetOfTheSourceSplitsInTheKeptDimensions) {
  const std::vector<std::vector<std::size_t>> keeps = {{0, 1}, {2, 3}, {0, 2}, {1}, {0, 1, 3}, {0, 1, 2, 3}};
  std::mt19937 rng(6000);
  const Grid g4{4, grid_bits(4)};
  std::size_t projected_splits = 0;
  for (int trial = 0; trial < 16; ++trial) {
    // Trees that interleave dimensions at random, and trees that split them in turn (as the
    // intersection kd-tree of Alg 5.4 does), whose projections keep many splits.
    const KdTree n = trial % 2 == 0 ? random_tree(unit_box(4), g4.bits, rng) : random_cyclic_tree(unit_box(4), g4.bits, rng);
    const std::vector<bool> cn = coverage(n, g4);
    for (const std::vector<std::size_t>& keep : keeps) {
      const KdTree p = project(n, keep);
      ASSERT_EQ(p.dims(), keep.size());
      std::set<KdSplit> allowed;
      for (const KdSplit& s : n.splits()) {
        const auto j = std::find(keep.begin(), keep.end(), s.dim);
        if (j != keep.end()) allowed.insert({s.address.restricted(keep), static_cast<std::size_t>(j - keep.begin())});
      }
      projected_splits += keep.size() < 4 ? p.splits().size() : 0;
      for (const KdSplit& s : p.splits())
        EXPECT_TRUE(allowed.count(s)) << "projected split of " << s.address.to_string() << " in dimension " << s.dim;
      // The projection of every covered point is covered.
      for (std::size_t c = 0; c < g4.cells(); ++c) {
        if (!cn[c]) continue;
        const std::vector<double> x = g4.centre(n.domain(), c);
        std::vector<double> y;
        for (std::size_t d : keep) y.push_back(x[d]);
        EXPECT_NE(p.leaf_containing(y), KdTree::kNone) << "cell " << c;
      }
      const Grid gp{keep.size(), grid_bits(keep.size())};
      expect_tiling(p, gp, rng);
      if (keep.size() == 4) {
        EXPECT_EQ(p.splits(), n.splits());
        EXPECT_EQ(leaf_addresses(p), leaf_addresses(n));
      }
    }
  }
  // The trees are not so mixed that every projection collapses to one leaf.
  EXPECT_GT(projected_splits, 100u);
}

TEST(KdTreeProject, DroppingAnUnsplitDimensionKeepsTheTree) {
  // A 3-D tree that never splits z projects onto (x, y) with the same leaves and splits.
  std::mt19937 rng(7000);
  for (int trial = 0; trial < 6; ++trial) {
    const KdTree t2 = random_tree(unit_box(2), 5, rng);
    // Copy t2's nodes into three dimensions, node by node (same split dimensions).
    KdTree t3(unit_box(3));
    std::vector<std::pair<Index, Index>> stack{{t2.root(), t3.make_root()}};
    while (!stack.empty()) {
      const auto [from, to] = stack.back();
      stack.pop_back();
      const KdTree::Node& nd = t2.node(from);
      for (int s = 0; s < 2; ++s)
        if (nd.child[static_cast<std::size_t>(s)] != KdTree::kNone)
          stack.emplace_back(nd.child[static_cast<std::size_t>(s)],
                             t3.add_child(to, static_cast<std::size_t>(nd.split_dim), s));
    }
    const std::size_t keep[] = {0, 1};
    const KdTree p = project(t3, keep);
    EXPECT_EQ(leaf_addresses(p), leaf_addresses(t2));
    EXPECT_EQ(p.splits(), t2.splits());
  }
}

TEST(KdTreeProject, SplitsInADroppedDimensionMergeWithoutSubdividing) {
  // 2-D: the root splits y; below, the low half splits x, the high half is one leaf. Dropping
  // y merges "x split" with "whole": the leaf may not be subdivided, so x gets one leaf.
  KdTree t = KdTree::full(unit_box(2));
  const auto [low, high] = t.split(t.root(), 1);
  t.split(low, 0);
  (void)high;
  const std::size_t keep_x[] = {0};
  const KdTree px = project(t, keep_x);
  EXPECT_EQ(px.num_nodes(), 1u);
  EXPECT_EQ(px.box(px.root()), unit_box(1));
  // Dropping x instead keeps the y split.
  const std::size_t keep_y[] = {1};
  const KdTree py = project(t, keep_y);
  EXPECT_EQ(leaf_addresses(py), (std::set<KdAddress>{KdAddress::parse({"0"}), KdAddress::parse({"1"})}));
  EXPECT_TRUE(project(KdTree(unit_box(2)), keep_y).empty());
}

}  // namespace
}  // namespace genmod
