// The point semantics of every tape opcode, shared by the scalar and batch evaluators so
// that both give bitwise identical results. An error is NaN, and every operator propagates
// NaN from its operands, except select (which ignores the branch it does not take) and
// is-error (which turns it into 1).
#pragma once

#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/opcode.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace genmod::detail {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

inline double truth(bool t) noexcept { return t ? 1.0 : 0.0; }
inline bool either_nan(double a, double b) noexcept { return a != a || b != b; }

// b is the second operand, or the immediate for the *Imm forms.
template <Op op>
inline double point_op(double a, double b, double c) noexcept {
  if constexpr (op == Op::Neg) return -a;
  else if constexpr (op == Op::Square) return a * a;
  else if constexpr (op == Op::Sqrt) return std::sqrt(a);  // NaN below 0
  else if constexpr (op == Op::Exp) return std::exp(a);
  else if constexpr (op == Op::Log) return point::log(a);
  else if constexpr (op == Op::Sin) return std::sin(a);
  else if constexpr (op == Op::Cos) return std::cos(a);
  else if constexpr (op == Op::Tan) return std::tan(a);
  else if constexpr (op == Op::Asin) return std::asin(a);  // NaN outside [-1, 1]
  else if constexpr (op == Op::Acos) return std::acos(a);
  else if constexpr (op == Op::Atan) return std::atan(a);
  else if constexpr (op == Op::Abs) return std::fabs(a);
  else if constexpr (op == Op::Floor) return std::floor(a);
  else if constexpr (op == Op::Ceil) return std::ceil(a);
  else if constexpr (op == Op::Not) return a != a ? kNaN : truth(a == 0.0);
  else if constexpr (op == Op::IsError) return truth(a != a);
  else if constexpr (op == Op::Add || op == Op::AddImm) return a + b;
  else if constexpr (op == Op::Sub) return a - b;
  else if constexpr (op == Op::SubImm) return b - a;
  else if constexpr (op == Op::Mul || op == Op::MulImm) return a * b;
  else if constexpr (op == Op::Div || op == Op::DivImmR) return point::div(a, b);
  else if constexpr (op == Op::DivImmL) return point::div(b, a);
  else if constexpr (op == Op::Pow) return point::pow(a, b);
  else if constexpr (op == Op::Atan2) return std::atan2(a, b);
  else if constexpr (op == Op::Min || op == Op::MinImm) return point::min(a, b);
  else if constexpr (op == Op::Max || op == Op::MaxImm) return point::max(a, b);
  else if constexpr (op == Op::Lt) return either_nan(a, b) ? kNaN : truth(a < b);
  else if constexpr (op == Op::Le) return either_nan(a, b) ? kNaN : truth(a <= b);
  else if constexpr (op == Op::Gt) return either_nan(a, b) ? kNaN : truth(a > b);
  else if constexpr (op == Op::Ge) return either_nan(a, b) ? kNaN : truth(a >= b);
  else if constexpr (op == Op::Eq) return either_nan(a, b) ? kNaN : truth(a == b);
  else if constexpr (op == Op::Ne) return either_nan(a, b) ? kNaN : truth(a != b);
  else if constexpr (op == Op::And) return either_nan(a, b) ? kNaN : truth(a != 0.0 && b != 0.0);
  else if constexpr (op == Op::Or) return either_nan(a, b) ? kNaN : truth(a != 0.0 || b != 0.0);
  else if constexpr (op == Op::Select) return a != a ? kNaN : (a != 0.0 ? b : c);
  else static_assert(op == Op::Neg, "point_op: an arithmetic opcode without a point rule");
}

// The point rule of clause c over a register file r and the tape's constants k (the operand
// positions follow the opcode table's arity and immediate flag).
template <Op op>
inline double point_clause(const double* r, const double* k, std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept {
  constexpr int n = arity(op);
  const double second = has_immediate(op) ? k[b] : r[n >= 2 ? b : a];
  return point_op<op>(r[a], second, r[n >= 3 ? c : a]);
}

// The point rule of an arithmetic opcode chosen at run time (b is the second operand or the
// immediate); NaN for the others, which have no point rule of their own.
inline double point_value(Op op, double a, double b, double c) noexcept {
  switch (op) {
#define GENMOD_CASE(NAME, TEXT, ARITY, FLAGS) \
  case Op::NAME: return point_op<Op::NAME>(a, b, c);
    GENMOD_ARITHMETIC_OPCODES(GENMOD_CASE)
#undef GENMOD_CASE
    default: return kNaN;
  }
}

}  // namespace genmod::detail
