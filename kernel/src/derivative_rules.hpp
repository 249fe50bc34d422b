// The derivative rule of every arithmetic DAG opcode, written once and used twice: over DAG
// nodes by the symbolic differentiator (derivative.cpp) and over doubles by the forward-mode
// gradient evaluator (gradient_evaluator.cpp). Every rule is linear in the operands'
// derivatives, so forward mode gets the coefficient of one operand by passing 1 for its
// derivative and 0 for the others'.
//
// An algebra M supplies the value type M::T and:
//   c(double)                   a constant;
//   make(op, x, y = {}, z = {}) the opcode applied (a new node, or its point value);
//   add, sub                    sums;
//   mul(x, y)                   0 when x or y is exactly 0: a term whose operand does not vary
//                               is dropped, not multiplied (its coefficient may be infinite,
//                               as d/da a^b at a = 0 for b < 1);
//   div(x, y)                   0 when x is exactly 0;
//   zero(x)                     true when x is exactly 0.
#pragma once

#include "genmod/kernel/opcode.hpp"

#include <stdexcept>
#include <string>

namespace genmod::detail {

// d(op(a, b, c)) for the arithmetic opcodes of the DAG, given the result v = op(a, b, c) and
// the operands' derivatives da, db, dc (those an opcode does not have are ignored). Leaves
// (Const, Var), custom applications and tape-only forms are the callers' (see
// dag_form_of_immediate below for the last).
template <class M>
typename M::T derivative_rule(M& m, Op op, typename M::T v, typename M::T a, typename M::T b,
                              typename M::T da, typename M::T db, typename M::T dc) {
  switch (op) {
    case Op::Neg: return m.make(Op::Neg, da);
    case Op::Add: return m.add(da, db);
    case Op::Sub: return m.sub(da, db);
    case Op::Mul: return m.add(m.mul(da, b), m.mul(a, db));
    case Op::Div: return m.div(m.sub(da, m.mul(v, db)), b);  // (a' - v b') / b
    case Op::Square: return m.mul(m.mul(m.c(2.0), a), da);
    case Op::Sqrt: return m.div(da, m.mul(m.c(2.0), v));
    case Op::Exp: return m.mul(v, da);
    case Op::Log: return m.div(da, a);
    case Op::Sin: return m.mul(m.make(Op::Cos, a), da);
    case Op::Cos: return m.mul(m.make(Op::Neg, m.make(Op::Sin, a)), da);
    case Op::Tan: return m.mul(m.add(m.c(1.0), m.make(Op::Square, v)), da);
    case Op::Asin: return m.div(da, m.make(Op::Sqrt, m.sub(m.c(1.0), m.make(Op::Square, a))));
    case Op::Acos: return m.make(Op::Neg, m.div(da, m.make(Op::Sqrt, m.sub(m.c(1.0), m.make(Op::Square, a)))));
    case Op::Atan: return m.div(da, m.add(m.c(1.0), m.make(Op::Square, a)));
    case Op::Atan2:  // atan2(y, x)' = (x y' - y x') / (x^2 + y^2)
      return m.div(m.sub(m.mul(b, da), m.mul(a, db)), m.add(m.make(Op::Square, b), m.make(Op::Square, a)));
    case Op::Abs: return m.make(Op::Select, m.make(Op::Lt, a, m.c(0.0)), m.make(Op::Neg, da), da);
    // The branch the point rules take (a tie goes to b, as min and max do at a point).
    case Op::Min: return m.make(Op::Select, m.make(Op::Lt, a, b), da, db);
    case Op::Max: return m.make(Op::Select, m.make(Op::Gt, a, b), da, db);
    case Op::Select: return m.make(Op::Select, a, db, dc);
    case Op::Pow: {
      // b a^(b-1) a' (also right for a negative base with an integer b), plus a^b log(a) b'
      // where the exponent varies: at a = 0 that term is 0 (mul drops it), below 0 it is an
      // error (no real derivative in b).
      const auto power_rule = m.mul(m.mul(b, m.make(Op::Pow, a, m.sub(b, m.c(1.0)))), da);
      if (m.zero(db)) return power_rule;
      return m.add(power_rule, m.mul(m.mul(v, m.make(Op::Log, a)), db));
    }
    // Piecewise constant: derivative 0 wherever it exists.
    case Op::Floor: case Op::Ceil: case Op::Not: case Op::IsError:
    case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne:
    case Op::And: case Op::Or:
      return m.c(0.0);
    case Op::Const: case Op::Var: case Op::Custom:
    case Op::AddImm: case Op::MulImm: case Op::SubImm: case Op::DivImmR: case Op::DivImmL: case Op::MinImm:
    case Op::MaxImm: case Op::Load: case Op::Call: case Op::CallOut:
      break;
  }
  throw std::logic_error("genmod: derivative: no rule for op " + std::string(op_name(op)));
}

// A tape-only immediate form as its DAG opcode: op(a, k) is dag(a, k), or dag(k, a) when
// `swapped` (k - a and k / a).
struct DagForm {
  Op op;
  bool swapped;
};
constexpr DagForm dag_form_of_immediate(Op op) noexcept {
  switch (op) {
    case Op::AddImm: return {Op::Add, false};
    case Op::MulImm: return {Op::Mul, false};
    case Op::SubImm: return {Op::Sub, true};
    case Op::DivImmR: return {Op::Div, false};
    case Op::DivImmL: return {Op::Div, true};
    case Op::MinImm: return {Op::Min, false};
    case Op::MaxImm: return {Op::Max, false};
    default: return {op, false};
  }
}

}  // namespace genmod::detail
