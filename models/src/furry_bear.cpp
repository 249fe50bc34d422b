// Furry bear (thesis Fig 3.23, research/snyder.md 7.24): a vector field on a surface,
// V(u, v): R^2 -> R^6 = (point on the scalp, tip of the hair). The thesis gives no formulas;
// the substitute: the scalp S is a profile-product body (a circle swept by the authored
// profile curves/furry_bear_profile.crv, a belly, a neck and a head), and the hair at S is
// the straight segment
//   S -> S + hair_length normalize(N + kappa S_v),   N = S_u x S_v (outward),
// combed toward S_v (up the body): it leans from the normal toward S_v by the angle
// atan(kappa |S_v| / |N|) (N is perpendicular to S_v). The MODEL surface is the scalp (a
// 3-D surface, meshed as usual); the hair field is furry_bear_hair(p), for renderers that
// draw segments or texels. The poles (v = 0, 1) have N = 0: the hair there is along S_v.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/sweep.hpp"
#include "genmod/operators/vector.hpp"

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
}  // namespace

Fn furry_bear_hair(const ParameterValues& p) {
  const double length = detail::require_positive(p, "hair_length");
  const double kappa = kappa_of(p);
  const Fn s = scalp(p);
  const Fn su = derivative(s, 0), sv = derivative(s, 1);
  const Fn direction = normalize(cross(su, sv) + kappa * sv);
  return cat({s, s + length * direction});
}

namespace detail {

Model furry_bear_model() {
  Model m;
  m.name = "furry_bear";
  m.description = "thesis Fig 3.23: a profile-product scalp carrying a combed hair field (furry_bear_hair: R^2 -> R^6)";
  m.parameters = {{"size", 1.0, "half the body's height (the body spans z in [-size, size])"},
                  {"hair_length", 0.08, "length of every hair"},
                  {"kappa", 1.5, "combing: the hair leans from the normal N toward S_v by atan(kappa |S_v| / |N|)"}};
  m.build = [](const ParameterValues& p) {
    require_positive(p, "hair_length");
    kappa_of(p);
    return scalp(p);
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
