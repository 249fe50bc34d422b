// Batch point evaluation: many points per call, structure of arrays.
//
// Each clause runs as a tight loop over a chunk of points, which the compiler vectorizes
// (an AVX2 version is selected at run time where the CPU has it). Results are bitwise equal
// to PointEvaluator's.
#pragma once

#include "genmod/kernel/tape.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace genmod {

class BatchEvaluator {
 public:
  static constexpr std::size_t kChunk = 256;  // points per pass over the tape

  // inputs[k][p] is input k of point p, outputs[j][p] receives output j, for p < count.
  // Throws std::invalid_argument if the spans do not match the tape.
  void eval(const Tape& tape, std::span<const double* const> inputs, std::size_t count,
            std::span<double* const> outputs) {
    eval(tape, inputs, count, outputs, 1, 1);
  }
  // The same over strided arrays: input k of point p is inputs[k][p * input_stride] and output
  // j goes to outputs[j][p * output_stride], so a row-major (count, n) array is read in place
  // (inputs[k] = data + k, input_stride = n). Strides must be >= 1. Bitwise the same values.
  void eval(const Tape& tape, std::span<const double* const> inputs, std::size_t count,
            std::span<double* const> outputs, std::size_t input_stride, std::size_t output_stride);

 private:
  void run_chunk(const Tape& tape, std::span<const double* const> inputs, std::size_t offset, std::size_t n,
                 std::span<double* const> outputs, std::size_t input_stride, std::size_t output_stride);
  std::vector<double> regs_;  // num_registers x kChunk
  std::vector<double> slots_, args_, call_out_;
};

}  // namespace genmod
