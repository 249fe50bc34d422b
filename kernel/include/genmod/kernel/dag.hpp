// The expression DAG store: immutable, hash-consed scalar nodes shared by all Fn values.
//
// Threading: there is one process-wide store. Creating and reading nodes is safe from any
// number of threads at once (creation takes a lock; reading a node by id is lock-free because
// nodes never move and are never freed). Structurally equal nodes get the same id, so an id is
// a cache key for the function it computes.
#pragma once

#include "genmod/kernel/opcode.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace genmod {

class CustomOp;

using NodeId = std::uint32_t;
inline constexpr NodeId kNoNode = 0xffffffffu;
// Parametric coordinates are x(0) .. x(kMaxInputs - 1).
inline constexpr int kMaxInputs = 64;

struct Node {
  Op op;
  bool may_error;        // some node below can raise an error (static, conservative)
  std::uint32_t arg[3];  // operands (kNoNode when unused); Custom: arg[0] = offset, arg[1] = count in the arg pool
  std::int32_t index;    // Var: coordinate; Custom: output index
  std::uint32_t custom;  // Custom: operator id
  double value;          // Const: the value
  std::uint64_t inputs;  // bit i set if the node depends on x(i)
  std::uint32_t depth;   // longest path to a leaf
};

namespace dag {

const Node& node(NodeId id) noexcept;
std::size_t size() noexcept;

// Node construction with the cheap simplifications: exact constant folding, x+0, x*1, x/1,
// x-x (when x cannot raise an error), --x, x*x -> square(x), and commutative operand order.
// Throws std::invalid_argument for a coordinate outside [0, kMaxInputs).
NodeId constant(double value);
NodeId var(int index);
NodeId make(Op op, NodeId a, NodeId b = kNoNode, NodeId c = kNoNode);
NodeId make_custom(std::uint32_t op_id, int output, std::span<const NodeId> args);

// Registered custom operators live as long as the process.
std::uint32_t register_custom(std::shared_ptr<const CustomOp> op);
const CustomOp& custom(std::uint32_t op_id) noexcept;
std::span<const NodeId> custom_args(const Node& n) noexcept;

inline bool is_const(NodeId id, double v) noexcept {
  const Node& n = node(id);
  return n.op == Op::Const && n.value == v;
}

// The nodes reachable from `roots`, children before parents.
std::vector<NodeId> topological_order(std::span<const NodeId> roots);

}  // namespace dag
}  // namespace genmod
