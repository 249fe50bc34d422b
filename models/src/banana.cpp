// Banana (thesis Fig 3.6, research/snyder.md 7.8): a quasi-linear sweep, exactly as the
// thesis writes it:
//   cross = m_crv("bancross.crv", u); scale = m_crv("banscale.crv", v)[1];
//   banana = m_transform3d(@(cross, 0),
//       m_roty(m_interp(v, 0.0, -0.4*pi)) * m_transz(m_interp(v, -1, 1)) *
//       m_scalex(scale) * m_scaley(scale));
// The factor written last applies first: scale x and y by banscale(v), lift to z in [-1, 1],
// bend about y by 0 ... -0.4 pi. Substitute curves (curves/banana_cross.crv,
// banana_scale.crv): a rounded pentagon and a bump schedule, 0 at both tips.
//
// Where the surface stops being embedded (checked when it is built). The section at v lies
// in the plane through R(theta) (0, 0, 2v - 1) with normal R(theta) z, theta = -bend v, and a
// point (s cx, s cy) of it (s = thickness banscale(v)) moves along that normal at the rate
// 2 - bend s cx per unit v: the rotation about the origin sweeps the side cx bend > 0 back.
// Where the rate reaches 0 neighbouring sections cross (the inside of the bend folds), so
//   |bend| thickness max(banscale) max(-+cx) < 2           (local fold)
// with -cx for bend > 0 and cx for bend < 0 (the pentagon is symmetric: the same). Globally
// the two tips, at (0, 0, -1) and R(-bend) (0, 0, 1), meet at |bend| = pi and the banana
// passes through itself beyond, so |bend| < pi. Sampling agrees: lattice meshes (v in
// [0.001, 0.999], 256^2) have no self-intersecting triangles up to bend 3.145 at thickness 1
// (tips cut), none at bend thickness 6.5 and many from 6.9 on, the limit being 6.70
// (self_intersection_limits_test.cpp checks just inside the limits).
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/transform.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "model_definitions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {

// max over t in [0, 1] of sign * component k of the curve, by dense sampling (the curves are
// smooth; 4096 samples put the maximum within 1e-6 relative).
double curve_max(const Curve& c, std::size_t k, double sign) {
  const Tape tape(c(x(0)), std::vector<int>{0});
  PointEvaluator ev;
  double best = -INFINITY;
  for (int i = 0; i <= 4096; ++i) best = std::max(best, sign * ev.eval(tape, {i / 4096.0})[k]);
  return best;
}

// 2 / (max(banscale) max(-+cx)): the largest |bend| thickness before the fold (about 6.70).
double fold_limit() {
  static const double limit = [] {
    const Curve cross = gallery_curve("banana_cross");
    const double extent = std::max(curve_max(cross, 0, 1.0), curve_max(cross, 0, -1.0));
    return 2.0 / (curve_max(gallery_curve("banana_scale"), 1, 1.0) * extent);
  }();
  return limit;
}

}  // namespace

double banana_max_bend(double thickness) { return std::min(std::numbers::pi, fold_limit() / thickness); }

namespace detail {

Model banana_model() {
  Model m;
  m.name = "banana";
  m.description = "thesis Fig 3.6: quasi-linear sweep of a rounded pentagon: scaled by a bump schedule, lifted and bent about y";
  m.parameters = {{"bend", 0.4 * std::numbers::pi,
                   "bend angle in radians: the section at v is rotated by -bend v about y; |bend| < min(pi, 6.70 / thickness) "
                   "(beyond, the surface intersects itself)"},
                  {"thickness", 1.0, "multiplier of the banscale schedule (the largest section radius is about 0.3 thickness)"}};
  m.build = [](const ParameterValues& p) {
    const double bend = param(p, "bend");
    const double thickness = require_positive(p, "thickness");
    // Beyond this the surface intersects itself (see the top of this file).
    const double max_bend = banana_max_bend(thickness);
    if (!(std::abs(bend) < max_bend))
      throw std::invalid_argument(
          "parameter 'bend' must be in (-" + std::to_string(max_bend) + ", " + std::to_string(max_bend) +
          ") with thickness " + std::to_string(thickness) + " (|bend| < pi and |bend| thickness < " +
          std::to_string(fold_limit()) + "; beyond, the banana intersects itself), got " + std::to_string(bend));
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
