// insert_addonly / insert_nosubdivide, merge_addonly / merge_nosubdivide and project
// (Snyder 1991 §5.2.4.2, Figs 5.23-5.25, with the precise semantics of research snyder.md
// §5.4.2 [IMPL]).
//
// Both insertions descend from the root along X's address. Where the printed figure is
// ambiguous, the rules here are:
//  * addonly: at a leaf, stop (X's part there is covered; the leaf is not split). At an empty
//    slot, hang a chain of nodes down to the part of X in that slot. Where X has no further bit
//    in a node's split dimension (X straddles the split, also below X's own node), follow both
//    halves. So exactly the uncovered parts of X are added, as maximal nodes.
//  * nosubdivide: at a leaf, stop. At an empty slot, hang a chain down to X. At the first node
//    whose split X straddles (X's furthest ancestor in the tree, or X itself with a subtree),
//    collapse that node's subtree into one leaf.
// A merge passes the source tree as a guide: a chain takes the split dimension the source has
// at the same address, so it reproduces the source's splits. Where the source has no node at a
// chain's address (the trees interleave dimensions differently), addonly picks the least split
// dimension still needed (lowest index on ties), while nosubdivide ends the chain in a leaf
// there (a larger node that contains X), which is what keeps merge_nosubdivide and project from
// inventing splits.
#include "genmod/tessellate/kd_tree.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace genmod {

// The algorithms need the node vector; KdTree befriends this one accessor.
struct KdTreeAccess {
  using Index = KdTree::Index;
  enum class Mode { AddOnly, NoSubdivide };

  static KdTree::Node& node(KdTree& t, Index i) { return t.nodes_[static_cast<std::size_t>(i)]; }

  // The split dimension for the next node of a chain at address `at` heading for `target`, or
  // -1 to end the chain here with a larger leaf (nosubdivide without a matching source node).
  static int chain_dim(const KdAddress& at, const KdAddress& target, Mode mode, const KdTree* guide) {
    if (guide != nullptr) {
      const Index g = guide->find(at);
      if (g != KdTree::kNone && !guide->is_leaf(g)) {
        const auto d = static_cast<std::size_t>(guide->node(g).split_dim);
        if (target.depth(d) > at.depth(d)) return static_cast<int>(d);
      }
      if (mode == Mode::NoSubdivide) return -1;
    }
    int best = -1;
    for (std::size_t d = 0; d < at.dims(); ++d)
      if (target.depth(d) > at.depth(d) && (best < 0 || at.depth(d) < at.depth(static_cast<std::size_t>(best))))
        best = static_cast<int>(d);
    return best;
  }

  // `leaf` (a new node at address `at`, an ancestor of `target`) grows a chain down to target.
  static void grow(KdTree& t, Index leaf, KdAddress at, const KdAddress& target, Mode mode, const KdTree* guide) {
    while (at != target) {
      const int d = chain_dim(at, target, mode, guide);
      if (d < 0) return;
      const auto du = static_cast<std::size_t>(d);
      const int side = target.bit(du, at.depth(du));
      leaf = t.add_child(leaf, du, side);
      at = at.child(du, side);
    }
  }

  // Removes the subtree below i, leaving i a leaf. The removed nodes stay in the vector,
  // unreachable, until compact().
  static void collapse(KdTree& t, Index i) {
    KdTree::Node& n = node(t, i);
    n.child = {KdTree::kNone, KdTree::kNone};
    n.split_dim = -1;
  }

  // Descends from node i (address `at`, compatible with x) as the header comment says.
  static void descend(KdTree& t, Index i, const KdAddress& at, const KdAddress& x, Mode mode, const KdTree* guide) {
    const KdTree::Node n = node(t, i);
    if (n.split_dim < 0) return;
    const auto d = static_cast<std::size_t>(n.split_dim);
    if (x.depth(d) > at.depth(d)) {  // X lies in one half
      const int side = x.bit(d, at.depth(d));
      const KdAddress c_at = at.child(d, side);
      const Index c = n.child[static_cast<std::size_t>(side)];
      if (c == KdTree::kNone)
        grow(t, t.add_child(i, d, side), c_at, x, mode, guide);
      else
        descend(t, c, c_at, x, mode, guide);
      return;
    }
    if (mode == Mode::NoSubdivide) {  // this split would cut X
      collapse(t, i);
      return;
    }
    for (int side = 0; side < 2; ++side) {
      const KdAddress c_at = at.child(d, side);
      const Index c = n.child[static_cast<std::size_t>(side)];
      if (c == KdTree::kNone)
        grow(t, t.add_child(i, d, side), c_at, meet(x, c_at), mode, guide);
      else
        descend(t, c, c_at, x, mode, guide);
    }
  }

  // The intersection of two compatible addresses: per dimension the longer bit string.
  static KdAddress meet(const KdAddress& a, const KdAddress& b) {
    std::vector<std::string> bits(a.dims());
    for (std::size_t d = 0; d < a.dims(); ++d) {
      const KdAddress& deeper = a.depth(d) >= b.depth(d) ? a : b;
      for (int k = 0; k < deeper.depth(d); ++k) bits[d] += static_cast<char>('0' + deeper.bit(d, k));
    }
    return KdAddress::parse(bits);
  }

  static void insert(KdTree& t, const KdAddress& x, Mode mode, const KdTree* guide) {
    const KdAddress root_at(t.dims());
    if (t.empty())
      grow(t, t.make_root(), root_at, x, mode, guide);
    else
      descend(t, t.root_, root_at, x, mode, guide);
  }

  // Renumbers the nodes reachable from the root depth first, low child first, and drops the
  // others.
  static void compact(KdTree& t) {
    std::vector<KdTree::Node> out;
    out.reserve(t.nodes_.size());
    if (t.root_ != KdTree::kNone) {
      // (old index, new parent index, side in the parent)
      struct Item {
        Index old;
        Index parent;
        int side;
      };
      std::vector<Item> stack{{t.root_, KdTree::kNone, 0}};
      while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        const KdTree::Node& o = t.nodes_[static_cast<std::size_t>(it.old)];
        const auto here = static_cast<Index>(out.size());
        KdTree::Node n;
        n.parent = it.parent;
        n.split_dim = o.split_dim;
        out.push_back(n);
        if (it.parent != KdTree::kNone) out[static_cast<std::size_t>(it.parent)].child[static_cast<std::size_t>(it.side)] = here;
        if (o.child[1] != KdTree::kNone) stack.push_back({o.child[1], here, 1});
        if (o.child[0] != KdTree::kNone) stack.push_back({o.child[0], here, 0});
      }
      t.root_ = 0;
    }
    t.nodes_ = std::move(out);
  }

  // Copies src's nodes below dst's node `parent`, in slot `side` of dimension d.
  static void graft(KdTree& dst, Index parent, std::size_t d, int side, const KdTree& src) {
    struct Item {
      Index old;
      Index parent;
      std::size_t dim;
      int side;
    };
    std::vector<Item> stack{{src.root_, parent, d, side}};
    while (!stack.empty()) {
      const Item it = stack.back();
      stack.pop_back();
      const Index here = dst.add_child(it.parent, it.dim, it.side);
      const KdTree::Node& o = src.nodes_[static_cast<std::size_t>(it.old)];
      for (int s = 0; s < 2; ++s)
        if (o.child[static_cast<std::size_t>(s)] != KdTree::kNone)
          stack.push_back({o.child[static_cast<std::size_t>(s)], here, static_cast<std::size_t>(o.split_dim), s});
    }
  }

  static void merge(KdTree& t1, const KdTree& t2_in, Mode mode, const char* who) {
    if (t1.dims() != t2_in.dims())
      throw std::invalid_argument(std::string(who) + ": a " + std::to_string(t1.dims()) + "-dimensional and a " +
                                  std::to_string(t2_in.dims()) + "-dimensional tree");
    for (std::size_t d = 0; d < t1.dims(); ++d)
      if (!(t1.domain()[d] == t2_in.domain()[d]))
        throw std::invalid_argument(std::string(who) + ": the trees' domains differ in side " + std::to_string(d));
    const KdTree copy = &t1 == &t2_in ? t2_in : KdTree(t2_in.domain());
    const KdTree& t2 = &t1 == &t2_in ? copy : t2_in;
    for (const Index leaf : t2.leaves()) insert(t1, t2.address(leaf), mode, &t2);
    compact(t1);
  }

  // Fig 5.25 for the subtree at source node i; the result is a tree over the projected domain
  // whose root stands for i's (projected) address.
  static KdTree project_node(const KdTree& src, Index i, std::span<const std::size_t> keep, const KdBox& domain) {
    const KdTree::Node& n = src.nodes_[static_cast<std::size_t>(i)];
    if (n.split_dim < 0) return KdTree::full(domain);
    std::array<KdTree, 2> part{KdTree(domain), KdTree(domain)};
    for (int s = 0; s < 2; ++s)
      if (n.child[static_cast<std::size_t>(s)] != KdTree::kNone)
        part[static_cast<std::size_t>(s)] = project_node(src, n.child[static_cast<std::size_t>(s)], keep, domain);
    const auto kept = std::find(keep.begin(), keep.end(), static_cast<std::size_t>(n.split_dim));
    if (kept != keep.end()) {
      const auto j = static_cast<std::size_t>(kept - keep.begin());
      KdTree out(domain);
      const Index root = out.make_root();
      for (int s = 0; s < 2; ++s)
        if (!part[static_cast<std::size_t>(s)].empty()) graft(out, root, j, s, part[static_cast<std::size_t>(s)]);
      return out;
    }
    if (part[1].empty()) return std::move(part[0]);
    if (part[0].empty()) return std::move(part[1]);
    merge(part[0], part[1], Mode::NoSubdivide, "project");
    return std::move(part[0]);
  }
};

void KdTree::insert_addonly(const KdAddress& address) {
  if (address.dims() != dims())
    throw std::invalid_argument("KdTree::insert_addonly: a " + std::to_string(address.dims()) +
                                "-dimensional address in a " + std::to_string(dims()) + "-dimensional tree");
  KdTreeAccess::insert(*this, address, KdTreeAccess::Mode::AddOnly, nullptr);
  KdTreeAccess::compact(*this);
}

void KdTree::insert_nosubdivide(const KdAddress& address) {
  if (address.dims() != dims())
    throw std::invalid_argument("KdTree::insert_nosubdivide: a " + std::to_string(address.dims()) +
                                "-dimensional address in a " + std::to_string(dims()) + "-dimensional tree");
  KdTreeAccess::insert(*this, address, KdTreeAccess::Mode::NoSubdivide, nullptr);
  KdTreeAccess::compact(*this);
}

void merge_addonly(KdTree& t1, const KdTree& t2) { KdTreeAccess::merge(t1, t2, KdTreeAccess::Mode::AddOnly, "merge_addonly"); }

void merge_nosubdivide(KdTree& t1, const KdTree& t2) {
  KdTreeAccess::merge(t1, t2, KdTreeAccess::Mode::NoSubdivide, "merge_nosubdivide");
}

KdTree project(const KdTree& tree, std::span<const std::size_t> keep) {
  if (keep.empty()) throw std::invalid_argument("project: no dimension to keep");
  KdBox domain;
  for (std::size_t j = 0; j < keep.size(); ++j) {
    if (keep[j] >= tree.dims())
      throw std::invalid_argument("project: dimension " + std::to_string(keep[j]) + " of a " +
                                  std::to_string(tree.dims()) + "-dimensional tree");
    if (j > 0 && keep[j] <= keep[j - 1])
      throw std::invalid_argument("project: the kept dimensions are not strictly increasing");
    domain.push_back(tree.domain()[keep[j]]);
  }
  if (tree.empty()) return KdTree(domain);
  KdTree out = KdTreeAccess::project_node(tree, tree.root(), keep, domain);
  KdTreeAccess::compact(out);
  return out;
}

}  // namespace genmod
