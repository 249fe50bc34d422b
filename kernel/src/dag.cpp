// The process-wide hash-consed node store.
#include "genmod/kernel/dag.hpp"

#include "genmod/kernel/custom_op.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace genmod::dag {
namespace {

// Nodes live in fixed-size chunks that never move, so readers need no lock.
constexpr unsigned kChunkBits = 16;
constexpr std::size_t kChunkSize = std::size_t{1} << kChunkBits;
constexpr std::size_t kMaxChunks = std::size_t{1} << 16;

struct Key {
  Op op;
  std::uint32_t arg[3];
  std::int32_t index;
  std::uint32_t custom;
  std::uint64_t value_bits;
  bool operator==(const Key&) const = default;
};

struct KeyHash {
  std::size_t operator()(const Key& k) const noexcept {
    std::uint64_t h = static_cast<std::uint64_t>(k.op) * 0x9E3779B97F4A7C15ull;
    auto mix = [&h](std::uint64_t v) {
      h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    };
    mix(k.arg[0]);
    mix(k.arg[1]);
    mix(k.arg[2]);
    mix(static_cast<std::uint32_t>(k.index));
    mix(k.custom);
    mix(k.value_bits);
    return static_cast<std::size_t>(h);
  }
};

struct ArgListHash {
  std::size_t operator()(const std::vector<NodeId>& v) const noexcept {
    std::size_t h = v.size();
    for (NodeId id : v) h = h * 1000003u ^ id;
    return h;
  }
};

class Store {
 public:
  const Node& get(NodeId id) const noexcept {
    return chunks_[id >> kChunkBits].load(std::memory_order_acquire)[id & (kChunkSize - 1)];
  }
  std::size_t size() const noexcept { return size_.load(std::memory_order_acquire); }

  NodeId intern(const Key& key, const Node& proto) {
    std::lock_guard lock(mutex_);
    if (auto it = index_.find(key); it != index_.end()) return it->second;
    const std::size_t id = size_.load(std::memory_order_relaxed);
    const std::size_t chunk = id >> kChunkBits;
    if (chunk >= kMaxChunks) throw std::length_error("genmod: expression DAG store is full");
    if (!chunks_[chunk].load(std::memory_order_relaxed)) {
      owned_[chunk] = std::make_unique<Node[]>(kChunkSize);
      chunks_[chunk].store(owned_[chunk].get(), std::memory_order_release);
    }
    owned_[chunk][id & (kChunkSize - 1)] = proto;
    size_.store(id + 1, std::memory_order_release);
    index_.emplace(key, static_cast<NodeId>(id));
    return static_cast<NodeId>(id);
  }

  // Interned argument lists of custom nodes: returns the offset in the pool.
  std::uint32_t intern_args(std::span<const NodeId> args) {
    std::lock_guard lock(mutex_);
    std::vector<NodeId> key(args.begin(), args.end());
    if (auto it = arg_lists_.find(key); it != arg_lists_.end()) return it->second;
    // The pool is a chunked array too, so spans handed out stay valid; a list never straddles
    // two chunks, so it is contiguous.
    if (args.size() > kChunkSize) throw std::length_error("genmod: too many custom operator arguments");
    const std::size_t used = arg_pool_size_ & (kChunkSize - 1);
    if (used + args.size() > kChunkSize) arg_pool_size_ += kChunkSize - used;
    const std::uint32_t offset = static_cast<std::uint32_t>(arg_pool_size_);
    for (NodeId a : args) {
      const std::size_t i = arg_pool_size_++;
      if ((i >> kChunkBits) >= kMaxChunks) throw std::length_error("genmod: custom argument pool is full");
      auto& chunk = arg_pool_[i >> kChunkBits];
      if (!chunk) chunk = std::make_unique<NodeId[]>(kChunkSize);
      chunk[i & (kChunkSize - 1)] = a;
    }
    arg_lists_.emplace(std::move(key), offset);
    return offset;
  }
  std::span<const NodeId> args(std::uint32_t offset, std::uint32_t count) const noexcept {
    if (count == 0) return {};
    return {&arg_pool_[offset >> kChunkBits][offset & (kChunkSize - 1)], count};
  }

  std::uint32_t register_op(std::shared_ptr<const CustomOp> op) {
    std::lock_guard lock(mutex_);
    if (auto it = op_ids_.find(op.get()); it != op_ids_.end()) return it->second;
    const std::size_t id = ops_.size();
    if (id >= kMaxCustomOps) throw std::length_error("genmod: too many custom operators");
    op_ptrs_[id].store(op.get(), std::memory_order_release);
    op_ids_.emplace(op.get(), static_cast<std::uint32_t>(id));
    ops_.push_back(std::move(op));
    return static_cast<std::uint32_t>(id);
  }
  // Lock-free: evaluators look operators up on every call.
  const CustomOp& op(std::uint32_t id) const noexcept { return *op_ptrs_[id].load(std::memory_order_acquire); }


 private:
  mutable std::mutex mutex_;
  std::array<std::atomic<Node*>, kMaxChunks> chunks_{};
  std::array<std::unique_ptr<Node[]>, kMaxChunks> owned_{};
  std::atomic<std::size_t> size_{0};
  std::unordered_map<Key, NodeId, KeyHash> index_;
  std::array<std::unique_ptr<NodeId[]>, kMaxChunks> arg_pool_{};
  std::size_t arg_pool_size_ = 0;
  std::unordered_map<std::vector<NodeId>, std::uint32_t, ArgListHash> arg_lists_;
  static constexpr std::size_t kMaxCustomOps = 1 << 16;
  std::vector<std::shared_ptr<const CustomOp>> ops_;  // keeps the operators alive
  std::array<std::atomic<const CustomOp*>, kMaxCustomOps> op_ptrs_{};
  std::unordered_map<const CustomOp*, std::uint32_t> op_ids_;
};

Store& store() {
  static Store* s = new Store;  // never destroyed: nodes outlive every Fn, even static ones
  return *s;
}

std::uint64_t bits_of(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, 8);
  return b;
}

NodeId intern(Op op, NodeId a, NodeId b, NodeId c, std::int32_t index, std::uint32_t custom_id, double value) {
  Key key{op, {a, b, c}, index, custom_id, bits_of(value)};
  Node n{};
  n.op = op;
  n.arg[0] = a;
  n.arg[1] = b;
  n.arg[2] = c;
  n.index = index;
  n.custom = custom_id;
  n.value = value;
  n.may_error = can_error(op);
  n.inputs = op == Op::Var ? (std::uint64_t{1} << index) : 0;
  n.depth = 0;
  if (op == Op::Custom) {
    for (NodeId arg : store().args(a, b)) {
      const Node& child = node(arg);
      n.inputs |= child.inputs;
      n.may_error |= child.may_error;
      n.depth = std::max(n.depth, child.depth + 1);
    }
  } else {
    for (NodeId arg : {a, b, c}) {
      if (arg == kNoNode) continue;
      const Node& child = node(arg);
      n.inputs |= child.inputs;
      n.may_error |= child.may_error;
      n.depth = std::max(n.depth, child.depth + 1);
    }
  }
  if (op == Op::IsError) n.may_error = false;  // error(h) itself never fails
  return store().intern(key, n);
}

// Folds an operation on constants when the double result is exact, so the folded constant
// is the real value (folding sin(1) to a double would lose the inclusion's rigor).
bool fold(Op op, double a, double b, double c, double* out) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (op) {
    case Op::Neg: *out = -a; return true;
    case Op::Abs: *out = std::fabs(a); return true;
    case Op::Floor: *out = std::floor(a); return true;
    case Op::Ceil: *out = std::ceil(a); return true;
    case Op::Min: *out = point::min(a, b); return true;
    case Op::Max: *out = point::max(a, b); return true;
    case Op::Lt: *out = (a != a || b != b) ? nan : double(a < b); return true;
    case Op::Le: *out = (a != a || b != b) ? nan : double(a <= b); return true;
    case Op::Gt: *out = (a != a || b != b) ? nan : double(a > b); return true;
    case Op::Ge: *out = (a != a || b != b) ? nan : double(a >= b); return true;
    case Op::Eq: *out = (a != a || b != b) ? nan : double(a == b); return true;
    case Op::Ne: *out = (a != a || b != b) ? nan : double(a != b); return true;
    case Op::And: *out = (a != a || b != b) ? nan : double(a != 0 && b != 0); return true;
    case Op::Or: *out = (a != a || b != b) ? nan : double(a != 0 || b != 0); return true;
    case Op::Not: *out = (a != a) ? nan : double(a == 0); return true;
    case Op::IsError: *out = double(a != a); return true;
    case Op::Select: *out = (a != a) ? nan : (a != 0 ? b : c); return true;
    case Op::Add: {
      const double s = a + b;
      if (!std::isfinite(s)) return false;
      const double bb = s - a;  // TwoSum error term is zero iff the sum is exact
      if ((a - (s - bb)) + (b - bb) != 0.0) return false;
      *out = s;
      return true;
    }
    case Op::Sub: return fold(Op::Add, a, -b, 0, out);
    case Op::Mul: {
      const double p = a * b;
      if (!std::isfinite(p) || std::fma(a, b, -p) != 0.0) return false;
      *out = p;
      return true;
    }
    case Op::Square: return fold(Op::Mul, a, a, 0, out);
    case Op::Div: {
      if (b == 0.0 || !std::isfinite(a) || !std::isfinite(b)) return false;
      const double q = a / b;
      if (!std::isfinite(q) || std::fma(q, b, -a) != 0.0) return false;
      *out = q;
      return true;
    }
    case Op::Sqrt: {
      if (!(a >= 0.0) || !std::isfinite(a)) return false;
      const double s = std::sqrt(a);
      if (std::fma(s, s, -a) != 0.0) return false;
      *out = s;
      return true;
    }
    default: return false;
  }
}

}  // namespace

const Node& node(NodeId id) noexcept { return store().get(id); }
std::size_t size() noexcept { return store().size(); }

NodeId constant(double value) {
  if (value == 0.0) value = 0.0;  // one zero: -0 and +0 compare equal everywhere we use them
  return intern(Op::Const, kNoNode, kNoNode, kNoNode, 0, 0, value);
}

NodeId var(int index) {
  if (index < 0 || index >= kMaxInputs)
    throw std::invalid_argument("genmod: parametric coordinate x(" + std::to_string(index) +
                                ") is out of range [0, " + std::to_string(kMaxInputs) + ")");
  return intern(Op::Var, kNoNode, kNoNode, kNoNode, index, 0, 0.0);
}

NodeId make(Op op, NodeId a, NodeId b, NodeId c) {
  const int n_args = arity(op);
  if (op <= Op::Var || op > Op::Select || n_args == 0)
    throw std::invalid_argument("genmod: dag::make cannot build a '" + std::string(op_name(op)) + "' node");
  const NodeId args[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const bool wanted = k < n_args;
    if (wanted != (args[k] != kNoNode) || (wanted && args[k] >= size()))
      throw std::invalid_argument("genmod: dag::make: bad operand " + std::to_string(k) + " for '" +
                                  std::string(op_name(op)) + "'");
  }
  if (is_commutative(op) && b < a) std::swap(a, b);

  // Constant folding (exact results only).
  const Node& na = node(a);
  const bool ca = na.op == Op::Const;
  const bool cb = b != kNoNode && node(b).op == Op::Const;
  const bool cc = c != kNoNode && node(c).op == Op::Const;
  if (ca && (n_args < 2 || cb) && (n_args < 3 || cc)) {
    double v;
    if (fold(op, na.value, cb ? node(b).value : 0.0, cc ? node(c).value : 0.0, &v)) return constant(v);
  }
  // Identities that hold for every value, errors included.
  switch (op) {
    case Op::Add:
      if (is_const(a, 0.0)) return b;
      if (is_const(b, 0.0)) return a;
      break;
    case Op::Sub:
      if (is_const(b, 0.0)) return a;
      if (is_const(a, 0.0)) return make(Op::Neg, b);
      // x - x = 0 is exact for every finite x; only skip it where x may be an error (NaN).
      if (a == b && !na.may_error) return constant(0.0);
      break;
    case Op::Mul:
      if (is_const(a, 1.0)) return b;
      if (is_const(b, 1.0)) return a;
      if (a == b) return make(Op::Square, a);
      break;
    case Op::Div:
      if (is_const(b, 1.0)) return a;
      break;
    case Op::Neg:
      if (na.op == Op::Neg) return na.arg[0];
      break;
    case Op::Select:
      if (b == c && !na.may_error) return b;
      break;
    default: break;
  }
  return intern(op, a, b, c, 0, 0, 0.0);
}

NodeId make_custom(std::uint32_t op_id, int output, std::span<const NodeId> args) {
  const CustomOp& op = custom(op_id);
  if (static_cast<int>(args.size()) != op.num_args())
    throw std::invalid_argument("genmod: custom operator '" + op.name() + "' takes " +
                                std::to_string(op.num_args()) + " arguments, got " + std::to_string(args.size()));
  if (output < 0 || output >= op.num_outputs())
    throw std::invalid_argument("genmod: custom operator '" + op.name() + "' has no output " + std::to_string(output));
  for (NodeId a : args)
    if (a >= size()) throw std::invalid_argument("genmod: custom operator argument is not a node");
  const std::uint32_t offset = store().intern_args(args);
  return intern(Op::Custom, offset, static_cast<std::uint32_t>(args.size()), kNoNode, output, op_id, 0.0);
}

std::uint32_t register_custom(std::shared_ptr<const CustomOp> op) {
  if (!op) throw std::invalid_argument("genmod: null custom operator");
  if (op->num_args() < 0 || op->num_outputs() < 1)
    throw std::invalid_argument("genmod: custom operator '" + op->name() + "' needs >= 0 arguments and >= 1 output");
  return store().register_op(std::move(op));
}

const CustomOp& custom(std::uint32_t op_id) noexcept { return store().op(op_id); }

std::span<const NodeId> custom_args(const Node& n) noexcept { return store().args(n.arg[0], n.arg[1]); }

std::vector<NodeId> topological_order(std::span<const NodeId> roots) {
  std::vector<NodeId> order;
  std::unordered_map<NodeId, bool> seen;  // false = on the stack, true = emitted
  std::vector<std::pair<NodeId, bool>> stack;
  for (NodeId r : roots) stack.emplace_back(r, false);
  while (!stack.empty()) {
    auto [id, expanded] = stack.back();
    stack.pop_back();
    if (expanded) {
      if (!seen[id]) {
        seen[id] = true;
        order.push_back(id);
      }
      continue;
    }
    if (seen.count(id)) continue;
    seen[id] = false;
    stack.emplace_back(id, true);
    // Children are visited deepest first (Sethi-Ullman order): a long min/max chain is then
    // evaluated along the chain, keeping few values live, which keeps tapes' register
    // files small. The stack pops the last pushed child first.
    const Node& n = node(id);
    const std::size_t first = stack.size();
    auto push_child = [&](NodeId a) {
      if (a != kNoNode && !seen.count(a)) stack.emplace_back(a, false);
    };
    if (n.op == Op::Custom) {
      for (NodeId a : custom_args(n)) push_child(a);
    } else {
      for (NodeId a : n.arg) push_child(a);
    }
    std::stable_sort(stack.begin() + static_cast<std::ptrdiff_t>(first), stack.end(),
                     [](const auto& p, const auto& q) { return node(p.first).depth < node(q.first).depth; });
  }
  return order;
}

}  // namespace genmod::dag
