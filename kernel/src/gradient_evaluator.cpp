#include "genmod/kernel/gradient_evaluator.hpp"

#include "tape_data.hpp"

#include "custom_call.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "point_ops.hpp"

#include <algorithm>
#include <cmath>

namespace genmod {
namespace {

// The Jacobian of a custom operator's outputs with respect to its arguments, as a tape in
// the argument values (built once per operator from its symbolic derivative).
Tape custom_partials_tape(const CustomOp& op) {
  std::vector<Fn> args;
  std::vector<int> inputs;
  for (int k = 0; k < op.num_args(); ++k) {
    args.push_back(x(k));
    inputs.push_back(k);
  }
  std::vector<Fn> columns;
  for (int k = 0; k < op.num_args(); ++k) columns.push_back(op.derivative(args, k));
  if (columns.empty()) columns.push_back(cat(std::vector<Fn>(static_cast<std::size_t>(op.num_outputs()), Fn(0.0))));
  return Tape(cat(columns), inputs);  // component k * num_outputs + j = d out_j / d arg_k
}

}  // namespace

void GradientEvaluator::eval(const Tape& tape, std::span<const double> point) {
  detail::check_inputs(tape, point.size(), "GradientEvaluator");
  const std::size_t n = tape.num_inputs();
  const std::size_t stride = n + 1;  // value, then partials
  regs_.assign(std::size_t{tape.num_registers()} * stride, 0.0);
  slots_.assign(std::size_t{detail::num_call_slots(tape)} * stride, 0.0);
  scratch_.resize(stride);
  const std::span<const double> konst = tape.constants();

  for (const Clause& c : detail::clauses(tape)) {
    double* out = &regs_[std::size_t{c.out} * stride];
    // Operand rows (only those the clause has; the others alias a harmless row).
    const int ar = arity(c.op);
    const bool imm_form = has_immediate(c.op);
    const double* a = &regs_[ar >= 1 ? std::size_t{c.a} * stride : 0];
    const double* b = &regs_[ar >= 2 && !imm_form ? std::size_t{c.b} * stride : 0];
    const double* cc = &regs_[ar >= 3 ? std::size_t{c.c} * stride : 0];
    if (c.op == Op::Call) {
      const CallSite& cs = detail::calls(tape)[c.a];
      const CustomOp& op = *cs.op;
      std::vector<double> args(cs.num_args), outs(detail::num_call_slots(tape));
      for (std::uint32_t k = 0; k < cs.num_args; ++k) args[k] = regs_[std::size_t{detail::call_arg_registers(tape)[cs.first_arg + k]} * stride];
      detail::run_call_point(tape, c.a, args, outs);
      // Keyed by address; the weak owner tells a live operator from a later one at the same
      // address after the first was destroyed.
      auto it = custom_partials_.find(&op);
      if (it != custom_partials_.end() && it->second.op.expired()) {
        custom_partials_.erase(it);
        it = custom_partials_.end();
      }
      if (it == custom_partials_.end())
        it = custom_partials_.emplace(&op, CustomPartials{detail::custom_ops(tape)[cs.op_index], custom_partials_tape(op)}).first;
      PointEvaluator pe;
      const std::span<const double> partials = cs.num_args ? pe.eval(it->second.tape, args) : std::span<const double>{};
      for (std::uint32_t j = 0; j < cs.num_outputs; ++j) {
        double* slot = &slots_[std::size_t{cs.first_slot + j} * stride];
        std::fill(slot, slot + stride, 0.0);
        slot[0] = outs[cs.first_slot + j];
        for (std::uint32_t k = 0; k < cs.num_args; ++k) {
          const double* arg = &regs_[std::size_t{detail::call_arg_registers(tape)[cs.first_arg + k]} * stride];
          const double p = partials[std::size_t{k} * cs.num_outputs + j];
          for (std::size_t i = 1; i < stride; ++i) slot[i] += p * arg[i];
        }
      }
      continue;
    }
    // The value first: operands may share the output register, so read them before writing.
    const bool imm = imm_form;
    const double k = imm ? konst[c.b] : 0.0;
    const double av = a[0], bv = imm ? k : b[0], cv = cc[0];
    double v;
    // d = coefficient on a's partials, e = on b's, f = on c's (chain rule, one line per op).
    double da = 0.0, db = 0.0, dc = 0.0;
    switch (c.op) {
      case Op::Const: v = konst[c.a]; break;
      case Op::Load: v = point[c.a]; break;
      case Op::CallOut: v = slots_[std::size_t{c.a} * stride]; break;
      default: v = detail::point_value(c.op, av, bv, cv); break;
    }
    switch (c.op) {
      case Op::Neg: da = -1.0; break;
      case Op::Square: da = 2.0 * av; break;
      case Op::Sqrt: da = 0.5 / v; break;
      case Op::Exp: da = v; break;
      case Op::Log: da = 1.0 / av; break;
      case Op::Sin: da = std::cos(av); break;
      case Op::Cos: da = -std::sin(av); break;
      case Op::Tan: da = 1.0 + v * v; break;
      case Op::Asin: da = 1.0 / std::sqrt(1.0 - av * av); break;
      case Op::Acos: da = -1.0 / std::sqrt(1.0 - av * av); break;
      case Op::Atan: da = 1.0 / (1.0 + av * av); break;
      case Op::Abs: da = av < 0.0 ? -1.0 : 1.0; break;
      case Op::Add: da = 1.0; db = 1.0; break;
      case Op::Sub: da = 1.0; db = -1.0; break;
      case Op::Mul: da = bv; db = av; break;
      case Op::Div: da = 1.0 / bv; db = -v / bv; break;
      case Op::Pow:
        da = bv * std::pow(av, bv - 1.0);
        db = av > 0.0 ? v * std::log(av) : 0.0;
        break;
      case Op::Atan2: {
        const double r2 = av * av + bv * bv;
        da = bv / r2;
        db = -av / r2;
        break;
      }
      case Op::Min: (av < bv ? da : db) = 1.0; break;
      case Op::Max: (av > bv ? da : db) = 1.0; break;
      case Op::Select: (av != 0.0 ? db : dc) = 1.0; break;
      case Op::AddImm: da = 1.0; break;
      case Op::MulImm: da = k; break;
      case Op::SubImm: da = -1.0; break;
      case Op::DivImmR: da = 1.0 / k; break;
      case Op::DivImmL: da = -v / av; break;
      case Op::MinImm: da = av < k ? 1.0 : 0.0; break;
      case Op::MaxImm: da = av > k ? 1.0 : 0.0; break;
      // Piecewise constant: derivative 0 wherever it exists.
      case Op::Floor: case Op::Ceil: case Op::Not: case Op::IsError: case Op::Lt: case Op::Le: case Op::Gt:
      case Op::Ge: case Op::Eq: case Op::Ne: case Op::And: case Op::Or:
      // Leaves and plumbing: set below.
      case Op::Const: case Op::Var: case Op::Custom: case Op::Load: case Op::Call: case Op::CallOut:
        break;
    }
    // Partials into a temporary first: `out` may alias an operand.
    double* g = scratch_.data();
    for (std::size_t i = 1; i < stride; ++i) {
      // A term whose operand does not depend on the input is skipped, not multiplied: its
      // coefficient may be infinite (0^y at y < 1), as the symbolic derivative skips it too.
      double s = 0.0;
      if (da != 0.0 && a[i] != 0.0) s += da * a[i];
      if (db != 0.0 && b[i] != 0.0) s += db * b[i];
      if (dc != 0.0 && cc[i] != 0.0) s += dc * cc[i];
      g[i] = s;
    }
    if (c.op == Op::Load) {
      std::fill(g + 1, g + stride, 0.0);
      g[1 + c.a] = 1.0;
    } else if (c.op == Op::CallOut) {
      std::copy(&slots_[std::size_t{c.a} * stride + 1], &slots_[std::size_t{c.a} * stride + stride], g + 1);
    }
    out[0] = v;
    std::copy(g + 1, g + stride, out + 1);
  }
  values_.resize(tape.num_outputs());
  jacobian_.resize(tape.num_outputs() * n);
  for (std::size_t j = 0; j < tape.num_outputs(); ++j) {
    const double* r = &regs_[std::size_t{detail::output_registers(tape)[j]} * stride];
    values_[j] = r[0];
    std::copy(r + 1, r + stride, jacobian_.begin() + static_cast<std::ptrdiff_t>(j * n));
  }
}

}  // namespace genmod
