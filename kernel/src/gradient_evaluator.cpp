#include "genmod/kernel/gradient_evaluator.hpp"

#include "tape_data.hpp"

#include "custom_call.hpp"
#include "derivative_rules.hpp"
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

// Doubles as the algebra of derivative_rules.hpp.
struct PointAlgebra {
  using T = double;
  static double c(double x) { return x; }
  static double make(Op op, double a, double b = 0.0, double c = 0.0) { return detail::point_value(op, a, b, c); }
  static bool zero(double x) { return x == 0.0; }
  static double add(double x, double y) { return x + y; }
  static double sub(double x, double y) { return x - y; }
  static double mul(double x, double y) { return zero(x) || zero(y) ? 0.0 : x * y; }
  static double div(double x, double y) { return zero(x) ? 0.0 : x / y; }
};

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
    // The coefficients of a's, b's and c's partials (the chain rule).
    double da = 0.0, db = 0.0, dc = 0.0;
    switch (c.op) {
      case Op::Const: v = konst[c.a]; break;
      case Op::Load: v = point[c.a]; break;
      case Op::CallOut: v = slots_[std::size_t{c.a} * stride]; break;
      default: v = detail::point_value(c.op, av, bv, cv); break;
    }
    if (is_arithmetic(c.op)) {
      // The coefficients of the rule (derivative_rules.hpp): operand k's is the rule with
      // derivative 1 for k and 0 for the others. An immediate form is its DAG opcode with the
      // constant as the other operand.
      const detail::DagForm form = detail::dag_form_of_immediate(c.op);
      const double x = form.swapped ? bv : av, y = form.swapped ? av : bv;
      PointAlgebra m;
      auto coefficient = [&](int operand) {
        return detail::derivative_rule(m, form.op, v, x, y, operand == 0 ? 1.0 : 0.0, operand == 1 ? 1.0 : 0.0,
                                       operand == 2 ? 1.0 : 0.0);
      };
      if (imm) {
        da = coefficient(form.swapped ? 1 : 0);
      } else {
        if (ar >= 1) da = coefficient(0);
        if (ar >= 2) db = coefficient(1);
        if (ar >= 3) dc = coefficient(2);
      }
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
