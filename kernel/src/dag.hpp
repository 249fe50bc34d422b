// The expression DAG store: immutable, hash-consed scalar nodes shared by all Fn values.
//
// Threading: there is one process-wide store. Creating, reading, holding and dropping nodes is
// safe from any number of threads at once (creation and reclamation take a lock; reading a node
// and copying a reference are lock-free). Structurally equal live nodes get the same id, so an
// id is a cache key for the function it computes while the node lives.
//
// Lifetime: nodes are reference counted, and so are custom operators.
//  * An Fn holds one reference on each of its component nodes; a node holds its operands and
//    (a custom node) its argument list and its operator. A node whose count drops to zero is
//    reclaimed at once (its id may be reused), and so is everything only it held; a custom
//    operator is destroyed when no node applies it any more.
//  * The functions below that return a NodeId (constant, var, make, make_custom) return a *new
//    reference* owned by the caller: hand it to an Fn (detail::FnAccess::adopt), or give it back with release().
//    A NodeId read from an Fn or a node (f.node(j), n.arg[k]) is *borrowed*: valid while the
//    Fn or node that holds it lives; Fn(ids) and Fn::of(id) take a reference of their own.
//  * Tapes keep the custom operators they call alive (they never refer to nodes).
// A reference that is never given back is a leak, never a dangling id, so mistakes fail safe.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/opcode.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace genmod {

class CustomOp;

inline constexpr NodeId kNoNode = 0xffffffffu;

struct Node {
  Op op;
  bool may_error;        // some node below can raise an error (static, conservative)
  std::uint32_t arg[3];  // operands (kNoNode when unused); Custom: arg[0] = argument list id, arg[1] = count
  std::int32_t index;    // Var: coordinate; Custom: output index
  std::uint32_t custom;  // Custom: operator id
  double value;          // Const: the value
  std::uint64_t inputs;  // bit i set if the node depends on x(i)
  std::uint32_t depth;   // longest path to a leaf
  // A hash of the node's structure (op, constant, coordinate, operator name, operands' shapes),
  // independent of node ids. Ids are reused after reclamation, so they depend on what the
  // process built before; the shape does not, and orders commutative operands (hence tapes,
  // and the solvers' work on them) the same way in every process history.
  std::uint64_t shape;
};

namespace dag {

// The node of a live id (borrowed: valid while someone holds the node).
const Node& node(NodeId id) noexcept;
// The number of live nodes (and of live custom operators).
std::size_t size() noexcept;
std::size_t custom_count() noexcept;
// True when `id` names a live node.
bool is_live(NodeId id) noexcept;

// Node construction with the cheap simplifications: exact constant folding, x+0, x*1, x/1,
// x-x (when x cannot raise an error), --x, x*x -> square(x), and commutative operands in the
// order of their shapes (ids only break a tie between different nodes of equal shape).
// Each returns a new reference (see Lifetime above). Throws std::invalid_argument for a
// coordinate outside [0, kMaxInputs) or an operand that is not a live node.
NodeId constant(double value);
NodeId var(int index);
NodeId make(Op op, NodeId a, NodeId b = kNoNode, NodeId c = kNoNode);
NodeId make_custom(std::uint32_t op_id, int output, std::span<const NodeId> args);

// Reference counting of node ids: retain() adds a reference to a live node, release() gives
// one back (reclaiming the node when it was the last).
void retain(NodeId id) noexcept;
void release(NodeId id) noexcept;

// Registers a custom operator (once per object) and returns its id with a new reference on it,
// given back by release_custom(); nodes that apply it hold references of their own.
std::uint32_t register_custom(std::shared_ptr<const CustomOp> op);
void release_custom(std::uint32_t op_id) noexcept;
// The operator of a live custom node (borrowed) or a shared owner of it (what tapes keep).
const CustomOp& custom(std::uint32_t op_id) noexcept;
std::shared_ptr<const CustomOp> custom_shared(std::uint32_t op_id);
std::span<const NodeId> custom_args(const Node& n) noexcept;

inline bool is_const(NodeId id, double v) noexcept {
  const Node& n = node(id);
  return n.op == Op::Const && n.value == v;
}

// The nodes reachable from `roots`, children before parents.
std::vector<NodeId> topological_order(std::span<const NodeId> roots);

// Owner of the new references made while building something: keeps each id given to own()
// alive until the Refs is destroyed, then releases them all. Builders of intermediate nodes
// (derivatives, substitutions, file readers) use one, then wrap their results in an Fn.
class Refs {
 public:
  Refs() = default;
  Refs(const Refs&) = delete;
  Refs& operator=(const Refs&) = delete;
  ~Refs() {
    for (NodeId id : ids_) release(id);
  }
  NodeId own(NodeId new_reference) {
    ids_.push_back(new_reference);
    return new_reference;
  }

 private:
  std::vector<NodeId> ids_;
};

}  // namespace dag
namespace detail {
// An Fn that takes over new references (what constant, var, make and make_custom return).
struct FnAccess {
  static Fn adopt(std::vector<NodeId> owned) { return Fn::adopt(std::move(owned)); }
  static Fn adopt(NodeId owned) { return Fn::adopt(owned); }
};
}  // namespace detail

}  // namespace genmod
