// The primitive scalar operations of the expression DAG and of tapes.
//
// GENMOD_OPCODES is the one table of opcodes: every property below (the enum, names, arity,
// flags) is generated from it, and every evaluator dispatches over it, so an opcode's row here
// and its rules (kernel/src/point_ops.hpp: point; interval_evaluator.cpp: enclosure;
// derivative_rules.hpp: derivative, symbolic and forward mode; tape_contractor.cpp: HC4
// projection)
// are all there is to an opcode. The evaluators' switches have no default case, so a new row
// without a rule fails to compile (-Werror=switch).
#pragma once

#include <cstdint>
#include <string_view>

namespace genmod {

// Flags of an opcode row.
namespace op_flag {
inline constexpr unsigned kCommutative = 1;  // f(a, b) = f(b, a)
inline constexpr unsigned kChoice = 2;       // its interval evaluation may pick one operand (pruning)
inline constexpr unsigned kCanError = 4;     // may raise an error for some argument (NaN at a point)
inline constexpr unsigned kImmediate = 8;    // tape-only: operand b is the constant constants[b]
inline constexpr unsigned kTapeOnly = 16;    // never in the DAG
inline constexpr unsigned kExact = 32;       // on doubles, the point rule's result is exact
}  // namespace op_flag

// X(Name, "name", register operands, flags), in sections. The enum follows the order of
// GENMOD_OPCODES: leaves, the DAG's arithmetic (unary, binary, ternary), custom (the DAG's
// ops end there), then the tape-only forms. kExact: the point rule's double result is the
// real result (constant folding may use it).
#define GENMOD_LEAF_OPCODES(X)                                                                      \
  X(Const, "const", 0, op_flag::kExact)                                                            \
  X(Var, "var", 0, 0) /* a parametric coordinate x(i) */

#define GENMOD_DAG_ARITHMETIC_OPCODES(X)                                                            \
  X(Neg, "neg", 1, op_flag::kExact)                                                                \
  X(Square, "square", 1, 0)                                                                        \
  X(Sqrt, "sqrt", 1, op_flag::kCanError)                                                           \
  X(Exp, "exp", 1, 0)                                                                              \
  X(Log, "log", 1, op_flag::kCanError)                                                             \
  X(Sin, "sin", 1, 0)                                                                              \
  X(Cos, "cos", 1, 0)                                                                              \
  X(Tan, "tan", 1, 0)                                                                              \
  X(Asin, "asin", 1, op_flag::kCanError)                                                           \
  X(Acos, "acos", 1, op_flag::kCanError)                                                           \
  X(Atan, "atan", 1, 0)                                                                            \
  X(Abs, "abs", 1, op_flag::kExact)                                                                \
  X(Floor, "floor", 1, op_flag::kExact)                                                            \
  X(Ceil, "ceil", 1, op_flag::kExact)                                                              \
  X(Not, "not", 1, op_flag::kExact)          /* 1 if the argument is 0, else 0 */                  \
  X(IsError, "is-error", 1, op_flag::kExact) /* 1 if the argument is an error (GENMOD's error(h)) */ \
  X(Add, "add", 2, op_flag::kCommutative)                                                          \
  X(Sub, "sub", 2, 0)                                                                              \
  X(Mul, "mul", 2, op_flag::kCommutative)                                                          \
  X(Div, "div", 2, op_flag::kCanError)                                                             \
  X(Pow, "pow", 2, op_flag::kCanError)                                                             \
  X(Atan2, "atan2", 2, 0)                                                                          \
  X(Min, "min", 2, op_flag::kCommutative | op_flag::kChoice | op_flag::kExact)                     \
  X(Max, "max", 2, op_flag::kCommutative | op_flag::kChoice | op_flag::kExact)                     \
  X(Lt, "lt", 2, op_flag::kExact) /* relational: 1 or 0 */                                         \
  X(Le, "le", 2, op_flag::kExact)                                                                  \
  X(Gt, "gt", 2, op_flag::kExact)                                                                  \
  X(Ge, "ge", 2, op_flag::kExact)                                                                  \
  X(Eq, "eq", 2, op_flag::kCommutative | op_flag::kExact)                                          \
  X(Ne, "ne", 2, op_flag::kCommutative | op_flag::kExact)                                          \
  X(And, "and", 2, op_flag::kCommutative | op_flag::kExact) /* logical, nonzero is true: 1 or 0 */ \
  X(Or, "or", 2, op_flag::kCommutative | op_flag::kExact)                                          \
  X(Select, "select", 3, op_flag::kChoice | op_flag::kExact) /* a != 0 ? b : c */

// Output `var` of a custom operator applied to an argument list (see custom_op.hpp).
#define GENMOD_CUSTOM_OPCODES(X) X(Custom, "custom", 0, op_flag::kCanError)

// Tape-only arithmetic: operand b is the constant constants[b] (a - k is add-imm with -k).
#define GENMOD_IMMEDIATE_OPCODES(X)                                                                 \
  X(AddImm, "add-imm", 1, op_flag::kImmediate | op_flag::kTapeOnly)  /* a + k */                   \
  X(MulImm, "mul-imm", 1, op_flag::kImmediate | op_flag::kTapeOnly)  /* a * k */                   \
  X(SubImm, "sub-imm", 1, op_flag::kImmediate | op_flag::kTapeOnly)  /* k - a */                   \
  X(DivImmR, "div-imm-r", 1, op_flag::kImmediate | op_flag::kTapeOnly | op_flag::kCanError) /* a / k */ \
  X(DivImmL, "div-imm-l", 1, op_flag::kImmediate | op_flag::kTapeOnly | op_flag::kCanError) /* k / a */ \
  X(MinImm, "min-imm", 1, op_flag::kImmediate | op_flag::kTapeOnly | op_flag::kChoice)             \
  X(MaxImm, "max-imm", 1, op_flag::kImmediate | op_flag::kTapeOnly | op_flag::kChoice)

// The tape's plumbing.
#define GENMOD_PLUMBING_OPCODES(X)                                                                  \
  X(Load, "load", 0, op_flag::kTapeOnly)        /* input number a */                                \
  X(Call, "call", 0, op_flag::kTapeOnly)        /* run custom call a, writing the call slots */     \
  X(CallOut, "call-out", 0, op_flag::kTapeOnly) /* the value in call slot a */

// Every opcode a point rule computes from its register operands (and immediate).
#define GENMOD_ARITHMETIC_OPCODES(X) GENMOD_DAG_ARITHMETIC_OPCODES(X) GENMOD_IMMEDIATE_OPCODES(X)

#define GENMOD_OPCODES(X)                                                                          \
  GENMOD_LEAF_OPCODES(X)                                                                           \
  GENMOD_DAG_ARITHMETIC_OPCODES(X)                                                                 \
  GENMOD_CUSTOM_OPCODES(X)                                                                         \
  GENMOD_IMMEDIATE_OPCODES(X)                                                                      \
  GENMOD_PLUMBING_OPCODES(X)

enum class Op : std::uint8_t {
#define GENMOD_OPCODE_ENUM(NAME, TEXT, ARITY, FLAGS) NAME,
  GENMOD_OPCODES(GENMOD_OPCODE_ENUM)
#undef GENMOD_OPCODE_ENUM
};

inline constexpr int kNumOps = 0
#define GENMOD_OPCODE_COUNT(NAME, TEXT, ARITY, FLAGS) +1
    GENMOD_OPCODES(GENMOD_OPCODE_COUNT)
#undef GENMOD_OPCODE_COUNT
    ;
inline constexpr int kNumDagOps = static_cast<int>(Op::Custom) + 1;

namespace opcode_detail {
struct Row {
  std::string_view name;
  int arity;
  unsigned flags;
};
inline constexpr Row kRows[] = {
#define GENMOD_OPCODE_ROW(NAME, TEXT, ARITY, FLAGS) Row{TEXT, ARITY, FLAGS},
    GENMOD_OPCODES(GENMOD_OPCODE_ROW)
#undef GENMOD_OPCODE_ROW
};
static_assert(sizeof(kRows) / sizeof(kRows[0]) == kNumOps);
constexpr const Row& row(Op op) noexcept { return kRows[static_cast<int>(op)]; }
}  // namespace opcode_detail

// Number of register operands (0 for leaves, Custom and Call, whose arguments live elsewhere).
constexpr int arity(Op op) noexcept { return opcode_detail::row(op).arity; }

constexpr bool is_commutative(Op op) noexcept { return opcode_detail::row(op).flags & op_flag::kCommutative; }

// Operations whose interval evaluation makes a choice a pruned tape can keep.
constexpr bool has_choice(Op op) noexcept { return opcode_detail::row(op).flags & op_flag::kChoice; }

// Operations that can raise an error for some argument (before any argument errors).
constexpr bool can_error(Op op) noexcept { return opcode_detail::row(op).flags & op_flag::kCanError; }

// Tape-only forms whose operand b is an index into the tape's constants.
constexpr bool has_immediate(Op op) noexcept { return opcode_detail::row(op).flags & op_flag::kImmediate; }

// The point rule gives the exact real result on doubles (constant folding may use it).
constexpr bool is_exact(Op op) noexcept { return opcode_detail::row(op).flags & op_flag::kExact; }

// Arithmetic opcodes (GENMOD_ARITHMETIC_OPCODES): a point rule computes them from their
// register operands and immediate, unlike leaves, custom applications and call plumbing.
constexpr bool is_arithmetic(Op op) noexcept {
  switch (op) {
#define GENMOD_OPCODE_ARITHMETIC(NAME, TEXT, ARITY, FLAGS) case Op::NAME:
    GENMOD_ARITHMETIC_OPCODES(GENMOD_OPCODE_ARITHMETIC)
#undef GENMOD_OPCODE_ARITHMETIC
    return true;
    default: return false;
  }
}

constexpr std::string_view op_name(Op op) noexcept { return opcode_detail::row(op).name; }

}  // namespace genmod
