// expression(): a scalar Fn's root node as an opcode and operand Fns (see expression.hpp).
#include "genmod/kernel/expression.hpp"

#include "dag.hpp"

#include <stdexcept>
#include <string>

namespace genmod {

Expression expression(const Fn& f) {
  if (f.dim() != 1)
    throw std::invalid_argument("genmod: expression: the function must be scalar, got dimension " +
                                std::to_string(f.dim()));
  const Node& n = dag::node(f.node(0));
  Expression e;
  e.op = n.op;
  if (n.op == Op::Const) {
    e.value = n.value;
  } else if (n.op == Op::Var) {
    e.coordinate = n.index;
  } else if (n.op == Op::Custom) {
    e.output = n.index;
    for (NodeId a : dag::custom_args(n)) e.operands.push_back(Fn::of(a));
  } else {
    for (int i = 0; i < arity(n.op); ++i) e.operands.push_back(Fn::of(n.arg[i]));
  }
  return e;
}

std::size_t count_nodes(const Fn& f) { return dag::topological_order(f.nodes()).size(); }

std::size_t live_nodes() noexcept { return dag::size(); }
std::size_t live_custom_operators() noexcept { return dag::custom_count(); }

}  // namespace genmod
