// The primitive scalar operations of the expression DAG and of tapes.
#pragma once

#include <cstdint>
#include <string_view>

namespace genmod {

enum class Op : std::uint8_t {
  // Leaves.
  Const,  // a constant
  Var,    // a parametric coordinate x(i)
  // Unary.
  Neg, Square, Sqrt, Exp, Log, Sin, Cos, Tan, Asin, Acos, Atan, Abs, Floor, Ceil,
  Not,      // 1 if the argument is 0, else 0
  IsError,  // 1 if evaluating the argument gives an error, else 0 (GENMOD's error(h))
  // Binary.
  Add, Sub, Mul, Div, Pow, Atan2, Min, Max,
  Lt, Le, Gt, Ge, Eq, Ne,  // relational: 1 or 0
  And, Or,                 // logical on "nonzero is true": 1 or 0
  // Ternary.
  Select,  // a != 0 ? b : c
  // Output `var` of a custom operator applied to an argument list (see custom_op.hpp).
  Custom,

  // Tape-only forms (never in the DAG): one operand is the constant constants[b].
  AddImm,   // a + k
  MulImm,   // a * k
  SubImm,   // k - a          (a - k is stored as AddImm with -k, which is exact)
  DivImmR,  // a / k
  DivImmL,  // k / a
  MinImm,   // min(a, k)
  MaxImm,   // max(a, k)
  Load,     // input number a
  Call,     // run custom call a, writing its outputs to the call slots
  CallOut,  // the value in call slot a
};

inline constexpr int kNumDagOps = static_cast<int>(Op::Custom) + 1;

// Number of register operands (0 for leaves, Custom and Call, whose arguments live elsewhere).
constexpr int arity(Op op) noexcept {
  if (op <= Op::Var) return 0;
  if (op <= Op::IsError) return 1;
  if (op <= Op::Or) return 2;
  if (op == Op::Select) return 3;
  if (op >= Op::AddImm && op <= Op::MaxImm) return 1;
  return 0;
}

constexpr bool is_commutative(Op op) noexcept {
  return op == Op::Add || op == Op::Mul || op == Op::Min || op == Op::Max || op == Op::Eq || op == Op::Ne ||
         op == Op::And || op == Op::Or;
}

// Operations whose interval evaluation makes a choice a pruned tape can keep.
constexpr bool has_choice(Op op) noexcept {
  return op == Op::Min || op == Op::Max || op == Op::Select || op == Op::MinImm || op == Op::MaxImm;
}

// Operations that can raise an error for some argument (before any argument errors).
constexpr bool can_error(Op op) noexcept {
  return op == Op::Sqrt || op == Op::Log || op == Op::Asin || op == Op::Acos || op == Op::Div || op == Op::Pow ||
         op == Op::Custom || op == Op::DivImmL || op == Op::DivImmR;
}

std::string_view op_name(Op op) noexcept;

}  // namespace genmod
