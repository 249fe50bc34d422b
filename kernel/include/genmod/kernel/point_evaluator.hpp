// Scalar point evaluation of a tape: one point per call.
//
// Example:
//   Fn f = cat({x(0) + x(1), sqrt(x(0) - x(1))});
//   Tape t(f);
//   PointEvaluator ev;
//   std::span<const double> y = ev.eval(t, {0.5, 0.25});   // y[j] = f_j(point); NaN = error
#pragma once

#include "genmod/kernel/tape.hpp"

#include <initializer_list>
#include <span>
#include <vector>

namespace genmod {

class PointEvaluator {
 public:
  // `point[k]` is the value of input k (x(tape.inputs()[k])). The result is valid until the
  // next call. Throws std::invalid_argument if the point has the wrong dimension.
  std::span<const double> eval(const Tape& tape, std::span<const double> point);
  std::span<const double> eval(const Tape& tape, std::initializer_list<double> point) {
    return eval(tape, std::span<const double>(point.begin(), point.size()));
  }

 private:
  std::vector<double> regs_, slots_, args_, out_;
};

// Evaluates f at a point given as values of x(0), x(1), ... (convenience, compiles a tape).
std::vector<double> evaluate(const Fn& f, std::span<const double> coordinates);
inline std::vector<double> evaluate(const Fn& f, std::initializer_list<double> coordinates) {
  return evaluate(f, std::span<const double>(coordinates.begin(), coordinates.size()));
}

}  // namespace genmod
