// Spoon (thesis Fig 3.14, research/snyder.md 7.15): a circular-arc cross section thickened by
// a closed offset (offset, end cap, offset back, end cap), exactly the thesis's code:
//   shape = m_crv("shape.crv", v); bowl = m_crv("bowl.crv", v);
//   bend = m_crv("bend.crv", v);   thick = m_crv("thick.crv", v);
//   _arc = m_arc_2pt_height((-shape[1], 0), (shape[1], 0), bowl[1], u);
//   arc = m_closed_offset(_arc, thick[1]);
//   spoon = (shape[0], arc[0], arc[1] + bend[1]);
// The section at v lies in the plane x = shape_x(v): an arc of half-width shape_y(v) and
// sagitta bowl_y(v) (in the (y, z) plane), thickened to 2 thick_y(v) and lifted by bend_y(v).
// The curves are models/curves/spoon_{shape,bowl,bend,thick}.crv; two parameters scale the
// bowl depth and the thickness.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/offset.hpp"
#include "model_definitions.hpp"

#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {

struct SpoonCurves {
  Fn shape, bowl, bend, thick;
};

SpoonCurves spoon_curves(const ParameterValues& p) {
  const double bowl_scale = detail::param(p, "bowl_scale");
  if (!(bowl_scale >= 0.0 && bowl_scale <= 2.0))
    throw std::invalid_argument("parameter 'bowl_scale' must be in [0, 2], got " + std::to_string(bowl_scale));
  const double thickness_scale = detail::require_positive(p, "thickness_scale");
  if (!(thickness_scale <= 3.0))
    throw std::invalid_argument("parameter 'thickness_scale' must be in (0, 3], got " + std::to_string(thickness_scale));
  const Fn v = x(1);
  return {gallery_curve("spoon_shape")(v), gallery_curve("spoon_bowl")(v)[1] * bowl_scale,
          gallery_curve("spoon_bend")(v)[1], gallery_curve("spoon_thick")(v)[1] * thickness_scale};
}

// The thesis's _arc: the (y, z) arc of the section, a function of (u, v).
Fn section_arc(const SpoonCurves& c) {
  return arc_2pt_height(cat({-c.shape[1], Fn(0.0)}), cat({c.shape[1], Fn(0.0)}), c.bowl, x(0));
}

}  // namespace

Fn spoon_mid_surface(const ParameterValues& p) {
  const SpoonCurves c = spoon_curves(p);
  const Fn arc = section_arc(c);
  return cat({c.shape[0], arc[0], arc[1] + c.bend});
}

Fn spoon_half_thickness(const ParameterValues& p) { return spoon_curves(p).thick; }

namespace detail {

Model spoon_model() {
  Model m;
  m.name = "spoon";
  m.description = "thesis Fig 3.14: a circular-arc cross section thickened by a closed offset, swept along the spoon";
  m.parameters = {{"bowl_scale", 1.0, "multiplies the bowl depth (the arc's sagitta), in [0, 2]; 0 = flat"},
                  {"thickness_scale", 1.0, "multiplies the thickness of the spoon, in (0, 3]"}};
  m.build = [](const ParameterValues& p) {
    const SpoonCurves c = spoon_curves(p);
    const Fn arc = closed_offset(section_arc(c), c.thick, 0);
    return cat({c.shape[0], arc[0], arc[1] + c.bend});
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
