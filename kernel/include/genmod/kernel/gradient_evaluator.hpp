// Forward-mode derivative evaluation over a tape: values and the full Jacobian at a point.
// It is independent of the symbolic derivative (derivative() in fn.hpp), and the tests
// check the two against each other.
#pragma once

#include "genmod/kernel/tape.hpp"

#include <cstdint>
#include <span>
#include <memory>
#include <unordered_map>
#include <vector>

namespace genmod {

class GradientEvaluator {
 public:
  // Evaluates at `point` (one value per tape input).
  void eval(const Tape& tape, std::span<const double> point);
  // Output values of the last evaluation.
  std::span<const double> values() const noexcept { return values_; }
  // jacobian()[j * num_inputs + k] = d output_j / d input_k.
  std::span<const double> jacobian() const noexcept { return jacobian_; }

 private:
  std::vector<double> regs_;   // per register: value then num_inputs partials
  std::vector<double> slots_;  // per call slot: value then partials
  std::vector<double> scratch_;  // one register's partials
  std::vector<double> values_, jacobian_;
  struct CustomPartials {
    std::weak_ptr<const CustomOp> op;
    Tape tape;
  };
  std::unordered_map<const CustomOp*, CustomPartials> custom_partials_;  // per custom operator
};

}  // namespace genmod
