// Furry bear (thesis Fig 3.23, research/snyder.md 7.24): a vector field on a surface,
// V(u, v): R^2 -> R^6 = (point on the scalp, tip of the hair). The thesis gives no formulas;
// the substitute: the scalp S is a profile-product body (a circle swept by the authored
// profile curves/furry_bear_profile.crv, a belly, a neck and a head), and the hair at S is
// the straight segment
//   S -> S + hair_length normalize(N + kappa S_v),   N = S_u x S_v (outward),
// combed toward S_v (up the body): it leans from the normal toward S_v by the angle
// atan(kappa |S_v| / |N|) (N is perpendicular to S_v). The main surface is the scalp; the
// hair field is furry_bear_hair(p) (for renderers that draw segments or texels), and a grid
// of hairs sampled from it are the model's extra patches (furry_bear_hairs): thin closed
// tubes around the hair segments, so a mesher outputs the fur with the scalp. The poles (v = 0, 1)
// have N = 0 (the hair there is along S_v); the grid keeps away from them.
#include "genmod/models/gallery.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/sweep.hpp"
#include "genmod/operators/vector.hpp"
#include "model_definitions.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {
Fn scalp(const ParameterValues& p) {
  const double size = detail::require_positive(p, "size");
  const Fn theta = x(0) * (2.0 * std::numbers::pi);
  const Fn profile = gallery_curve("furry_bear_profile")(x(1)) * size;
  return profile_product(cat({cos(theta), sin(theta)}), profile);
}

// The hair parameters (checked when the model is built, too).
double kappa_of(const ParameterValues& p) {
  const double kappa = detail::param(p, "kappa");
  if (!(kappa >= 0.0)) throw std::invalid_argument("parameter 'kappa' must be >= 0, got " + std::to_string(kappa));
  return kappa;
}

// hair_rows: a whole number in [1, kMaxHairRows] (2 rows^2 hairs, at most 392).
constexpr double kMaxHairRows = 14;
int hair_rows_of(const ParameterValues& p) {
  const double rows = detail::param(p, "hair_rows");
  if (!(rows >= 1.0 && rows <= kMaxHairRows && rows == std::floor(rows)))
    throw std::invalid_argument("parameter 'hair_rows' must be a whole number in [1, 14], got " + std::to_string(rows));
  return static_cast<int>(rows);
}

using V3 = std::array<double, 3>;
V3 cross3(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 unit(const V3& a) {
  const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}

// One hair as a closed thin tube of (theta, s) = (x(0), x(1)) around the segment from
// root = S - 2 r d (sunk below the scalp point S, so the tube's closed root end is hidden in
// the body) to the tip S + hair_length d:
//   axis(s) + rho(s) (cos(2 pi theta) e1 + sin(2 pi theta) e2),  rho(s) = (27/4) r s (1 - s)^2,
// rho being 0 at both ends (two poles: the tube is closed), r at s = 1/3 and tapering to the
// tip. e1, e2, d are a right-handed frame (d along the hair), so S_theta x S_s points away
// from the axis.
Fn hair_tube(const V3& scalp_point, const V3& tip, double r) {
  const V3 d = unit({tip[0] - scalp_point[0], tip[1] - scalp_point[1], tip[2] - scalp_point[2]});
  const V3 root{scalp_point[0] - 2.0 * r * d[0], scalp_point[1] - 2.0 * r * d[1], scalp_point[2] - 2.0 * r * d[2]};
  // Any axis not close to d gives the frame.
  const V3 helper = std::abs(d[0]) < 0.6 ? V3{1.0, 0.0, 0.0} : V3{0.0, 1.0, 0.0};
  const V3 e1 = unit(cross3(helper, d)), e2 = cross3(d, e1);
  const Fn theta = x(0) * (2.0 * std::numbers::pi), s = x(1);
  const Fn c = cos(theta), sn = sin(theta), radius = (6.75 * r) * s * square(1.0 - s);
  std::vector<Fn> xyz;
  for (int k = 0; k < 3; ++k)
    xyz.push_back(root[k] + s * (tip[k] - root[k]) + radius * (e1[k] * c + e2[k] * sn));
  return cat(xyz);
}
}  // namespace

Fn furry_bear_hair(const ParameterValues& p) {
  const double length = detail::require_positive(p, "hair_length");
  const double kappa = kappa_of(p);
  const Fn s = scalp(p);
  const Fn su = derivative(s, 0), sv = derivative(s, 1);
  const Fn direction = normalize(cross(su, sv) + kappa * sv);
  return cat({s, s + length * direction});
}

std::vector<ModelPatch> furry_bear_hairs(const ParameterValues& p) {
  const int rows = hair_rows_of(p);
  const double radius = detail::require_positive(p, "hair_radius");
  const Tape hair(furry_bear_hair(p), std::vector<int>{0, 1});
  PointEvaluator ev;
  std::vector<ModelPatch> hairs;
  const int around = 2 * rows;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double u = (i + 0.5) / around, v = (j + 0.5) / rows;
      const auto h = ev.eval(hair, {u, v});
      ModelPatch patch{hair_tube({h[0], h[1], h[2]}, {h[3], h[4], h[5]}, radius)};
      patch.periodic_u = true;
      hairs.push_back(patch);
    }
  return hairs;
}

namespace detail {

Model furry_bear_model() {
  Model m;
  m.name = "furry_bear";
  m.description = "thesis Fig 3.23: a profile-product scalp carrying a combed hair field (R^2 -> R^6), hairs output as thin tubes (extra patches)";
  m.parameters = {{"size", 1.0, "half the body's height (the body spans z in [-size, size])"},
                  {"hair_length", 0.08, "length of every hair"},
                  {"kappa", 1.5, "combing: the hair leans from the normal N toward S_v by atan(kappa |S_v| / |N|)"},
                  {"hair_rows", 12, "hairs output: hair_rows rows (in v) of 2 hair_rows hairs (in u), a whole number in [1, 14]"},
                  {"hair_radius", 0.004, "largest radius of a hair (each hair is a thin closed tube, thickest near the scalp, pointed at the tip)"}};
  m.build = [](const ParameterValues& p) {
    require_positive(p, "hair_length");
    require_positive(p, "hair_radius");
    hair_rows_of(p);
    kappa_of(p);
    return scalp(p);
  };
  m.periodic_u = true;
  m.extra_patches = furry_bear_hairs;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
