#include "genmod/kernel/point_evaluator.hpp"

#include "tape_data.hpp"

#include "custom_call.hpp"
#include "point_ops.hpp"

namespace genmod {

std::span<const double> PointEvaluator::eval(const Tape& tape, std::span<const double> point) {
  detail::check_inputs(tape, point.size(), "PointEvaluator");
  regs_.resize(tape.num_registers());
  slots_.resize(detail::num_call_slots(tape));
  const std::span<const double> k = tape.constants();
  double* r = regs_.data();
  for (const Clause& c : detail::clauses(tape)) {
    switch (c.op) {
#define GENMOD_CASE(NAME, TEXT, ARITY, FLAGS) \
  case Op::NAME: r[c.out] = detail::point_clause<Op::NAME>(r, k.data(), c.a, c.b, c.c); break;
      GENMOD_ARITHMETIC_OPCODES(GENMOD_CASE)
#undef GENMOD_CASE
      case Op::Const: r[c.out] = k[c.a]; break;
      case Op::Load: r[c.out] = point[c.a]; break;
      case Op::Call: {
        const CallSite& cs = detail::calls(tape)[c.a];
        args_.resize(cs.num_args);
        for (std::uint32_t i = 0; i < cs.num_args; ++i) args_[i] = r[detail::call_arg_registers(tape)[cs.first_arg + i]];
        detail::run_call_point(tape, c.a, args_, slots_);
        break;
      }
      case Op::CallOut: r[c.out] = slots_[c.a]; break;
      case Op::Var: case Op::Custom: break;  // never on tapes
    }
  }
  out_.resize(tape.num_outputs());
  for (std::size_t j = 0; j < out_.size(); ++j) out_[j] = r[detail::output_registers(tape)[j]];
  return out_;
}

std::vector<double> evaluate(const Fn& f, std::span<const double> coordinates) {
  const std::vector<int> inputs = f.inputs();
  std::vector<double> point;
  for (int i : inputs) {
    if (static_cast<std::size_t>(i) >= coordinates.size())
      throw std::invalid_argument("genmod: evaluate: the function depends on x(" + std::to_string(i) + ") but only " +
                                  std::to_string(coordinates.size()) + " coordinates were given");
    point.push_back(coordinates[static_cast<std::size_t>(i)]);
  }
  Tape tape(f, inputs);
  PointEvaluator ev;
  const auto out = ev.eval(tape, point);
  return {out.begin(), out.end()};
}

}  // namespace genmod
