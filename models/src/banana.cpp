// Banana (thesis Fig 3.6, research/snyder.md 7.8): a quasi-linear sweep, exactly as the
// thesis writes it:
//   cross = m_crv("bancross.crv", u); scale = m_crv("banscale.crv", v)[1];
//   banana = m_transform3d(@(cross, 0),
//       m_roty(m_interp(v, 0.0, -0.4*pi)) * m_transz(m_interp(v, -1, 1)) *
//       m_scalex(scale) * m_scaley(scale));
// The factor written last applies first: scale x and y by banscale(v), lift to z in [-1, 1],
// bend about y by 0 ... -0.4 pi. Substitute curves (curves/banana_cross.crv,
// banana_scale.crv): a rounded pentagon and a bump schedule, 0 at both tips.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/transform.hpp"

#include <numbers>

namespace genmod::models {
namespace detail {

Model banana_model() {
  Model m;
  m.name = "banana";
  m.description = "thesis Fig 3.6: quasi-linear sweep of a rounded pentagon: scaled by a bump schedule, lifted and bent about y";
  m.parameters = {{"bend", 0.4 * std::numbers::pi, "bend angle in radians: the section at v is rotated by -bend v about y"},
                  {"thickness", 1.0, "multiplier of the banscale schedule (the largest section radius is about 0.3 thickness)"}};
  m.build = [](const ParameterValues& p) {
    const double bend = param(p, "bend");
    const double thickness = require_positive(p, "thickness");
    const Fn u = x(0), v = x(1);
    const Fn cross = gallery_curve("banana_cross")(u);
    const Fn s = gallery_curve("banana_scale")(v)[1] * thickness;
    return transform3d(cat({cross, Fn(0.0)}),
                       rotate_y(interp(v, 0.0, -bend)) * translate(0.0, 0.0, interp(v, -1.0, 1.0)) *
                           scale(s, 1.0, 1.0) * scale(1.0, s, 1.0));
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
