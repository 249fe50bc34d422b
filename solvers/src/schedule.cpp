#include "genmod/solvers/schedule.hpp"

#include "genmod/operators/vector.hpp"
#include "genmod/solvers/inverse_operator.hpp"

#include <stdexcept>
#include <string>

namespace genmod {
namespace {

[[noreturn]] void fail(const char* op, const std::string& what) {
  throw std::invalid_argument(std::string("genmod: ") + op + ": " + what);
}

void require_parm(const char* op, const Fn& curve, const char* name, int parm) {
  if (parm < 0 || parm >= kMaxInputs)
    fail(op, "parameter " + std::to_string(parm) + " is outside [0, " + std::to_string(kMaxInputs) + ")");
  if (!(curve.input_mask() >> parm & 1u))
    fail(op, std::string(name) + " does not depend on x(" + std::to_string(parm) + ")");
}

// c[component] at the parameter where it equals `value`; the shared core of the three schedules.
Fn matched_parameter(const char* op, const Fn& c, int component, const Fn& value, int parm, Interval domain) {
  require_parm(op, c[static_cast<std::size_t>(component)], "the inverted component", parm);
  try {
    return inverse(c[static_cast<std::size_t>(component)], value, parm, domain);
  } catch (const std::invalid_argument& e) {
    fail(op, e.what());  // keep the operator's name in front of inverse()'s own message
  }
}

}  // namespace

Fn resample_by_curve(const Fn& c1, const Fn& c2, int parm, int component, Interval domain) {
  constexpr const char* op = "resample_by_curve";
  if (component < 0 || static_cast<std::size_t>(component) >= c1.dim() ||
      static_cast<std::size_t>(component) >= c2.dim())
    fail(op, "component " + std::to_string(component) + " is missing (c1 has dimension " + std::to_string(c1.dim()) +
                 ", c2 " + std::to_string(c2.dim()) + ")");
  require_parm(op, c1, "c1", parm);
  const Fn t = matched_parameter(op, c1, component, c2[static_cast<std::size_t>(component)], parm, domain);
  return compose(c1, parm, t);
}

Fn match_schedule(const Fn& curve, const Fn& x1, int parm, Interval domain) {
  constexpr const char* op = "match_schedule";
  if (curve.dim() < 2) fail(op, "the curve has dimension " + std::to_string(curve.dim()) + ", expected >= 2");
  if (x1.dim() != 1) fail(op, "x1 has dimension " + std::to_string(x1.dim()) + ", expected 1");
  require_parm(op, curve, "the curve", parm);
  const Fn t = matched_parameter(op, curve, 0, x1, parm, domain);
  return compose(curve[1], parm, t);
}

Fn warp_by_length(const Fn& m, const Fn& w, int parm, Interval domain) {
  constexpr const char* op = "warp_by_length";
  if (w.dim() < 2) fail(op, "the warp curve has dimension " + std::to_string(w.dim()) + ", expected >= 2");
  require_parm(op, w, "the warp curve", parm);
  const Fn t = matched_parameter(op, w, 0, length(m), parm, domain);
  return cat({m, compose(w[1], parm, t)});
}

}  // namespace genmod
