#include "genmod/kernel/batch_evaluator.hpp"

#include "tape_data.hpp"

#include "custom_call.hpp"
#include "point_ops.hpp"

#include <algorithm>
#include <stdexcept>

namespace genmod {
namespace {

// One clause over n points. Plain indexed loops over separate arrays vectorize; the result
// may alias an operand (same index only), which the compiler's overlap check handles.
template <Op op>
inline void run_clause(double* out, const double* a, const double* b, const double* c, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = detail::point_op<op>(a[i], b[i], c[i]);
}

template <Op op>
inline void run_clause_imm(double* out, const double* a, double k, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = detail::point_op<op>(a[i], k, 0.0);
}

// The tape loop, compiled twice (AVX2 and baseline) and dispatched at load time.
__attribute__((target_clones("avx2", "default"))) void run_tape(const Clause* clauses, std::size_t num_clauses,
                                                                 const double* constants, double* regs,
                                                                 const double* const* inputs, std::size_t offset,
                                                                 std::size_t stride, std::size_t n, const Tape& tape,
                                                                 std::vector<double>& slots, std::vector<double>& args,
                                                                 std::vector<double>& call_out) {
  constexpr std::size_t W = BatchEvaluator::kChunk;
  for (std::size_t ci = 0; ci < num_clauses; ++ci) {
    const Clause& c = clauses[ci];
    // Operand rows; fields that are not registers (constant index, input position, slot)
    // are mapped to row 0 so that no pointer leaves the register file.
    const int ar = arity(c.op);
    const bool imm = has_immediate(c.op);
    double* out = regs + std::size_t{c.out} * W;
    const double* a = regs + (ar >= 1 ? std::size_t{c.a} * W : 0);
    const double* b = regs + (ar >= 2 && !imm ? std::size_t{c.b} * W : 0);
    const double* cc = regs + (ar >= 3 ? std::size_t{c.c} * W : 0);
    switch (c.op) {
#define GENMOD_CASE(NAME, TEXT, ARITY, FLAGS)                                \
  case Op::NAME:                                                            \
    if constexpr (has_immediate(Op::NAME))                                  \
      run_clause_imm<Op::NAME>(out, a, constants[c.b], n);                  \
    else                                                                    \
      run_clause<Op::NAME>(out, a, ARITY >= 2 ? b : a, ARITY >= 3 ? cc : a, n); \
    break;
      GENMOD_ARITHMETIC_OPCODES(GENMOD_CASE)
#undef GENMOD_CASE
      case Op::Const: std::fill(out, out + n, constants[c.a]); break;
      case Op::Load:
        if (stride == 1) {
          std::copy(inputs[c.a] + offset, inputs[c.a] + offset + n, out);
        } else {
          const double* in = inputs[c.a] + offset * stride;
          for (std::size_t p = 0; p < n; ++p) out[p] = in[p * stride];
        }
        break;
      case Op::Call: {
        // Custom operators are called point by point; their outputs go to per-slot rows.
        const CallSite& cs = detail::calls(tape)[c.a];
        args.resize(cs.num_args);
        call_out.resize(detail::num_call_slots(tape));
        for (std::size_t p = 0; p < n; ++p) {
          for (std::uint32_t i = 0; i < cs.num_args; ++i)
            args[i] = regs[std::size_t{detail::call_arg_registers(tape)[cs.first_arg + i]} * W + p];
          detail::run_call_point(tape, c.a, args, call_out);
          for (std::uint32_t j = 0; j < cs.num_outputs; ++j) slots[(cs.first_slot + j) * W + p] = call_out[cs.first_slot + j];
        }
        break;
      }
      case Op::CallOut: std::copy(slots.data() + std::size_t{c.a} * W, slots.data() + std::size_t{c.a} * W + n, out); break;
      case Op::Var: case Op::Custom: break;  // never on tapes
    }
  }
}

}  // namespace

void BatchEvaluator::eval(const Tape& tape, std::span<const double* const> inputs, std::size_t count,
                          std::span<double* const> outputs, std::size_t input_stride, std::size_t output_stride) {
  detail::check_inputs(tape, inputs.size(), "BatchEvaluator");
  if (input_stride == 0 || output_stride == 0)
    throw std::invalid_argument("genmod: BatchEvaluator: strides must be >= 1");
  if (outputs.size() != tape.num_outputs())
    throw std::invalid_argument("genmod: BatchEvaluator: the tape has " + std::to_string(tape.num_outputs()) +
                                " outputs, got " + std::to_string(outputs.size()) + " output arrays");
  regs_.resize(std::size_t{tape.num_registers()} * kChunk);
  slots_.resize(std::size_t{detail::num_call_slots(tape)} * kChunk);
  for (std::size_t offset = 0; offset < count; offset += kChunk)
    run_chunk(tape, inputs, offset, std::min(kChunk, count - offset), outputs, input_stride, output_stride);
}

void BatchEvaluator::run_chunk(const Tape& tape, std::span<const double* const> inputs, std::size_t offset,
                               std::size_t n, std::span<double* const> outputs, std::size_t input_stride,
                               std::size_t output_stride) {
  const auto clauses = detail::clauses(tape);
  run_tape(clauses.data(), clauses.size(), tape.constants().data(), regs_.data(), inputs.data(), offset, input_stride,
           n, tape, slots_, args_, call_out_);
  for (std::size_t j = 0; j < outputs.size(); ++j) {
    const double* r = regs_.data() + std::size_t{detail::output_registers(tape)[j]} * kChunk;
    if (output_stride == 1) {
      std::copy(r, r + n, outputs[j] + offset);
    } else {
      double* o = outputs[j] + offset * output_stride;
      for (std::size_t p = 0; p < n; ++p) o[p * output_stride] = r[p];
    }
  }
}

}  // namespace genmod
