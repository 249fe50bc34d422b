// One node of a function's expression, read without the store's internals: the
// opcode at the root of a scalar Fn and its operands as Fns. Layers above the kernel walk and
// rewrite expressions with it (a constraint's and / or skeleton and its relations) and build
// the new ones with Fn arithmetic, which applies the store's usual simplifications.
//
// The operands of a commutative opcode (+, *, min, max, ==, and, ...) are in the store's
// order (by the operands' shapes), not necessarily the order they were written in.
//
// Example:
//   using namespace genmod;
//   Fn c = (x(0) <= 1.0) && (x(1) == 2.0);
//   Expression e = expression(c);               // Op::And, operands x0 <= 1 and x1 == 2
//   Expression le = expression(x(0) <= 1.0);    // Op::Le, operands {x(0), 1} (not commutative)
//   if (e.op != Op::And || e.operands.size() != 2 || le.op != Op::Le ||
//       expression(le.operands[1]).value != 1.0 || expression(le.operands[0]).coordinate != 0)
//     throw std::logic_error("expression");
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/opcode.hpp"

#include <cstddef>
#include <vector>

namespace genmod {

struct Expression {
  Op op = Op::Const;
  std::vector<Fn> operands;  // in the store's order; for Op::Custom the operator's arguments
  double value = 0.0;        // Op::Const: the number
  int coordinate = -1;       // Op::Var: x(coordinate)
  int output = -1;           // Op::Custom: which output of the operator
};

// The root of the scalar function f. std::invalid_argument unless f has one component.
Expression expression(const Fn& f);

// The number of distinct nodes of f's expression (shared subexpressions count once).
std::size_t count_nodes(const Fn& f);

// The number of live nodes in the store, and of live custom operators: what the shapes that
// are still held take (the store reclaims the rest; see NodeId in fn.hpp).
std::size_t live_nodes() noexcept;
std::size_t live_custom_operators() noexcept;

}  // namespace genmod
