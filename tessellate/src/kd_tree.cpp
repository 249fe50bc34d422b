// Kd-addresses, boxes and the structure of kd-trees: building, addresses, leaves, neighbours.
// The insertion, merge and projection algorithms are in kd_tree_merge.cpp.
#include "genmod/tessellate/kd_tree.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace genmod {

namespace {

constexpr int kGridBits = KdAddress::kMaxDepth;

std::string dim_text(std::size_t d) { return std::to_string(d); }

// The point at index / 2^depth of [lo, hi]. The fraction is reduced to lowest terms first so
// that the same dyadic rational always gives the same double, whatever node computes it.
double dyadic_coordinate(const Interval& side, std::uint64_t index, int depth) {
  while (depth > 0 && index % 2 == 0) {
    index /= 2;
    --depth;
  }
  if (index == 0) return side.lo();
  if (depth == 0) return side.hi();  // index == 1: the whole side
  const double t = std::ldexp(static_cast<double>(index), -depth);  // exact: index < 2^52
  return side.lo() + (side.hi() - side.lo()) * t;
}

// The integer box of an address on the grid of 2^kGridBits cells per side: exact comparisons
// for neighbour searches.
struct GridBox {
  std::vector<std::uint64_t> lo, hi;
};

GridBox grid_box(const KdAddress& a) {
  GridBox g;
  for (std::size_t d = 0; d < a.dims(); ++d) {
    const int shift = kGridBits - a.depth(d);
    g.lo.push_back(a.index(d) << shift);
    g.hi.push_back((a.index(d) + 1) << shift);
  }
  return g;
}

}  // namespace

// ---- KdAddress ---------------------------------------------------------------------------

KdAddress::KdAddress(std::size_t dims) : paths_(dims) {}

KdAddress KdAddress::parse(const std::vector<std::string>& bit_strings) {
  KdAddress a(bit_strings.size());
  for (std::size_t d = 0; d < bit_strings.size(); ++d) {
    const std::string& s = bit_strings[d];
    if (s.size() > static_cast<std::size_t>(kMaxDepth))
      throw std::invalid_argument("KdAddress::parse: the bit string of dimension " + dim_text(d) + " has " +
                                  std::to_string(s.size()) + " bits, more than the limit of " +
                                  std::to_string(kMaxDepth));
    for (char c : s) {
      if (c != '0' && c != '1')
        throw std::invalid_argument("KdAddress::parse: the bit string \"" + s + "\" of dimension " + dim_text(d) +
                                    " holds a character other than '0' and '1'");
      a.paths_[d].index = a.paths_[d].index * 2 + static_cast<std::uint64_t>(c - '0');
      ++a.paths_[d].depth;
    }
  }
  return a;
}

int KdAddress::depth(std::size_t d) const {
  if (d >= paths_.size())
    throw std::invalid_argument("KdAddress: dimension " + dim_text(d) + " of a " + dim_text(paths_.size()) +
                                "-dimensional address");
  return paths_[d].depth;
}

std::uint64_t KdAddress::index(std::size_t d) const {
  depth(d);  // checks d
  return paths_[d].index;
}

int KdAddress::bit(std::size_t d, int i) const {
  const int n = depth(d);
  if (i < 0 || i >= n)
    throw std::invalid_argument("KdAddress::bit: bit " + std::to_string(i) + " of dimension " + dim_text(d) +
                                ", which has " + std::to_string(n) + " bits");
  return static_cast<int>((paths_[d].index >> (n - 1 - i)) & 1u);
}

KdAddress KdAddress::child(std::size_t d, int side) const {
  const int n = depth(d);
  if (side != 0 && side != 1)
    throw std::invalid_argument("KdAddress::child: side " + std::to_string(side) + " is neither 0 nor 1");
  if (n >= kMaxDepth)
    throw std::invalid_argument("KdAddress::child: dimension " + dim_text(d) + " is already split " +
                                std::to_string(kMaxDepth) + " times, the depth limit");
  KdAddress c = *this;
  c.paths_[d].index = paths_[d].index * 2 + static_cast<std::uint64_t>(side);
  c.paths_[d].depth = n + 1;
  return c;
}

KdAddress KdAddress::restricted(std::span<const std::size_t> keep) const {
  KdAddress r(keep.size());
  for (std::size_t j = 0; j < keep.size(); ++j) {
    if (j > 0 && keep[j] <= keep[j - 1])
      throw std::invalid_argument("KdAddress::restricted: the kept dimensions are not strictly increasing");
    depth(keep[j]);  // checks the dimension
    r.paths_[j] = paths_[keep[j]];
  }
  return r;
}

bool KdAddress::contains(const KdAddress& other) const {
  if (other.dims() != dims())
    throw std::invalid_argument("KdAddress::contains: a " + dim_text(dims()) + "-dimensional and a " +
                                dim_text(other.dims()) + "-dimensional address");
  for (std::size_t d = 0; d < dims(); ++d) {
    const Path& p = paths_[d];
    const Path& q = other.paths_[d];
    if (p.depth > q.depth || (q.index >> (q.depth - p.depth)) != p.index) return false;
  }
  return true;
}

std::string KdAddress::to_string() const {
  std::string s;
  for (std::size_t d = 0; d < dims(); ++d) {
    if (d > 0) s += ',';
    for (int i = 0; i < paths_[d].depth; ++i) s += static_cast<char>('0' + bit(d, i));
  }
  return s;
}

// ---- boxes -------------------------------------------------------------------------------

KdBox address_box(std::span<const Interval> domain, const KdAddress& address) {
  if (address.dims() != domain.size())
    throw std::invalid_argument("address_box: a " + dim_text(address.dims()) + "-dimensional address in a " +
                                dim_text(domain.size()) + "-dimensional domain");
  KdBox box;
  box.reserve(domain.size());
  for (std::size_t d = 0; d < domain.size(); ++d) {
    const std::uint64_t k = address.index(d);
    const int n = address.depth(d);
    box.push_back(Interval::unchecked(dyadic_coordinate(domain[d], k, n), dyadic_coordinate(domain[d], k + 1, n)));
  }
  return box;
}

KdAddress box_address(std::span<const Interval> domain, std::span<const Interval> box) {
  if (box.size() != domain.size())
    throw std::invalid_argument("box_address: a " + dim_text(box.size()) + "-dimensional box in a " +
                                dim_text(domain.size()) + "-dimensional domain");
  std::vector<std::string> bits(domain.size());
  for (std::size_t d = 0; d < domain.size(); ++d) {
    std::uint64_t k = 0;
    int n = 0;
    // Descend by halves until the side matches exactly; the target must stay inside one half.
    while (true) {
      const double lo = dyadic_coordinate(domain[d], k, n);
      const double hi = dyadic_coordinate(domain[d], k + 1, n);
      if (lo == box[d].lo() && hi == box[d].hi()) break;
      const double mid = dyadic_coordinate(domain[d], 2 * k + 1, n + 1);
      if (n >= KdAddress::kMaxDepth || box[d].is_empty() || box[d].lo() < lo || box[d].hi() > hi ||
          (box[d].lo() < mid && box[d].hi() > mid))
        throw std::invalid_argument("box_address: side " + dim_text(d) +
                                    " of the box is not the side of a kd-tree node of the domain");
      const int side = box[d].lo() >= mid ? 1 : 0;
      k = 2 * k + static_cast<std::uint64_t>(side);
      ++n;
      bits[d] += static_cast<char>('0' + side);
    }
  }
  return KdAddress::parse(bits);
}

// ---- KdTree: structure -------------------------------------------------------------------

KdTree::KdTree(KdBox domain) : domain_(std::move(domain)) {
  if (domain_.empty()) throw std::invalid_argument("KdTree: the domain has no dimensions");
  for (std::size_t d = 0; d < domain_.size(); ++d) {
    const Interval& s = domain_[d];
    if (s.is_empty() || !s.is_bounded() || !(s.lo() < s.hi()))
      throw std::invalid_argument("KdTree: side " + dim_text(d) +
                                  " of the domain is not a finite interval of positive width");
  }
}

KdTree KdTree::full(KdBox domain) {
  KdTree t(std::move(domain));
  t.make_root();
  return t;
}

void KdTree::check_index(Index i, const char* who) const {
  if (i < 0 || static_cast<std::size_t>(i) >= nodes_.size())
    throw std::invalid_argument(std::string("KdTree::") + who + ": node " + std::to_string(i) +
                                " does not exist (the tree has " + std::to_string(nodes_.size()) + " nodes)");
}

const KdTree::Node& KdTree::node(Index i) const {
  check_index(i, "node");
  return nodes_[static_cast<std::size_t>(i)];
}

KdTree::Index KdTree::new_node(Index parent) {
  Node n;
  n.parent = parent;
  nodes_.push_back(n);
  return static_cast<Index>(nodes_.size() - 1);
}

KdTree::Index KdTree::make_root() {
  if (root_ != kNone) throw std::invalid_argument("KdTree::make_root: the tree has a root already");
  root_ = new_node(kNone);
  return root_;
}

std::array<KdTree::Index, 2> KdTree::split(Index leaf, std::size_t d) {
  check_index(leaf, "split");
  if (!is_leaf(leaf)) throw std::invalid_argument("KdTree::split: node " + std::to_string(leaf) + " is not a leaf");
  const Index low = add_child(leaf, d, 0);
  const Index high = add_child(leaf, d, 1);
  return {low, high};
}

KdTree::Index KdTree::add_child(Index i, std::size_t d, int side) {
  check_index(i, "add_child");
  if (d >= dims())
    throw std::invalid_argument("KdTree::add_child: dimension " + dim_text(d) + " of a " + dim_text(dims()) +
                                "-dimensional tree");
  if (side != 0 && side != 1)
    throw std::invalid_argument("KdTree::add_child: side " + std::to_string(side) + " is neither 0 nor 1");
  const Node& n = nodes_[static_cast<std::size_t>(i)];
  if (n.split_dim >= 0 && static_cast<std::size_t>(n.split_dim) != d)
    throw std::invalid_argument("KdTree::add_child: node " + std::to_string(i) + " is split in dimension " +
                                std::to_string(n.split_dim) + ", not " + dim_text(d));
  if (n.child[static_cast<std::size_t>(side)] != kNone)
    throw std::invalid_argument("KdTree::add_child: node " + std::to_string(i) + " has that child already");
  if (n.split_dim < 0) {
    // Splitting a leaf: the depth limit of addresses applies.
    int depth = 0;
    for (Index p = i, c = kNone; p != kNone; c = p, p = nodes_[static_cast<std::size_t>(p)].parent)
      if (c != kNone && static_cast<std::size_t>(nodes_[static_cast<std::size_t>(p)].split_dim) == d) ++depth;
    if (depth >= KdAddress::kMaxDepth)
      throw std::invalid_argument("KdTree::add_child: dimension " + dim_text(d) + " is already split " +
                                  std::to_string(KdAddress::kMaxDepth) + " times above node " + std::to_string(i) +
                                  ", the depth limit");
  }
  const Index c = new_node(i);
  Node& m = nodes_[static_cast<std::size_t>(i)];  // new_node may have reallocated
  m.split_dim = static_cast<int>(d);
  m.child[static_cast<std::size_t>(side)] = c;
  return c;
}

// ---- KdTree: addresses -------------------------------------------------------------------

KdAddress KdTree::address(Index i) const {
  check_index(i, "address");
  // The sides taken from the root down to i, collected bottom up.
  std::vector<std::pair<std::size_t, int>> steps;
  for (Index c = i, p = nodes_[static_cast<std::size_t>(i)].parent; p != kNone;
       c = p, p = nodes_[static_cast<std::size_t>(p)].parent) {
    const Node& n = nodes_[static_cast<std::size_t>(p)];
    steps.emplace_back(static_cast<std::size_t>(n.split_dim), n.child[1] == c ? 1 : 0);
  }
  KdAddress a(dims());
  for (auto it = steps.rbegin(); it != steps.rend(); ++it) a.push(it->first, it->second);
  return a;
}

KdTree::Index KdTree::find(const KdAddress& a) const {
  if (a.dims() != dims())
    throw std::invalid_argument("KdTree::find: a " + dim_text(a.dims()) + "-dimensional address in a " +
                                dim_text(dims()) + "-dimensional tree");
  std::vector<int> depth(dims(), 0);  // bits consumed per dimension
  Index i = root_;
  while (i != kNone) {
    bool at = true;
    for (std::size_t d = 0; d < dims(); ++d) at = at && depth[d] == a.depth(d);
    if (at) return i;
    const Node& n = nodes_[static_cast<std::size_t>(i)];
    if (n.split_dim < 0) return kNone;
    const auto d = static_cast<std::size_t>(n.split_dim);
    if (depth[d] == a.depth(d)) return kNone;  // the address straddles this split
    i = n.child[static_cast<std::size_t>(a.bit(d, depth[d]))];
    ++depth[d];
  }
  return kNone;
}

KdBox KdTree::box(Index i) const { return address_box(domain_, address(i)); }

std::vector<KdSplit> KdTree::splits() const {
  std::vector<KdSplit> out;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    // Only nodes reachable from the root count (nodes_ holds no others between public calls).
    if (nodes_[i].split_dim >= 0)
      out.push_back({address(static_cast<Index>(i)), static_cast<std::size_t>(nodes_[i].split_dim)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// ---- KdTree: leaves and neighbours -------------------------------------------------------

std::vector<KdTree::Index> KdTree::leaves() const {
  std::vector<Index> out;
  std::vector<Index> stack;
  if (root_ != kNone) stack.push_back(root_);
  while (!stack.empty()) {
    const Index i = stack.back();
    stack.pop_back();
    const Node& n = nodes_[static_cast<std::size_t>(i)];
    if (n.split_dim < 0) {
      out.push_back(i);
      continue;
    }
    if (n.child[1] != kNone) stack.push_back(n.child[1]);
    if (n.child[0] != kNone) stack.push_back(n.child[0]);
  }
  return out;
}

KdTree::Index KdTree::leaf_containing(std::span<const double> point) const {
  if (point.size() != dims())
    throw std::invalid_argument("KdTree::leaf_containing: a " + dim_text(point.size()) + "-dimensional point in a " +
                                dim_text(dims()) + "-dimensional tree");
  for (std::size_t d = 0; d < dims(); ++d)
    if (!domain_[d].contains(point[d])) return kNone;
  KdAddress a(dims());
  Index i = root_;
  while (i != kNone) {
    const Node& n = nodes_[static_cast<std::size_t>(i)];
    if (n.split_dim < 0) return i;
    const auto d = static_cast<std::size_t>(n.split_dim);
    const double mid = dyadic_coordinate(domain_[d], 2 * a.index(d) + 1, a.depth(d) + 1);
    // On the split plane: the low side if it exists.
    const int side = point[d] < mid ? 0 : point[d] > mid ? 1 : n.child[0] != kNone ? 0 : 1;
    a.push(d, side);
    i = n.child[static_cast<std::size_t>(side)];
  }
  return kNone;
}

std::vector<KdTree::Index> KdTree::neighbours(Index leaf) const {
  check_index(leaf, "neighbours");
  if (!is_leaf(leaf)) throw std::invalid_argument("KdTree::neighbours: node " + std::to_string(leaf) + " is not a leaf");
  const std::size_t n = dims();
  const GridBox me = grid_box(address(leaf));
  // Depth-first over the nodes whose closed boxes meet the leaf's, with their grid boxes in a
  // parallel stack (lo then hi, 2n words per node).
  std::vector<Index> nodes{root_};
  std::vector<std::uint64_t> boxes(2 * n, 0);
  for (std::size_t d = 0; d < n; ++d) boxes[n + d] = std::uint64_t{1} << kGridBits;
  std::vector<std::uint64_t> box(2 * n);
  std::vector<Index> out;
  while (!nodes.empty()) {
    const Index i = nodes.back();
    nodes.pop_back();
    std::copy(boxes.end() - static_cast<std::ptrdiff_t>(2 * n), boxes.end(), box.begin());
    boxes.resize(boxes.size() - 2 * n);
    // Count the dimensions in which the node only touches the leaf. Touching in two or more
    // means every box below meets the leaf in less than a face, so the subtree is skipped.
    int touching = 0;
    bool meets = true;
    for (std::size_t e = 0; e < n && meets; ++e) {
      const std::uint64_t lo = box[e], hi = box[n + e];
      meets = lo <= me.hi[e] && me.lo[e] <= hi;
      touching += (lo == me.hi[e] || hi == me.lo[e]) ? 1 : 0;
    }
    if (!meets || touching > 1) continue;
    const Node& nd = nodes_[static_cast<std::size_t>(i)];
    if (nd.split_dim < 0) {
      if (touching == 1) out.push_back(i);  // touching == 0 is the leaf itself
      continue;
    }
    const auto d = static_cast<std::size_t>(nd.split_dim);
    const std::uint64_t mid = box[d] + (box[n + d] - box[d]) / 2;
    for (int side = 0; side < 2; ++side) {
      if (nd.child[static_cast<std::size_t>(side)] == kNone) continue;
      nodes.push_back(nd.child[static_cast<std::size_t>(side)]);
      const std::size_t at = boxes.size();
      boxes.insert(boxes.end(), box.begin(), box.end());
      boxes[at + (side == 0 ? n + d : d)] = mid;
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace genmod
