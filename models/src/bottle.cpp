// Bottle (thesis Fig 3.19, App. B.3, research/snyder.md 7.20): a parameterized cross section
// (the top half of a square turned 45 degrees, its three corners rounded by an amount that
// varies along the bottle) swept with matched parameter schedules, warped by a function of
// the distance from the axis, and four pieces concatenated in v: nozzle, shoulders, body,
// bottom. Curves: models/curves/bottle_{prof,face,top,nozzle}.crv.
//
// Departures from the printed code, each an erratum or a choice:
//  * the bottom is shifted by prof_y(1) - 1 like the body (printed: prof_y(1)), so the body
//    and the bottom meet;
//  * the thesis models half the bottle and adds its mirror image; here the cross section is
//    the half followed by its mirror image about the xz plane, a closed curve (u periodic).
//
// The tangent length's limit. The half section is five cubic Hermite pieces: two along the
// square's edges (from p2 to p3, chord q sqrt 2, both end tangents along the chord with length
// T = tangent_length) and three around its corners (chord 1 - q, end tangents at 45 degrees to
// it, so T / sqrt 2 along it), q = the rounding amount (bottle_face) at the height. Along its
// chord a piece moves at the rate 1.5 chord - 0.5 T_chord at its middle: the edge pieces stop
// and run back for T >= 3 sqrt 2 q, and each corner piece, symmetric about its chord's
// perpendicular bisector, crosses that line a second time (a loop: the section intersects
// itself) for T > 3 sqrt 2 (1 - q). So tangent_length < 3 sqrt 2 min over v of min(q, 1 - q)
// (about 1.6 for the authored face curve); sampling the sections agrees (bottle tests).
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/vector.hpp"
#include "genmod/solvers/schedule.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "model_definitions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::models {

namespace {

// GENMOD's m_herm: cubic Hermite pieces through points with tangents, concatenated in
// x(parm) and evaluated at `in`.
Fn hermite_chain(const std::vector<Fn>& points, const std::vector<Fn>& tangents, int parm, const Fn& in) {
  std::vector<Fn> pieces;
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    pieces.push_back(hermite_interp(x(parm), points[i], points[i + 1], tangents[i], tangents[i + 1]));
  return concat(parm, in, pieces);
}

// The rounding amount q(v) at the height of the body section (matched schedules, 7.21), a
// function of x(1).
Fn rounding_amount() {
  return resample_by_curve(gallery_curve("bottle_face")(x(1)), gallery_curve("bottle_prof")(x(1)), 1, 1)[0];
}

}  // namespace

double bottle_max_tangent_length() {
  // q sampled along the bottle (a smooth schedule: 2048 samples put its extremes within 1e-6).
  static const double limit = [] {
    const Tape tape(rounding_amount(), std::vector<int>{1});
    PointEvaluator ev;
    double closest = 1.0;  // min over v of min(q, 1 - q)
    for (int i = 0; i <= 2048; ++i) {
      const double q = ev.eval(tape, {i / 2048.0})[0];
      closest = std::min({closest, q, 1.0 - q});
    }
    return 3.0 * std::sqrt(2.0) * closest;
  }();
  return limit;
}

Fn bottle_half_cross(const ParameterValues& p) {
  const double tangent = detail::require_positive(p, "tangent_length");
  if (!(tangent < bottle_max_tangent_length()))
    throw std::invalid_argument("parameter 'tangent_length' must be in (0, " + std::to_string(bottle_max_tangent_length()) +
                                ") (beyond, the rounded corners loop and the bottle intersects itself), got " +
                                std::to_string(tangent));
  const double size = detail::require_positive(p, "scale");
  const Fn in = interp(x(0), Fn(0.1), Fn(0.9));

  const Fn left = cat({Fn(-1.0), Fn(0.0)}), top = cat({Fn(0.0), Fn(1.0)}), right = cat({Fn(1.0), Fn(0.0)});
  const Fn q = rounding_amount();
  const Fn p2 = interp(0.5 * (1.0 - q), left, top), p3 = interp(0.5 * (q + 1.0), left, top);
  const Fn p4 = interp(0.5 * (1.0 - q), top, right), p5 = interp(0.5 * (q + 1.0), top, right);
  const Fn p1 = cat({p2[0], -p2[1]}), p6 = cat({p5[0], -p5[1]});
  const Fn t2 = normalize(p3 - p2) * tangent, t4 = normalize(p5 - p4) * tangent;
  const Fn t1 = cat({-t2[0], t2[1]}), t6 = cat({-t4[0], t4[1]});
  return size * hermite_chain({p1, p2, p3, p4, p5, p6}, {t1, t2, t2, t4, t4, t6}, 0, in);
}

Fn bottle_cross(const ParameterValues& p) {
  const Fn half = bottle_half_cross(p);
  const Fn back = compose(half, 0, 1.0 - x(0));
  return concat(0, x(0), {half, cat({back[0], -back[1]})});
}

namespace detail {

Model bottle_model() {
  Model m;
  m.name = "bottle";
  m.description = "thesis Fig 3.19 / App. B.3: rounded-square sections on matched schedules, warped, nozzle/shoulders/body/bottom";
  m.parameters = {{"scale", 0.5, "size of the cross section (the rotated square has half-diagonal `scale`)"},
                  {"tangent_length", 0.2,
                   "Hermite tangent length at the rounding points (larger = fuller corners), in (0, 1.6...): "
                   "3 sqrt 2 min(q, 1 - q) over the rounding schedule q, beyond which the corners loop"},
                  {"nozzle_radius", 0.1, "radius of the nozzle ring"}};
  m.build = [](const ParameterValues& p) {
    const double nozzle = require_positive(p, "nozzle_radius");
    const Fn v = x(1);
    const Fn prof = gallery_curve("bottle_prof")(v), top = gallery_curve("bottle_top")(v);
    const Fn nozzle_prof = gallery_curve("bottle_nozzle")(v);
    const Fn c = bottle_cross(p);
    const Fn lift = cat({Fn(0.0), Fn(0.0), prof[1] - 1.0});
    // Main body: the section grown by 1 + prof_x, warped, lowered by prof_y - 1.
    const Fn body = warp_by_length(c * (1.0 + prof[0]), top, 1) + lift;
    // Shoulders: from the nozzle ring out to the section at the top of the body.
    const Fn c0 = compose(c, 1, Fn(0.0));
    const Fn ring = normalize(c0) * nozzle;
    const Fn shoulders = warp_by_length(interp(v, ring, c0), top, 1);
    // Nozzle: the warped ring scaled and raised by the nozzle profile.
    const Fn ring3 = warp_by_length(ring, top, 1);
    const Fn neck = cat({ring3[0] * nozzle_prof[0], ring3[1] * nozzle_prof[0], ring3[2] + nozzle_prof[1]});
    // Bottom: the last body section shrunk to the axis.
    const Fn c1 = (1.0 - v) * compose(c, 1, Fn(1.0));
    const Fn bottom = warp_by_length(c1, top, 1) + cat({Fn(0.0), Fn(0.0), compose(prof[1], 1, Fn(1.0)) - 1.0});
    return concat(1, v, {neck, shoulders, body, bottom});
  };
  m.periodic_u = true;
  m.open = true;  // a surface open at the mouth of the nozzle, as in the thesis
  return m;
}

}  // namespace detail
}  // namespace genmod::models
