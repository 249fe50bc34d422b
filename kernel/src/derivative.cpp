// Symbolic differentiation and composition (substitution) over the DAG.
#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/fn.hpp"

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

bool zero(NodeId n) { return dag::is_const(n, 0.0); }

// Makes nodes for a walk: every node made is owned by the walk's Refs and released when the
// walk is done, after its results are wrapped in Fn values (see dag.hpp, Lifetime).
class Builder {
 protected:
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

  // The arguments whose derivatives rule() uses: none for the piecewise constant ops, the two
  // branches of a select (not its condition).
  template <class F>
  static void for_each_needed(const Node& n, F& f) {
    switch (n.op) {
      case Op::Floor: case Op::Ceil: case Op::Not: case Op::IsError:
      case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne:
      case Op::And: case Op::Or: case Op::Const: case Op::Var:
        return;
      case Op::Select:
        f(n.arg[1]);
        f(n.arg[2]);
        return;
      case Op::Custom:
        for (NodeId a : dag::custom_args(n)) f(a);
        return;
      default:
        for (int k = 0; k < arity(n.op); ++k) f(n.arg[k]);
    }
  }

  NodeId rule(NodeId id, const Node& n) {
    const NodeId a = n.arg[0], b = n.arg[1];
    switch (n.op) {
      case Op::Var: return c(n.index == var_ ? 1.0 : 0.0);
      case Op::Neg: return make(Op::Neg, d(a));
      case Op::Add: return add(d(a), d(b));
      case Op::Sub: return sub(d(a), d(b));
      case Op::Mul: return add(mul(d(a), b), mul(a, d(b)));
      case Op::Div: return div(sub(d(a), mul(id, d(b))), b);  // (a' - f b') / b
      case Op::Square: return mul(mul(c(2.0), a), d(a));
      case Op::Sqrt: return div(d(a), mul(c(2.0), id));
      case Op::Exp: return mul(id, d(a));
      case Op::Log: return div(d(a), a);
      case Op::Sin: return mul(make(Op::Cos, a), d(a));
      case Op::Cos: return mul(make(Op::Neg, make(Op::Sin, a)), d(a));
      case Op::Tan: return mul(add(c(1.0), make(Op::Square, id)), d(a));
      case Op::Asin: return div(d(a), make(Op::Sqrt, sub(c(1.0), make(Op::Square, a))));
      case Op::Acos: return make(Op::Neg, div(d(a), make(Op::Sqrt, sub(c(1.0), make(Op::Square, a)))));
      case Op::Atan: return div(d(a), add(c(1.0), make(Op::Square, a)));
      case Op::Atan2: {  // atan2(y, x)' = (x y' - y x') / (x^2 + y^2)
        const NodeId num = sub(mul(b, d(a)), mul(a, d(b)));
        return div(num, add(make(Op::Square, b), make(Op::Square, a)));
      }
      case Op::Abs: {
        const NodeId da = d(a);
        return make(Op::Select, make(Op::Lt, a, c(0.0)), make(Op::Neg, da), da);
      }
      case Op::Min: return make(Op::Select, make(Op::Lt, a, b), d(a), d(b));  // matches point::min
      case Op::Max: return make(Op::Select, make(Op::Gt, a, b), d(a), d(b));
      case Op::Select: return make(Op::Select, a, d(b), d(n.arg[2]));
      case Op::Pow: {
        const NodeId db = d(b);
        // Constant exponent: b a^(b-1) a' (also right for negative bases with integer b).
        const NodeId power_rule = mul(mul(b, make(Op::Pow, a, sub(b, c(1.0)))), d(a));
        if (zero(db)) return power_rule;
        return add(power_rule, mul(mul(id, make(Op::Log, a)), db));
      }
      case Op::Custom: return custom_rule(n);
      // Piecewise constant: derivative 0 wherever it exists.
      case Op::Floor: case Op::Ceil: case Op::Not: case Op::IsError:
      case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne:
      case Op::And: case Op::Or: case Op::Const:
        return c(0.0);
      // Tape-only forms never occur in the DAG.
      case Op::AddImm: case Op::MulImm: case Op::SubImm: case Op::DivImmR: case Op::DivImmL: case Op::MinImm:
      case Op::MaxImm: case Op::Load: case Op::Call: case Op::CallOut:
        break;
    }
    throw std::logic_error("genmod: derivative: unexpected op " + std::string(op_name(n.op)));
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
