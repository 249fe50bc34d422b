#include "genmod/kernel/opcode.hpp"

namespace genmod {

std::string_view op_name(Op op) noexcept {
  switch (op) {
    case Op::Const: return "const";
    case Op::Var: return "var";
    case Op::Neg: return "neg";
    case Op::Square: return "square";
    case Op::Sqrt: return "sqrt";
    case Op::Exp: return "exp";
    case Op::Log: return "log";
    case Op::Sin: return "sin";
    case Op::Cos: return "cos";
    case Op::Tan: return "tan";
    case Op::Asin: return "asin";
    case Op::Acos: return "acos";
    case Op::Atan: return "atan";
    case Op::Abs: return "abs";
    case Op::Floor: return "floor";
    case Op::Ceil: return "ceil";
    case Op::Not: return "not";
    case Op::IsError: return "is-error";
    case Op::Add: return "add";
    case Op::Sub: return "sub";
    case Op::Mul: return "mul";
    case Op::Div: return "div";
    case Op::Pow: return "pow";
    case Op::Atan2: return "atan2";
    case Op::Min: return "min";
    case Op::Max: return "max";
    case Op::Lt: return "lt";
    case Op::Le: return "le";
    case Op::Gt: return "gt";
    case Op::Ge: return "ge";
    case Op::Eq: return "eq";
    case Op::Ne: return "ne";
    case Op::And: return "and";
    case Op::Or: return "or";
    case Op::Select: return "select";
    case Op::Custom: return "custom";
    case Op::AddImm: return "add-imm";
    case Op::MulImm: return "mul-imm";
    case Op::SubImm: return "sub-imm";
    case Op::DivImmR: return "div-imm-r";
    case Op::DivImmL: return "div-imm-l";
    case Op::MinImm: return "min-imm";
    case Op::MaxImm: return "max-imm";
    case Op::Load: return "load";
    case Op::Call: return "call";
    case Op::CallOut: return "call-out";
  }
  return "?";
}

}  // namespace genmod
