// Time-varying curve (thesis Fig 3.21, research/snyder.md 7.23): a damped sinusoid with a
// time-varying phase, truncated at arclength `arclength` (the thesis's lambda):
//   c(u, t) = (u, amplitude u^2 sin(2 pi (t - phase_lag u))),   u in [0, u_t],
//   lambda = integral_0^{u_t} |dc/du| du   (u_t by the integrate and inverse operators).
// [ERRATUM] As extracted the ordinate is sin(2 pi (t - 0.1 u)) / (2 u^2), singular at u = 0
// where the range starts; we use the finite form amplitude u^2 sin(...) (amplitude 0.5 is the
// printed 1/2): the root stays fixed and the swing grows toward the tip, like a flapping
// wing's spar. The model is the space-time surface
//   S(s, v) = (c(s u_t(t), t), t),   t = interp(v, -0.1, 0.9),
// over the upstroke t in [-0.1, 0.4] and the downstroke [0.4, 0.9]; every time slice
// v = const is the curve at time t, of arclength lambda. u_t depends on t only, so the
// lattice evaluator computes it once per v sample (subfunction tables).
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/integrate.hpp"
#include "genmod/operators/vector.hpp"
#include "genmod/solvers/inverse_operator.hpp"
#include "model_definitions.hpp"

#include <numbers>

namespace genmod::models {

namespace {

// c(u, t) for arbitrary functions u and t.
Fn curve_at(const ParameterValues& p, const Fn& u, const Fn& t) {
  const double amplitude = detail::param(p, "amplitude");
  const double lag = detail::param(p, "phase_lag");
  return cat({u, amplitude * square(u) * sin(2.0 * std::numbers::pi * (t - lag * u))});
}

// u_t(t) for a function t of coordinates other than x(2) and x(3) (the integration and
// inversion variables). |dc/du| >= 1, so u_t <= lambda: the root is bracketed in
// [0, 1.5 lambda].
Fn time_varying_curve_end_at(const ParameterValues& p, const Fn& t) {
  const double lambda = detail::require_positive(p, "arclength");
  const Fn speed = length(derivative(curve_at(p, x(2), t), 2));
  const Fn arc = integrate(speed, 0.0, x(3), 2);
  return inverse(arc, lambda, 3, Interval(0.0, 1.5 * lambda));
}

}  // namespace

Fn time_varying_curve_c(const ParameterValues& p) { return curve_at(p, x(0), x(1)); }
Fn time_varying_curve_end(const ParameterValues& p) { return time_varying_curve_end_at(p, x(1)); }

namespace detail {

Model time_varying_curve_model() {
  Model m;
  m.name = "time_varying_curve";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.21: a sinusoid with moving phase, truncated at fixed arclength, as a space-time surface (x, y, t)";
  m.parameters = {{"arclength", 1.0, "the thesis's lambda: arclength of every time slice of the curve"},
                  {"amplitude", 0.5, "a in c(u, t) = (u, a u^2 sin(2 pi (t - phase_lag u)))"},
                  {"phase_lag", 0.1, "phase delay per unit u (the thesis's 0.1): a wave travelling toward the tip"}};
  m.build = [](const ParameterValues& p) {
    const Fn t = interp(x(1), -0.1, 0.9);
    const Fn end = time_varying_curve_end_at(p, t);
    return cat({curve_at(p, x(0) * end, t), t});
  };
  return m;
}

}  // namespace detail
}  // namespace genmod::models
