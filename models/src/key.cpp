// Key (thesis Fig 3.15, research/snyder.md 7.16): a rounded-square cross section stretched
// between two edge curves and deformed by a parabolic warp, the consistent reconstruction of
// the thesis's code (erratum: it mixes two versions; we keep the curves yz_left, yz_right, xz):
//   cross_sides = (cross + (1, 1)) * 0.5;                        // [-1, 1]^2 -> [0, 1]^2
//   _sides = (interp(cross_sides[0], -xz[0], xz[0]),             // x: the key's thickness
//             interp(cross_sides[1], yz_l, yz_r));               // (y, z): edge to edge
//   sides = m_warp_z_by_x(_sides, warp_scale * v, warp_offset * v);   // z + a x^2 + b
// with warp_scale = 0.2 and warp_offset = -0.05: no warp at the tip (v = 0), the most at the
// top of the bow (v = 1). The curves are models/curves/key_{cross,yz_left,yz_right,xz}.crv:
// a blade with four teeth on its right edge, a shoulder and a round bow.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/warp.hpp"

namespace genmod::models {

Fn key_unwarped(const ParameterValues&) {
  const Fn u = x(0), v = x(1);
  const Fn cross = gallery_curve("key_cross")(u);
  const Fn yz_l = gallery_curve("key_yz_left")(v), yz_r = gallery_curve("key_yz_right")(v);
  const Fn xz = gallery_curve("key_xz")(v);
  const Fn cross_sides = (cross + 1.0) * 0.5;
  const Fn yz = interp(cross_sides[1], yz_l, yz_r);
  return cat({interp(cross_sides[0], -xz[0], xz[0]), yz[0], yz[1]});
}

namespace detail {

Model key_model() {
  Model m;
  m.name = "key";
  m.description = "thesis Fig 3.15: a rounded-square section stretched between the key's edge curves, warped z += a x^2 + b";
  m.parameters = {{"warp_scale", 0.2, "a = warp_scale v: the parabolic warp's curvature grows from 0 at the tip (v = 0)"},
                  {"warp_offset", -0.05, "b = warp_offset v: the warp's shift in z, 0 at the tip (v = 0)"}};
  m.build = [](const ParameterValues& p) {
    const Fn v = x(1);
    return warp_z_by_x(key_unwarped(p), param(p, "warp_scale") * v, param(p, "warp_offset") * v);
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
