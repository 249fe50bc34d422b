// Extension interface: operators that are not scalar opcodes (curves, tables, integrals,
// nested solves, ...). A custom operator maps k scalar arguments to m scalar outputs and
// provides GENMOD's three methods. Tapes call it as an opaque clause, so a later layer (or a
// user) adds operators without touching the kernel.
//
//   auto op = std::make_shared<MyCurve>(...);
//   Fn c = apply_custom(op, {x(0)});   // an Fn with op->num_outputs() components
//
// (Not named `apply`: with a std::shared_ptr argument, argument-dependent lookup would also
// find std::apply.)
//
// Thread safety: one operator object may be called from several threads at once, so the
// methods must be const-correct and keep no mutable state (or guard it).
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"

#include <memory>
#include <span>
#include <string>

namespace genmod {

class CustomOp {
 public:
  virtual ~CustomOp() = default;
  virtual std::string name() const = 0;
  virtual int num_args() const = 0;
  virtual int num_outputs() const = 0;
  // Point evaluation; an output that is an error is NaN.
  virtual void eval(std::span<const double> args, std::span<double> out) const = 0;
  // Inclusion function: each out[j] must contain output j at every point of the box `args`.
  // Called in the caller's (default) rounding mode; use protected Interval arithmetic.
  // `err[j]` receives ErrorBits for output j (already or-ed with the arguments' errors).
  virtual void inclusion(std::span<const Interval> args, std::span<Interval> out,
                         std::span<std::uint8_t> err) const = 0;
  // Partial derivatives of all outputs with respect to argument k, as an Fn of dimension
  // num_outputs() built from the argument functions `args` (so it composes symbolically).
  virtual Fn derivative(std::span<const Fn> args, int k) const = 0;
  // True if the outputs are continuous in the arguments wherever they are defined (no
  // jumps), so that derivative-based inclusion forms (mean value, monotonicity) may be used
  // through the operator. The default is the safe answer.
  virtual bool continuous() const { return false; }
  // The inclusion function and continuity on the box in one call: fills out / err as
  // inclusion() does and returns true if the outputs are continuous on the box `args` (at its
  // points where no error occurs). The interval evaluator calls this one, so that an operator
  // continuous only under a condition its inclusion proves box by box (a root that is unique,
  // an integrand that is continuous) can say so at no extra cost. It must return false
  // wherever an output may jump: interval Newton and Krawczyk trust it. The default is
  // inclusion(), then continuous().
  virtual bool inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                                    std::span<std::uint8_t> err) const {
    inclusion(args, out, err);
    return continuous();
  }
};

// Applies `op` to scalar argument functions; the result has op->num_outputs() components.
Fn apply_custom(const std::shared_ptr<const CustomOp>& op, std::span<const Fn> args);
Fn apply_custom(const std::shared_ptr<const CustomOp>& op, std::initializer_list<Fn> args);

}  // namespace genmod
