// Symbolic differentiation and composition (substitution) over the DAG.
#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/fn.hpp"

#include "dag.hpp"
#include "derivative_rules.hpp"

#include <map>
#include <numbers>
#include <tuple>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace genmod {
namespace {

// Makes nodes for a walk: every node made is owned by the walk's Refs and released when the
// walk is done, after its results are wrapped in Fn values (see dag.hpp, Lifetime). It is the
// node algebra of derivative_rules.hpp.
class Builder {
 public:
  using T = NodeId;
  static bool zero(NodeId n) { return dag::is_const(n, 0.0); }
  NodeId c(double v) { return refs_.own(dag::constant(v)); }
  NodeId make(Op op, NodeId a, NodeId b = kNoNode, NodeId third = kNoNode) {
    return refs_.own(dag::make(op, a, b, third));
  }
  NodeId make_custom(std::uint32_t op_id, int output, std::span<const NodeId> args) {
    return refs_.own(dag::make_custom(op_id, output, args));
  }
  // Products and sums that skip known zeros, so derivative DAGs stay small.
  NodeId mul(NodeId a, NodeId b) { return (zero(a) || zero(b)) ? c(0.0) : make(Op::Mul, a, b); }
  NodeId add(NodeId a, NodeId b) { return make(Op::Add, a, b); }
  NodeId sub(NodeId a, NodeId b) { return make(Op::Sub, a, b); }
  NodeId div(NodeId a, NodeId b) { return zero(a) ? c(0.0) : make(Op::Div, a, b); }

 private:
  dag::Refs refs_;
};

// Fills memo[id] = make(id, node) for every node below `root` (root included) that `wanted`
// accepts, arguments before the nodes that use them: a post order over an explicit stack, so
// the depth of the DAG is bounded by memory, not by the call stack. `arguments(node, visit)`
// calls visit on the arguments whose results make() reads.
template <class Wanted, class Arguments, class Make>
void post_order(NodeId root, std::unordered_map<NodeId, NodeId>& memo, Wanted wanted, Arguments arguments,
                Make make) {
  std::vector<std::pair<NodeId, bool>> stack{{root, false}};
  while (!stack.empty()) {
    auto [id, expanded] = stack.back();
    stack.pop_back();
    if (!wanted(id) || memo.count(id)) continue;
    const Node& n = dag::node(id);
    if (expanded) {
      memo.emplace(id, make(id, n));
      continue;
    }
    stack.emplace_back(id, true);
    arguments(n, [&](NodeId a) {
      if (wanted(a) && !memo.count(a)) stack.emplace_back(a, false);
    });
  }
}

class Differentiator : private Builder {
 public:
  explicit Differentiator(int var) : var_(var) {}

  // d root / d x(var): the derivatives a node's rule needs are made first (post_order), so
  // the rules only look them up.
  NodeId derive(NodeId root) {
    post_order(
        root, memo_, [this](NodeId id) { return depends(id); },
        [](const Node& n, auto&& visit) { for_each_needed(n, visit); },
        [this](NodeId id, const Node& n) { return rule(id, n); });
    return d(root);
  }

 private:
  bool depends(NodeId id) const { return dag::node(id).inputs >> var_ & 1u; }

  // The derivative of a node made earlier (derive's post order); 0 if it does not depend on
  // the variable.
  NodeId d(NodeId id) {
    if (!depends(id)) return c(0.0);
    return memo_.at(id);
  }

  // Whether rule() reads the derivative of operand k: not for the piecewise constant ops, not
  // for a select's condition.
  static bool needs_derivative(Op op, int k) {
    switch (op) {
      case Op::Floor: case Op::Ceil: case Op::Not: case Op::IsError:
      case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne:
      case Op::And: case Op::Or:
        return false;
      case Op::Select: return k != 0;
      default: return true;
    }
  }

  // The arguments whose derivatives rule() uses.
  template <class F>
  static void for_each_needed(const Node& n, F& f) {
    if (n.op == Op::Custom) {
      for (NodeId a : dag::custom_args(n)) f(a);
      return;
    }
    for (int k = 0; k < arity(n.op); ++k)
      if (needs_derivative(n.op, k)) f(n.arg[k]);
  }

  NodeId rule(NodeId id, const Node& n) {
    switch (n.op) {
      case Op::Var: return c(n.index == var_ ? 1.0 : 0.0);
      case Op::Const: return c(0.0);
      case Op::Custom: return custom_rule(n);
      default: break;
    }
    // The operands' derivatives the rule reads (for_each_needed made them); the others are
    // never read, and kNoNode operands stay kNoNode.
    NodeId d_arg[3] = {kNoNode, kNoNode, kNoNode};
    for (int k = 0; k < arity(n.op); ++k)
      if (needs_derivative(n.op, k)) d_arg[k] = d(n.arg[k]);
    return detail::derivative_rule(static_cast<Builder&>(*this), n.op, id, n.arg[0], n.arg[1], d_arg[0], d_arg[1],
                                   d_arg[2]);
  }

  // Chain rule: sum over arguments k of (d out_j / d arg_k) * arg_k'.
  NodeId custom_rule(const Node& n) {
    const CustomOp& op = dag::custom(n.custom);
    const std::span<const NodeId> args = dag::custom_args(n);
    std::vector<Fn> arg_fns;
    for (NodeId a : args) arg_fns.push_back(Fn::of(a));
    NodeId sum = c(0.0);
    for (std::size_t k = 0; k < args.size(); ++k) {
      const NodeId dk = d(args[k]);
      if (zero(dk)) continue;
      // One request per (call, argument): the partials of all outputs come together.
      const auto key = std::make_tuple(n.custom, n.arg[0], k);
      auto it = custom_partials_.find(key);
      if (it == custom_partials_.end())
        it = custom_partials_.emplace(key, op.derivative(arg_fns, static_cast<int>(k))).first;
      const Fn& partial = it->second;
      if (partial.dim() != static_cast<std::size_t>(op.num_outputs()))
        throw std::logic_error("genmod: custom operator '" + op.name() + "' derivative has dimension " +
                               std::to_string(partial.dim()) + ", expected " + std::to_string(op.num_outputs()));
      sum = add(sum, mul(partial.node(static_cast<std::size_t>(n.index)), dk));
    }
    return sum;
  }

  int var_;
  std::unordered_map<NodeId, NodeId> memo_;
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::size_t>, Fn> custom_partials_;
};

// Rebuilds a DAG with some coordinates replaced (simplifying on the way).
class Substituter : private Builder {
 public:
  explicit Substituter(std::unordered_map<int, NodeId> replace) : replace_(std::move(replace)) {
    for (const auto& [i, n] : replace_) mask_ |= std::uint64_t{1} << i;
  }

  // root with the coordinates replaced (post_order: arguments are rebuilt first).
  NodeId substitute(NodeId root) {
    post_order(
        root, memo_, [this](NodeId id) { return touched(id); },
        [](const Node& n, auto&& visit) {
          if (n.op == Op::Custom) {
            for (NodeId a : dag::custom_args(n)) visit(a);
          } else {
            for (int k = 0; k < arity(n.op); ++k) visit(n.arg[k]);
          }
        },
        [this](NodeId, const Node& n) { return rebuild(n); });
    return sub(root);
  }

 private:
  bool touched(NodeId id) const { return (dag::node(id).inputs & mask_) != 0; }
  NodeId sub(NodeId id) const { return touched(id) ? memo_.at(id) : id; }

  NodeId rebuild(const Node& n) {
    if (n.op == Op::Var) return replace_.at(n.index);
    if (n.op == Op::Custom) {
      std::vector<NodeId> args;
      for (NodeId a : dag::custom_args(n)) args.push_back(sub(a));
      return make_custom(n.custom, n.index, args);
    }
    NodeId args[3] = {kNoNode, kNoNode, kNoNode};
    for (int k = 0; k < arity(n.op); ++k) args[k] = sub(n.arg[k]);
    return make(n.op, args[0], args[1], args[2]);
  }

  std::unordered_map<int, NodeId> replace_;
  std::uint64_t mask_ = 0;
  std::unordered_map<NodeId, NodeId> memo_;
};

void check_coordinate(int i, const char* what) {
  if (i < 0 || i >= kMaxInputs)
    throw std::invalid_argument(std::string("genmod: ") + what + ": coordinate " + std::to_string(i) +
                                " is out of range [0, " + std::to_string(kMaxInputs) + ")");
}

}  // namespace

Fn derivative(const Fn& f, int i) {
  check_coordinate(i, "derivative");
  Differentiator diff(i);
  std::vector<NodeId> out;
  for (NodeId n : f.nodes()) out.push_back(diff.derive(n));
  return Fn(std::move(out));
}

Fn compose(const Fn& f, int i, const Fn& g) {
  check_coordinate(i, "compose");
  if (g.dim() != 1)
    throw std::invalid_argument("genmod: compose: the substituted function must be scalar, got dimension " +
                                std::to_string(g.dim()));
  Substituter s({{i, g.node(0)}});
  std::vector<NodeId> out;
  for (NodeId n : f.nodes()) out.push_back(s.substitute(n));
  return Fn(std::move(out));
}

Fn compose_all(const Fn& f, Coordinates inputs, const Fn& g) {
  if (inputs.size() != g.dim())
    throw std::invalid_argument("genmod: compose_all: " + std::to_string(inputs.size()) +
                                " coordinates but the substituted function has dimension " + std::to_string(g.dim()));
  std::unordered_map<int, NodeId> replace;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    check_coordinate(inputs[k], "compose_all");
    if (!replace.emplace(inputs[k], g.node(k)).second)
      throw std::invalid_argument("genmod: compose_all: coordinate " + std::to_string(inputs[k]) + " appears twice");
  }
  Substituter s(std::move(replace));
  std::vector<NodeId> out;
  for (NodeId n : f.nodes()) out.push_back(s.substitute(n));
  return Fn(std::move(out));
}

}  // namespace genmod
