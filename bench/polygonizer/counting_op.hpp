// An identity custom operator that counts how often it is evaluated at a point and over a
// box: wrapping f as counted(f) counts the evaluations of f that a mesher makes through its
// value tape, whatever evaluator it uses (its gradient tapes do not pass through the operator:
// the derivative of the identity is 1). Used outside the timed runs only (a custom clause costs
// more than the opcodes it wraps).
#pragma once

#include "genmod/kernel/custom_op.hpp"

#include <atomic>
#include <cstddef>
#include <memory>

namespace genmod::bench {

class CountingOp final : public CustomOp {
 public:
  std::string name() const override { return "count"; }
  int num_args() const override { return 1; }
  int num_outputs() const override { return 1; }
  void eval(std::span<const double> args, std::span<double> out) const override {
    points.fetch_add(1, std::memory_order_relaxed);
    out[0] = args[0];
  }
  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    boxes.fetch_add(1, std::memory_order_relaxed);
    out[0] = args[0];
    (void)err;  // already holds the argument's error bits
  }
  Fn derivative(std::span<const Fn> args, int k) const override {
    (void)args;
    (void)k;
    return 1.0;
  }
  bool continuous() const override { return true; }

  mutable std::atomic<std::size_t> points{0}, boxes{0};
};

// f passed through a fresh counter.
inline Fn counted(const Fn& f, const std::shared_ptr<const CountingOp>& op) { return apply_custom(op, {f}); }

}  // namespace genmod::bench
