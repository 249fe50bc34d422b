// Wing (thesis Fig 3.22, research/snyder.md 7.23): a wire product with the time-varying curve
// (time_varying_curve.cpp) as the wire and an ellipse as the cross section, one axis scaled
// and translated to shape the wing; the time is the model parameter `time`:
//   wire(s)     = c(s u_T, T),   s = x(1) in [0, 1]   (the spar: root at s = 0, tip at 1)
//   cross(u, s) = (thickness chord(s) / 2 cos 2 pi u,  chord(s) (sin(2 pi u) / 2 - 1/4))
//   wing        = m_wire(cross, wire)
// chord(s) = root_chord * wing_chord.crv(s)[1] (curves/wing_chord.crv, tapering to the tip).
// The cross section's first axis (thickness) goes to the spar's in-plane normal (the flapping
// direction), its second (the chord, from +c/4 at the leading edge to -3c/4 at the trailing
// edge, so the spar sits at quarter chord) to world z. u_T depends only on the time, so it is
// computed once at build time with the integrate + inverse operators of the time-varying
// curve and enters the wire as a constant.
#include "genmod/models/gallery.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/operators/sweep.hpp"
#include "model_definitions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::models {

Fn wing_wire(const ParameterValues& p) {
  const double time = detail::param(p, "time");
  const std::vector<double> at_time{0.0, time};  // u_t is a function of t = x(1)
  const double end = evaluate(time_varying_curve_end(p), at_time)[0];
  if (!std::isfinite(end)) throw std::invalid_argument("wing: no arclength parameter for time " + std::to_string(time));
  const double amplitude = detail::param(p, "amplitude");
  const double lag = detail::param(p, "phase_lag");
  const Fn u = x(1) * end;
  return cat({u, amplitude * square(u) * sin(2.0 * std::numbers::pi * (time - lag * u))});
}

Fn wing_cross(const ParameterValues& p) {
  const double root = detail::require_positive(p, "root_chord");
  const double thickness = detail::require_positive(p, "thickness");
  const Fn chord = gallery_curve("wing_chord")(x(1))[1] * root;
  const Fn a = x(0) * (2.0 * std::numbers::pi);
  return cat({chord * (thickness / 2.0) * cos(a), chord * (0.5 * sin(a) - 0.25)});
}

namespace detail {

Model wing_model() {
  Model m;
  m.name = "wing";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.22: wire product of a tapered ellipse along the time-varying curve at a given time";
  m.parameters = {{"time", 0.15, "time t of the flap (period 1; the figure shows t in [-0.1, 0.9], upstroke to 0.4)"},
                  {"arclength", 1.0, "span: arclength of the spar (the time-varying curve's lambda)"},
                  {"amplitude", 0.5, "flap amplitude a of the spar c(u, t) = (u, a u^2 sin(2 pi (t - phase_lag u)))"},
                  {"phase_lag", 0.1, "phase delay per unit u of the spar's wave"},
                  {"root_chord", 0.35, "chord of the wing at the root"},
                  {"thickness", 0.12, "thickness as a fraction of the chord"}};
  m.build = [](const ParameterValues& p) { return wire_product(wing_cross(p), wing_wire(p), 1); };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
