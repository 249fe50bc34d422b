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
// The thesis's spoon is a solid, but its sweep stops at two sections that do not shrink to a
// point (the handle's end at v = 0, the tip at v = 1), so the model closes them with two flat
// faces, its extra patches (spoon_caps): each fills its end section and has the section's
// four quarters as its four edges, point for point, so a mesher glues them to the sweep.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/offset.hpp"
#include "genmod/operators/vector.hpp"
#include "model_definitions.hpp"

#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

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

// The flat face inside the section at v = end, a function of (s, t) = (x(0), x(1)) whose
// edges are the section's quarters (operators/offset.hpp, closed_offset), with c, n, T the
// arc, its unit left normal and unit tangent at s and r the half thickness at v = end:
//   t = 0: c(s) - r n(s)                        (u = s / 4, the right side)
//   s = 1: c(1) - r cos(pi t) n + r sin(pi t) T  (u = (1 + t) / 4, the cap around c(1))
//   t = 1: c(s) + r n(s)                        (u = (3 - s) / 4, the left side)
//   s = 0: c(0) - r cos(pi t) n - r sin(pi t) T  (u = 1 - t / 4, the cap around c(0))
// Inside, F(s, t) = c + r (f n + g T) with g = -(1 - 2s) sin(pi t) and
//   f = -((1 - w) cos(pi t) + w (1 - 2t)),  w = 4 s (1 - s).
// f runs from -1 to 1 in t, as on the semicircles at s = 0 and 1; the blend w towards a
// straight line in between makes the t lines cross the long sides transversally (f_t = 2w at
// t = 0 and 1), where a bilinear Coons patch of these edges has t lines leaving them almost
// tangentially (a Jacobian of rank 1 on the sides of a straight section: slivers). F_s x F_t
// points along +x except at the four corners (the joints, where the edge is smooth and the
// face's Jacobian vanishes) while r is small against the arc's radius and length: the test
// checks the sign on a dense grid of both faces.
Fn section_face(const SpoonCurves& c, double end) {
  const Fn s = x(0), t = x(1);
  auto at_end = [&](const Fn& f) { return compose(f, 1, Fn(end)); };
  const Fn arc = at_end(section_arc(c)), r = at_end(c.thick);
  const Fn n = normalize(normal2d(arc, 0)), tangent = cat({n[1], -n[0]});
  const double pi = std::numbers::pi;
  const Fn w = 4.0 * s * (1.0 - s);
  const Fn f = -((1.0 - w) * cos(pi * t) + w * (1.0 - 2.0 * t));
  const Fn g = -(1.0 - 2.0 * s) * sin(pi * t);
  const Fn yz = arc + r * (f * n + g * tangent);
  return cat({at_end(c.shape[0]), yz[0], yz[1] + at_end(c.bend)});
}

}  // namespace

Fn spoon_mid_surface(const ParameterValues& p) {
  const SpoonCurves c = spoon_curves(p);
  const Fn arc = section_arc(c);
  return cat({c.shape[0], arc[0], arc[1] + c.bend});
}

Fn spoon_half_thickness(const ParameterValues& p) { return spoon_curves(p).thick; }

std::vector<ModelPatch> spoon_caps(const ParameterValues& p) {
  const SpoonCurves c = spoon_curves(p);
  // The spoon runs along +x (shape_x increases with v): the tip's face (v = 1) as built,
  // F_s x F_t along +x, and the handle's end (v = 0) with s and t swapped, along -x; both
  // point out of the spoon.
  const Fn handle_end = compose_all(section_face(c, 0.0), std::vector<int>{0, 1}, cat({x(1), x(0)}));
  return {ModelPatch{handle_end}, ModelPatch{section_face(c, 1.0)}};
}

namespace detail {

Model spoon_model() {
  Model m;
  m.name = "spoon";
  m.description =
      "thesis Fig 3.14: a circular-arc cross section thickened by a closed offset, swept along the spoon, its two end "
      "sections closed by flat faces (extra patches)";
  m.parameters = {{"bowl_scale", 1.0, "multiplies the bowl depth (the arc's sagitta), in [0, 2]; 0 = flat"},
                  {"thickness_scale", 1.0, "multiplies the thickness of the spoon, in (0, 3]"}};
  m.build = [](const ParameterValues& p) {
    const SpoonCurves c = spoon_curves(p);
    const Fn arc = closed_offset(section_arc(c), c.thick, 0);
    return cat({c.shape[0], arc[0], arc[1] + c.bend});
  };
  m.periodic_u = true;
  m.extra_patches = spoon_caps;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
