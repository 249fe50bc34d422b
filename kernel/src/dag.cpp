// The process-wide hash-consed node store.
#include "dag.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "point_ops.hpp"

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

Key key_of(const Node& n) {
  std::uint64_t bits;
  std::memcpy(&bits, &n.value, 8);
  return Key{n.op, {n.arg[0], n.arg[1], n.arg[2]}, n.index, n.custom, bits};
}

// A node and its reference count. Slots live in fixed-size chunks that never move, so readers
// need no lock; a reclaimed slot goes on a free list and is reused.
struct Slot {
  Node node{};
  std::atomic<std::uint32_t> refs{0};
  std::atomic<bool> live{false};
};

// The argument list of custom nodes (shared by the outputs of one application).
struct ArgList {
  std::vector<NodeId> args;
  std::uint32_t users = 0;  // custom nodes using it (under the lock)
};

struct OpSlot {
  std::shared_ptr<const CustomOp> op;
  std::atomic<const CustomOp*> ptr{nullptr};
  std::uint32_t refs = 0;  // nodes applying it + registrations not given back (under the lock)
};

using DeadOps = std::vector<std::shared_ptr<const CustomOp>>;

class Store {
 public:
  Slot& slot(NodeId id) const noexcept {
    return chunks_[id >> kChunkBits].load(std::memory_order_acquire)[id & (kChunkSize - 1)];
  }
  const Node& get(NodeId id) const noexcept { return slot(id).node; }
  std::size_t size() const noexcept { return live_.load(std::memory_order_relaxed); }
  std::size_t custom_count() const noexcept { return live_ops_.load(std::memory_order_relaxed); }
  bool is_live(NodeId id) const noexcept {
    if (id >= capacity_.load(std::memory_order_acquire)) return false;
    return slot(id).live.load(std::memory_order_acquire);
  }

  // A new reference on the node equal to `proto` (found or created).
  NodeId intern(const Node& proto) {
    std::lock_guard lock(mutex_);
    return intern_locked(proto);
  }

  // A new reference on output `output` of op_id applied to args: the argument list and the
  // node are interned under one lock, so neither can be reclaimed in between.
  NodeId intern_custom(Node proto, std::span<const NodeId> args) {
    std::lock_guard lock(mutex_);
    std::vector<NodeId> key(args.begin(), args.end());
    std::uint32_t list_id;
    if (auto it = list_ids_.find(key); it != list_ids_.end()) {
      list_id = it->second;
    } else {
      list_id = allocate_list();
      ArgList& list = this->list(list_id);
      list.args = key;
      list.users = 0;
      for (NodeId a : args) slot(a).refs.fetch_add(1, std::memory_order_relaxed);  // the list holds its args
      list_ids_.emplace(std::move(key), list_id);
    }
    proto.arg[0] = list_id;
    return intern_locked(proto);  // a new node counts itself as a user of the list
  }

  std::span<const NodeId> args(std::uint32_t list_id, std::uint32_t count) const noexcept {
    if (count == 0) return {};
    return {list(list_id).args.data(), count};
  }

  void release(NodeId id) noexcept {
    if (slot(id).refs.fetch_sub(1, std::memory_order_acq_rel) != 1) return;
    DeadOps dead;
    {
      std::lock_guard lock(mutex_);
      reclaim(id, dead);
    }
    // Destroyed outside the lock: an operator may hold Fn values, whose release reenters.
  }

  std::uint32_t register_op(std::shared_ptr<const CustomOp> op) {
    std::lock_guard lock(mutex_);
    if (auto it = op_ids_.find(op.get()); it != op_ids_.end()) {
      ++ops_[it->second].refs;
      return it->second;
    }
    std::uint32_t id;
    if (!free_ops_.empty()) {
      id = free_ops_.back();
      free_ops_.pop_back();
    } else {
      if (next_op_ >= kMaxCustomOps)
        throw std::length_error("genmod: too many live custom operators (" + std::to_string(kMaxCustomOps) + ")");
      id = next_op_++;
    }
    OpSlot& s = ops_[id];
    s.ptr.store(op.get(), std::memory_order_release);
    s.refs = 1;
    op_ids_.emplace(op.get(), id);
    s.op = std::move(op);
    live_ops_.fetch_add(1, std::memory_order_relaxed);
    return id;
  }

  void release_op(std::uint32_t id) noexcept {
    DeadOps dead;
    std::lock_guard lock(mutex_);
    drop_op(id, dead);
  }

  // Lock-free: evaluators look operators up on every call.
  const CustomOp& op(std::uint32_t id) const noexcept { return *ops_[id].ptr.load(std::memory_order_acquire); }
  std::shared_ptr<const CustomOp> op_shared(std::uint32_t id) const {
    std::lock_guard lock(mutex_);
    return ops_[id].op;
  }

 private:
  NodeId intern_locked(const Node& proto) {
    const Key key = key_of(proto);
    if (auto it = index_.find(key); it != index_.end()) {
      // Also revives a node whose count just fell to zero: its releaser finds it held again.
      slot(it->second).refs.fetch_add(1, std::memory_order_relaxed);
      return it->second;
    }
    const NodeId id = allocate_slot();
    Slot& s = slot(id);
    s.node = proto;
    s.refs.store(1, std::memory_order_relaxed);
    if (proto.op == Op::Custom) {
      ++list(proto.arg[0]).users;
      ++ops_[proto.custom].refs;
    } else {
      for (NodeId a : proto.arg)
        if (a != kNoNode) slot(a).refs.fetch_add(1, std::memory_order_relaxed);
    }
    index_.emplace(key, id);
    s.live.store(true, std::memory_order_release);
    live_.fetch_add(1, std::memory_order_relaxed);
    return id;
  }

  NodeId allocate_slot() {
    if (!free_slots_.empty()) {
      const NodeId id = free_slots_.back();
      free_slots_.pop_back();
      return id;
    }
    const std::size_t id = capacity_.load(std::memory_order_relaxed);
    const std::size_t chunk = id >> kChunkBits;
    if (chunk >= kMaxChunks) throw std::length_error("genmod: expression DAG store is full");
    if (!chunks_[chunk].load(std::memory_order_relaxed)) {
      owned_[chunk] = std::make_unique<Slot[]>(kChunkSize);
      chunks_[chunk].store(owned_[chunk].get(), std::memory_order_release);
    }
    capacity_.store(id + 1, std::memory_order_release);
    return static_cast<NodeId>(id);
  }

  ArgList& list(std::uint32_t id) const noexcept {
    return list_chunks_[id >> kChunkBits].load(std::memory_order_acquire)[id & (kChunkSize - 1)];
  }

  std::uint32_t allocate_list() {
    if (!free_lists_.empty()) {
      const std::uint32_t id = free_lists_.back();
      free_lists_.pop_back();
      return id;
    }
    const std::size_t id = next_list_++;
    const std::size_t chunk = id >> kChunkBits;
    if (chunk >= kMaxChunks) throw std::length_error("genmod: too many custom argument lists");
    if (!list_chunks_[chunk].load(std::memory_order_relaxed)) {
      owned_lists_[chunk] = std::make_unique<ArgList[]>(kChunkSize);
      list_chunks_[chunk].store(owned_lists_[chunk].get(), std::memory_order_release);
    }
    return static_cast<std::uint32_t>(id);
  }

  // Frees `first` (count zero) and everything only it held; the lock is held.
  void reclaim(NodeId first, DeadOps& dead) {
    std::vector<NodeId> work{first};
    auto drop = [&](NodeId child) {
      if (slot(child).refs.fetch_sub(1, std::memory_order_acq_rel) == 1) work.push_back(child);
    };
    while (!work.empty()) {
      const NodeId id = work.back();
      work.pop_back();
      Slot& s = slot(id);
      // Revived since its count fell, or reclaimed already by another releaser.
      if (!s.live.load(std::memory_order_relaxed) || s.refs.load(std::memory_order_acquire) != 0) continue;
      s.live.store(false, std::memory_order_relaxed);
      index_.erase(key_of(s.node));
      live_.fetch_sub(1, std::memory_order_relaxed);
      const Node n = s.node;
      free_slots_.push_back(id);
      if (n.op == Op::Custom) {
        ArgList& args = list(n.arg[0]);
        if (--args.users == 0) {
          list_ids_.erase(args.args);
          for (NodeId a : args.args) drop(a);
          args.args.clear();
          args.args.shrink_to_fit();
          free_lists_.push_back(n.arg[0]);
        }
        drop_op(n.custom, dead);
      } else {
        for (NodeId a : n.arg)
          if (a != kNoNode) drop(a);
      }
    }
  }

  void drop_op(std::uint32_t id, DeadOps& dead) {
    OpSlot& s = ops_[id];
    if (--s.refs != 0) return;
    op_ids_.erase(s.op.get());
    s.ptr.store(nullptr, std::memory_order_release);
    dead.push_back(std::move(s.op));
    free_ops_.push_back(id);
    live_ops_.fetch_sub(1, std::memory_order_relaxed);
  }

  mutable std::mutex mutex_;
  std::array<std::atomic<Slot*>, kMaxChunks> chunks_{};
  std::array<std::unique_ptr<Slot[]>, kMaxChunks> owned_{};
  std::atomic<std::size_t> capacity_{0};
  std::atomic<std::size_t> live_{0};
  std::vector<NodeId> free_slots_;
  std::unordered_map<Key, NodeId, KeyHash> index_;
  // Argument lists, in chunks that never move (readers hold spans into them).
  std::array<std::atomic<ArgList*>, kMaxChunks> list_chunks_{};
  std::array<std::unique_ptr<ArgList[]>, kMaxChunks> owned_lists_{};
  std::size_t next_list_ = 0;
  std::vector<std::uint32_t> free_lists_;
  std::unordered_map<std::vector<NodeId>, std::uint32_t, ArgListHash> list_ids_;
  static constexpr std::uint32_t kMaxCustomOps = 1 << 16;
  std::array<OpSlot, kMaxCustomOps> ops_{};
  std::uint32_t next_op_ = 0;
  std::vector<std::uint32_t> free_ops_;
  std::unordered_map<const CustomOp*, std::uint32_t> op_ids_;
  std::atomic<std::size_t> live_ops_{0};
};

Store& store() {
  static Store* s = new Store;  // never destroyed: static Fn values release into it at exit
  return *s;
}


std::uint64_t mix_shape(std::uint64_t h, std::uint64_t v) noexcept {
  h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
  return h * 0xBF58476D1CE4E5B9ull;
}

// The structural hash of a node (see Node::shape): no node id or operator id goes into it.
std::uint64_t shape_of(const Node& n, std::span<const NodeId> operands) {
  std::uint64_t h = mix_shape(0x243F6A8885A308D3ull, static_cast<std::uint64_t>(n.op));
  std::uint64_t bits;
  std::memcpy(&bits, &n.value, 8);
  h = mix_shape(h, bits);
  h = mix_shape(h, static_cast<std::uint32_t>(n.index));
  if (n.op == Op::Custom) h = mix_shape(h, std::hash<std::string>{}(custom(n.custom).name()));
  for (NodeId arg : operands)
    if (arg != kNoNode) h = mix_shape(h, node(arg).shape);
  return h;
}

// The node's static facts (inputs, possible errors, depth, shape) from its operands.
Node prototype(Op op, std::span<const NodeId> operands, std::int32_t index, std::uint32_t custom_id, double value) {
  Node n{};
  n.op = op;
  n.arg[0] = n.arg[1] = n.arg[2] = kNoNode;
  if (op != Op::Custom)
    for (std::size_t k = 0; k < operands.size(); ++k) n.arg[k] = operands[k];
  n.index = index;
  n.custom = custom_id;
  n.value = value;
  n.may_error = can_error(op);
  n.inputs = op == Op::Var ? (std::uint64_t{1} << index) : 0;
  n.depth = 0;
  for (NodeId arg : operands) {
    if (arg == kNoNode) continue;
    const Node& child = node(arg);
    n.inputs |= child.inputs;
    n.may_error |= child.may_error;
    n.depth = std::max(n.depth, child.depth + 1);
  }
  if (op == Op::IsError) n.may_error = false;  // error(h) itself never fails
  n.shape = shape_of(n, operands);
  return n;
}

NodeId intern(Op op, NodeId a, NodeId b, NodeId c, std::int32_t index, double value) {
  const NodeId operands[3] = {a, b, c};
  return store().intern(prototype(op, operands, index, 0, value));
}

// Folds an operation on constants when the double result is exact, so the folded constant
// is the real value (folding sin(1) to a double would lose the inclusion's rigor).
bool fold(Op op, double a, double b, double c, double* out) {
  if (is_exact(op)) {  // the point rule's double is the real result (opcode table)
    *out = detail::point_value(op, a, b, c);
    return true;
  }
  switch (op) {
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
std::size_t custom_count() noexcept { return store().custom_count(); }
bool is_live(NodeId id) noexcept { return store().is_live(id); }
void retain(NodeId id) noexcept { store().slot(id).refs.fetch_add(1, std::memory_order_relaxed); }
void release(NodeId id) noexcept { store().release(id); }

NodeId constant(double value) {
  if (value == 0.0) value = 0.0;  // one zero: -0 and +0 compare equal everywhere we use them
  return intern(Op::Const, kNoNode, kNoNode, kNoNode, 0, value);
}

NodeId var(int index) {
  if (index < 0 || index >= kMaxInputs)
    throw std::invalid_argument("genmod: parametric coordinate x(" + std::to_string(index) +
                                ") is out of range [0, " + std::to_string(kMaxInputs) + ")");
  return intern(Op::Var, kNoNode, kNoNode, kNoNode, index, 0.0);
}

namespace {

// Commutative operands go in the order of their shapes, so the same expression is built the
// same way whatever ids its operands happen to have.
bool operand_after(NodeId a, NodeId b) noexcept {
  const std::uint64_t sa = node(a).shape, sb = node(b).shape;
  return sa != sb ? sb < sa : b < a;
}

}  // namespace

NodeId make(Op op, NodeId a, NodeId b, NodeId c) {
  const int n_args = arity(op);
  if (op <= Op::Var || op > Op::Select || n_args == 0)
    throw std::invalid_argument("genmod: dag::make cannot build a '" + std::string(op_name(op)) + "' node");
  const NodeId args[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const bool wanted = k < n_args;
    if (wanted != (args[k] != kNoNode) || (wanted && !is_live(args[k])))
      throw std::invalid_argument("genmod: dag::make: bad operand " + std::to_string(k) + " for '" +
                                  std::string(op_name(op)) + "'");
  }
  if (is_commutative(op) && operand_after(a, b)) std::swap(a, b);
  // An operand returned as it is gets a new reference, like every result.
  auto same = [](NodeId id) {
    retain(id);
    return id;
  };

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
      if (is_const(a, 0.0)) return same(b);
      if (is_const(b, 0.0)) return same(a);
      break;
    case Op::Sub:
      if (is_const(b, 0.0)) return same(a);
      if (is_const(a, 0.0)) return make(Op::Neg, b);
      // x - x = 0 is exact for every finite x; only skip it where x may be an error (NaN).
      if (a == b && !na.may_error) return constant(0.0);
      break;
    case Op::Mul:
      if (is_const(a, 1.0)) return same(b);
      if (is_const(b, 1.0)) return same(a);
      if (a == b) return make(Op::Square, a);
      break;
    case Op::Div:
      if (is_const(b, 1.0)) return same(a);
      break;
    case Op::Neg:
      if (na.op == Op::Neg) return same(na.arg[0]);
      break;
    case Op::Select:
      if (b == c && !na.may_error) return same(b);
      break;
    default: break;
  }
  return intern(op, a, b, c, 0, 0.0);
}

NodeId make_custom(std::uint32_t op_id, int output, std::span<const NodeId> args) {
  const CustomOp& op = custom(op_id);
  if (static_cast<int>(args.size()) != op.num_args())
    throw std::invalid_argument("genmod: custom operator '" + op.name() + "' takes " +
                                std::to_string(op.num_args()) + " arguments, got " + std::to_string(args.size()));
  if (output < 0 || output >= op.num_outputs())
    throw std::invalid_argument("genmod: custom operator '" + op.name() + "' has no output " + std::to_string(output));
  for (NodeId a : args)
    if (!is_live(a)) throw std::invalid_argument("genmod: custom operator argument is not a node");
  Node proto = prototype(Op::Custom, args, output, op_id, 0.0);
  proto.arg[1] = static_cast<std::uint32_t>(args.size());
  return store().intern_custom(proto, args);
}

std::uint32_t register_custom(std::shared_ptr<const CustomOp> op) {
  if (!op) throw std::invalid_argument("genmod: null custom operator");
  if (op->num_args() < 0 || op->num_outputs() < 1)
    throw std::invalid_argument("genmod: custom operator '" + op->name() + "' needs >= 0 arguments and >= 1 output");
  return store().register_op(std::move(op));
}

void release_custom(std::uint32_t op_id) noexcept { store().release_op(op_id); }

const CustomOp& custom(std::uint32_t op_id) noexcept { return store().op(op_id); }
std::shared_ptr<const CustomOp> custom_shared(std::uint32_t op_id) { return store().op_shared(op_id); }

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
