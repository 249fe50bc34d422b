// Key (thesis Fig 3.15, research/snyder.md 7.16): a key of a computer keyboard (a keycap). A
// rounded-square cross section is placed between profile curves in the yz and xz planes and
// warped parabolically in x, the warp growing from none at the bottom (v = 0) to the most at
// the top (v = 1), which dishes the top of the key. The consistent reconstruction of the
// thesis's code (erratum: it mixes two versions; we keep the curves yz_left, yz_right, xz):
//   cross_sides = (cross + (1, 1)) * 0.5;                        // [-1, 1]^2 -> [0, 1]^2
//   _sides = (interp(cross_sides[0], -xz[0], xz[0]),             // x: left to right
//             interp(cross_sides[1], yz_l, yz_r));               // (y, z): front to back
//   sides = m_warp_z_by_x(_sides, warp_scale * v, warp_offset * v);   // z + a x^2 + b
// The curves are built here from the parameters (key_cross, key_yz_left, key_yz_right,
// key_xz): the cross section a rounded square in [-1, 1]^2; the yz curves the front (left)
// and back (right) outline of the key, from the bottom edge (y = -+bottom_width/2, z = 0) up a
// slightly convex side to the top edge (y = -+top_width/2, z = height -+ tilt/2: the top
// slopes up toward the back, as on a sculpted keyboard row); xz the same outline seen from
// the front (x = bottom_width/2 ... top_width/2). So the footprint is a bottom_width square
// and the top a top_width square. With the thesis's warp (0.2 v, -0.05 v) and top_width 1 the
// top's left and right edges (x = +-1/2) keep their height and its middle sinks by 0.05.
// The sides are open at the bottom and the top; the model's extra patches close them: a flat
// bottom face and the top face, the planar cap of the unwarped top edge with the same warp,
// z += warp_scale x^2 + warp_offset (a cylindrical dish), both Coons patches on the sides'
// edges (coons_face.hpp).
#include "genmod/models/gallery.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/warp.hpp"

#include "coons_face.hpp"
#include "model_definitions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::models {

namespace {

double corner_radius_of(const ParameterValues& p) {
  const double r = detail::require_positive(p, "corner_radius");
  if (!(r < 1.0)) throw std::invalid_argument("parameter 'corner_radius' must be in (0, 1), got " + std::to_string(r));
  return r;
}

// The spans of the rounded square from (1, 0) counterclockwise: half side, then corner, side,
// corner, side, corner, side, corner, half side. Lengths in the [-1, 1]^2 square.
struct SquareSpans {
  double half_side, arc, side, perimeter;
};
SquareSpans square_spans(double r) {
  const double arc = r * std::numbers::pi / 2.0;
  return {1.0 - r, arc, 2.0 * (1.0 - r), 8.0 * (1.0 - r) + 4.0 * arc};
}

// The parameters of the middles of the four corner arcs (the Coons caps' corners).
std::array<double, 4> corner_parameters(double r) {
  const SquareSpans s = square_spans(r);
  std::array<double, 4> k{};
  for (int i = 0; i < 4; ++i) k[i] = (s.half_side + s.arc / 2.0 + i * (s.arc + s.side)) / s.perimeter;
  return k;
}

// A side outline: the quadratic Bezier from (bottom, 0) to (top, z_top) through the control
// point (bottom + (top - bottom) / 4, 0.55 z_top), a little outside the straight line (whose
// point at that height is bottom + 0.55 (top - bottom)), so the side is slightly convex. z
// grows with v at the rate z_top (1.1 - 0.2 v) >= 0.9 z_top.
Curve side_outline(double bottom, double top, double z_top) {
  return Curve::bezier({{bottom, 0.0}, {bottom + 0.25 * (top - bottom), 0.55 * z_top}, {top, z_top}});
}

struct KeyShape {
  double bottom_width, top_width, height, tilt, warp_scale, warp_offset;
};

KeyShape key_shape(const ParameterValues& p) {
  KeyShape k{detail::require_positive(p, "bottom_width"), detail::require_positive(p, "top_width"),
             detail::require_positive(p, "height"),       detail::param(p, "tilt"),
             detail::param(p, "warp_scale"),              detail::param(p, "warp_offset")};
  if (!(std::abs(k.tilt) < k.height))
    throw std::invalid_argument("parameter 'tilt' must be in (-height, height) (both top edges above the bottom), got " +
                                std::to_string(k.tilt) + " with height " + std::to_string(k.height));
  return k;
}

// The sides before the warp, a function of (u, v).
Fn unwarped(const ParameterValues& p) {
  const Fn u = x(0), v = x(1);
  const Fn cross = key_cross(p)(u);
  const Fn yz_l = key_yz_left(p)(v), yz_r = key_yz_right(p)(v), xz = key_xz(p)(v);
  const Fn cross_sides = (cross + 1.0) * 0.5;
  const Fn yz = interp(cross_sides[1], yz_l, yz_r);
  return cat({interp(cross_sides[0], -xz[0], xz[0]), yz[0], yz[1]});
}

// The sides must rise from the bottom to the top, dz/dv > 0, or the warp folds them over:
// z_v = (the profiles' rise, >= 0.9 (height - |tilt|/2)) + warp_scale (x^2 + 2 v x x_v) +
// warp_offset, where x x_v < 0 as the key narrows, so a strong warp on a strongly tapered
// key folds it. Checked on a 129 x 65 sample grid of (u, v) (z_v is smooth).
void check_sides_rise(const Fn& sides) {
  const Tape rise(derivative(sides, 1)[2], std::vector<int>{0, 1});
  PointEvaluator ev;
  double lowest = INFINITY, at_u = 0.0, at_v = 0.0;
  for (int j = 0; j <= 64; ++j)
    for (int i = 0; i <= 128; ++i) {
      const double u = i / 128.0, v = j / 64.0, z_v = ev.eval(rise, {u, v})[0];
      if (!(z_v >= lowest)) lowest = z_v, at_u = u, at_v = v;
    }
  if (!(lowest > 0.0))
    throw std::invalid_argument("parameters 'warp_scale' and 'warp_offset' fold the key's sides over (with these widths, "
                                "height and tilt): the sides must rise from bottom to top, but dz/dv = " +
                                std::to_string(lowest) + " at (u, v) = (" + std::to_string(at_u) + ", " +
                                std::to_string(at_v) + ")");
}

Fn warped_sides(const ParameterValues& p) {
  const KeyShape k = key_shape(p);
  const Fn v = x(1);
  const Fn sides = warp_z_by_x(unwarped(p), k.warp_scale * v, k.warp_offset * v);
  check_sides_rise(sides);
  return sides;
}

}  // namespace

Curve key_cross(const ParameterValues& p) {
  const double r = corner_radius_of(p);
  const SquareSpans s = square_spans(r);
  const double w = std::sqrt(0.5), a = 1.0 - r;
  // Degree-2 NURBS, one span per piece (line spans through their midpoint, arcs rational
  // with the middle weight cos 45 deg), double knots at the joints, knot spans in proportion
  // to the pieces' lengths.
  const Curve::Points points{{1, 0},   {1, a / 2},  {1, a},   {1, 1},   {a, 1},   {0, 1},   {-a, 1},
                             {-1, 1},  {-1, a},     {-1, 0},  {-1, -a}, {-1, -1}, {-a, -1}, {0, -1},
                             {a, -1},  {1, -1},     {1, -a},  {1, -a / 2}, {1, 0}};
  std::vector<double> weights(points.size(), 1.0);
  for (std::size_t i : {3u, 7u, 11u, 15u}) weights[i] = w;
  const double lengths[9] = {s.half_side, s.arc, s.side, s.arc, s.side, s.arc, s.side, s.arc, s.half_side};
  std::vector<double> knots{0.0, 0.0, 0.0};
  double at = 0.0;
  for (int i = 0; i < 8; ++i) {
    at += lengths[i] / s.perimeter;
    knots.push_back(at);
    knots.push_back(at);
  }
  knots.insert(knots.end(), {1.0, 1.0, 1.0});
  return Curve::nurbs(points, weights, 2, knots);
}

Curve key_yz_left(const ParameterValues& p) {
  const KeyShape k = key_shape(p);
  return side_outline(-k.bottom_width / 2.0, -k.top_width / 2.0, k.height - k.tilt / 2.0);
}

Curve key_yz_right(const ParameterValues& p) {
  const KeyShape k = key_shape(p);
  return side_outline(k.bottom_width / 2.0, k.top_width / 2.0, k.height + k.tilt / 2.0);
}

Curve key_xz(const ParameterValues& p) {
  const KeyShape k = key_shape(p);
  return side_outline(k.bottom_width / 2.0, k.top_width / 2.0, k.height);
}

Fn key_unwarped(const ParameterValues& p) { return unwarped(p); }

std::vector<ModelPatch> key_caps(const ParameterValues& p) {
  const KeyShape k = key_shape(p);
  const std::array<double, 4> corners = corner_parameters(corner_radius_of(p));
  const Fn sides = unwarped(p);
  // The top: the flat cap of the unwarped top edge, then warped like the sides at v = 1, so
  // its edge is the sides' top edge and its inside is the parabolic dish z += a x^2 + b.
  const Fn top = warp_z_by_x(detail::coons_face(compose(sides, 1, Fn(1.0)), corners), Fn(k.warp_scale),
                             Fn(k.warp_offset));
  const Fn bottom = detail::coons_face_flipped(compose(sides, 1, Fn(0.0)), corners);
  return {ModelPatch{top}, ModelPatch{bottom}};
}

namespace detail {

Model key_model() {
  Model m;
  m.name = "key";
  m.description =
      "thesis Fig 3.15: a keyboard key, a rounded-square section between profile curves, its top dished by the warp z += a x^2 + b";
  m.parameters = {
      {"bottom_width", 1.3, "side of the key's square footprint (x and y in [-bottom_width/2, bottom_width/2] at z = 0)"},
      {"top_width", 1.0, "side of the square top (x and y in [-top_width/2, top_width/2])"},
      {"height", 0.7, "height of the top's middle before the warp (z of the top edge at y = 0)"},
      {"tilt", 0.1, "the top's front edge is at height - tilt/2, its back edge at height + tilt/2; |tilt| < height"},
      {"corner_radius", 0.3, "corner radius of the rounded-square cross section, as a fraction of the half width, in (0, 1)"},
      {"warp_scale", 0.2, "a = warp_scale v: the warp's curvature, 0 at the bottom (v = 0); > 0 dishes the top"},
      {"warp_offset", -0.05,
       "b = warp_offset v: the warp's shift in z, 0 at the bottom (v = 0); a warp that folds the sides (dz/dv <= 0) is "
       "rejected"}};
  m.build = warped_sides;
  m.periodic_u = true;
  m.extra_patches = key_caps;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
