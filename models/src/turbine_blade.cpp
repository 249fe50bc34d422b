// Turbine blade (thesis Fig 3.7, research/snyder.md 7.9): a quasi-linear sweep (the printed
// code with its OCR erratum fixed):
//   blade = m_transform3d(@(cross, 0),
//       m_transz(m_interp(v, -1, 1)) * m_transx(-0.5) * m_rotz(pi*m_crv("bladerot.crv", v)[1]) *
//       m_transx(0.5) * m_scalex(m_crv("bladexscl.crv", v)[1]) * m_scaley(m_crv("bladeyscl.crv", v)[1]));
// Read right to left: scale x and y separately, translate x, rotate about z by
// pi bladerot(v), translate back, lift to z in [-1, 1]. [ERRATUM] As printed, transx(-0.5)
// rotz transx(+0.5) turns the section about the point x = -0.5, outside a chord on [0, 1];
// the described intent is a twist about mid-chord, so we write transx(+pivot) rotz
// transx(-pivot) with pivot = 0.5: the section turns about (pivot, 0). Substitute curves
// (curves/turbine_blade_*.crv): an airfoil on x in [0, 1], a twist 0 -> 0.25 half-turns,
// and x / y scales in [0.5, 1].
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/transform.hpp"
#include "model_definitions.hpp"

#include <numbers>

namespace genmod::models {
namespace detail {

Model turbine_blade_model() {
  Model m;
  m.name = "turbine_blade";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.7: quasi-linear sweep of an airfoil: scaled, twisted about a pivot, extruded along z";
  m.parameters = {{"twist", 1.0, "multiplier of the twist schedule: the section at v turns by twist pi bladerot(v) (1 = 45 degrees at the tip)"},
                  {"pivot", 0.5, "x of the twist axis: the scaled section turns about (pivot, 0)"},
                  {"span", 2.0, "length of the blade along z (from -span/2 to span/2)"}};
  m.build = [](const ParameterValues& p) {
    const double twist = param(p, "twist");
    const double pivot = param(p, "pivot");
    const double half = require_positive(p, "span") / 2.0;
    const Fn u = x(0), v = x(1);
    const Fn cross = gallery_curve("turbine_blade_cross")(u);
    const Fn rot = gallery_curve("turbine_blade_rotation")(v)[1];
    const Fn sx = gallery_curve("turbine_blade_xscale")(v)[1];
    const Fn sy = gallery_curve("turbine_blade_yscale")(v)[1];
    return transform3d(cat({cross, Fn(0.0)}),
                       translate(0.0, 0.0, interp(v, -half, half)) * translate(pivot, 0.0, 0.0) *
                           rotate_z(rot * (twist * std::numbers::pi)) * translate(-pivot, 0.0, 0.0) *
                           scale(sx, 1.0, 1.0) * scale(1.0, sy, 1.0));
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
