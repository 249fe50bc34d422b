// Gear (thesis Fig 3.8, research/snyder.md 7.10): linear interpolation of cross sections, a
// gear curve toward its radial projection onto the hole circle:
//   cross1 = m_crv("cross.crv", u); cross2 = m_normalize(cross1)*0.25;
//   interp = m_crv("interp.crv", v);
//   gear = @(m_interp(interp[1], cross1, cross2), interp[0]);
// cross2 is cross1 radially projected, so both are matched by polar angle (no mismatch,
// snyder.md 7.12). The gear curve depends on integer / numeric parameters and is built in
// code: a closed C2 cubic B-spline through samples of r(theta) = outer_radius - tooth_depth +
// tooth_depth (1 + tanh(4 sin(teeth theta)) / tanh(4)) / 2 (square-ish teeth). The schedule
// (curves/gear_interp.crv) is a closed polyline: bottom face, hole wall, top face, outer wall,
// so the gear is a closed surface (periodic in u and v).
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/sweep.hpp"
#include "genmod/operators/vector.hpp"
#include "model_definitions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {
constexpr int kSamplesPerTooth = 12;
}

Fn gear_cross(const ParameterValues& p) {
  const double teeth = detail::param(p, "teeth");
  if (!(teeth >= 3.0 && teeth <= 64.0) || teeth != std::floor(teeth))
    throw std::invalid_argument("parameter 'teeth' must be an integer in [3, 64], got " + std::to_string(teeth));
  const double outer = detail::require_positive(p, "outer_radius");
  const double depth = detail::require_positive(p, "tooth_depth");
  const double hole = detail::require_positive(p, "hole_radius");
  if (!(depth < outer - hole))
    throw std::invalid_argument("parameter 'tooth_depth' must be < outer_radius - hole_radius, got " +
                                std::to_string(depth));
  const int n = static_cast<int>(teeth) * kSamplesPerTooth;
  Curve::Points points;
  for (int i = 0; i < n + 3; ++i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i % n) / n;
    const double r = outer - depth + depth * 0.5 * (1.0 + std::tanh(4.0 * std::sin(teeth * a)) / std::tanh(4.0));
    points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return Curve::uniform_bspline(points, 3, /*clamped=*/false)(x(0));
}

namespace detail {

Model gear_model() {
  Model m;
  m.name = "gear";
  m.description = "thesis Fig 3.8: a gear curve linearly interpolated toward its radial projection on the hole circle";
  m.parameters = {{"teeth", 12.0, "number of teeth (integer, 3..64)"},
                  {"outer_radius", 0.8, "radius at the tips of the teeth"},
                  {"tooth_depth", 0.1, "radial depth of the teeth (< outer_radius - hole_radius)"},
                  {"hole_radius", 0.25, "radius of the round hole (the thesis's 0.25)"},
                  {"thickness", 0.3, "height of the gear along z"}};
  m.build = [](const ParameterValues& p) {
    const double hole = require_positive(p, "hole_radius");
    const double thickness = require_positive(p, "thickness");
    const Fn cross1 = gear_cross(p);
    const Fn cross2 = normalize(cross1) * hole;
    const Fn schedule = gallery_curve("gear_interp")(x(1));
    return cat({interp_cross_sections(schedule[1], cross1, cross2), schedule[0] * thickness});
  };
  m.periodic_u = true;
  m.periodic_v = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
