// Lamp stand (thesis Fig 3.3, research/snyder.md 7.4): the profile product of a closed,
// star-shaped cross section and a profile:
//   cross = m_crv("cross.crv", m_x(0)); profile = m_crv("profile.crv", m_x(1));
//   lampstand = m_profile(cross, profile);
// Substitute curves: a closed periodic cubic B-spline through samples of the lobed curve
// r(theta) = 1 + lobe_depth cos(lobes theta), and a Catmull-Rom profile with a base flare,
// a thin stem and a top flare.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/sweep.hpp"
#include "model_definitions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {
constexpr int kCrossSamples = 32;  // control points of the closed cross-section spline
}

Curve lamp_stand_cross(const ParameterValues& p) {
  const double lobes_value = detail::param(p, "lobes");
  if (!(lobes_value >= 0.0 && lobes_value <= 8.0) || lobes_value != std::floor(lobes_value))
    throw std::invalid_argument("parameter 'lobes' must be an integer in [0, 8], got " + std::to_string(lobes_value));
  const double depth = detail::param(p, "lobe_depth");
  if (!(depth >= 0.0 && depth < 0.5))
    throw std::invalid_argument("parameter 'lobe_depth' must be in [0, 0.5), got " + std::to_string(depth));
  // Unclamped uniform cubic B-spline over the samples with the first three repeated at the
  // end: a closed C2 curve (the domain [0, 1] runs once around).
  Curve::Points points;
  for (int i = 0; i < kCrossSamples + 3; ++i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i % kCrossSamples) / kCrossSamples;
    const double r = 1.0 + depth * std::cos(lobes_value * a);
    points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return Curve::uniform_bspline(points, 3, /*clamped=*/false);
}

Curve lamp_stand_profile(const ParameterValues& p) {
  const double base = detail::require_positive(p, "base_radius");
  const double stem = detail::require_positive(p, "stem_radius");
  const double top = detail::require_positive(p, "top_radius");
  const double h = detail::require_positive(p, "height");
  return Curve::catmull_rom({{0.0, 0.0},
                             {base, 0.0},
                             {base, 0.04 * h},
                             {0.5 * (base + stem), 0.1 * h},
                             {stem, 0.2 * h},
                             {stem, 0.5 * h},
                             {stem, 0.8 * h},
                             {0.5 * (stem + top), 0.9 * h},
                             {top, 0.97 * h},
                             {top, h},
                             {0.0, h}});
}

namespace detail {

Model lamp_stand_model() {
  Model m;
  m.name = "lamp_stand";
  m.description = "thesis Fig 3.3: profile product of a lobed closed spline and a flared stem profile";
  m.parameters = {{"lobes", 4.0, "number of lobes of the cross section (integer, 0..8; 0 = a circle of radius 1 + lobe_depth)"},
                  {"lobe_depth", 0.15, "lobe amplitude: r(theta) = 1 + lobe_depth cos(lobes theta), in [0, 0.5)"},
                  {"base_radius", 0.6, "radius of the base flare"},
                  {"stem_radius", 0.08, "radius of the stem"},
                  {"top_radius", 0.3, "radius of the top flare"},
                  {"height", 2.0, "height of the stand"}};
  m.build = [](const ParameterValues& p) {
    return profile_product(lamp_stand_cross(p)(x(0)), lamp_stand_profile(p)(x(1)));
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
