// Doorknob (thesis Fig 3.1, research/snyder.md 7.2): the profile product of a circle in u and
// an authored Catmull-Rom profile in v, a surface of revolution:
//   cross = m_circle(m_x(0)*2*pi); profile = m_crv("profile.crv", m_x(1));
//   doorknob = m_profile(cross, profile);
#include "genmod/models/gallery.hpp"
#include "genmod/operators/sweep.hpp"
#include "model_definitions.hpp"

#include <numbers>

namespace genmod::models {

// (radius, height) from the door plate (z = -height/2) through a narrow neck, out to the
// bulge, and closed on the axis at z = +height/2.
Curve doorknob_profile(const ParameterValues& p) {
  const double plate = detail::require_positive(p, "plate_radius");
  const double neck = detail::require_positive(p, "neck_radius");
  const double bulge = detail::require_positive(p, "bulge_radius");
  const double h = detail::require_positive(p, "height") / 2.0;
  return Curve::catmull_rom({{0.0, -h},
                             {plate, -h},
                             {plate, -0.85 * h},
                             {neck, -0.6 * h},
                             {neck, -0.3 * h},
                             {0.75 * bulge, 0.05 * h},
                             {bulge, 0.45 * h},
                             {0.7 * bulge, 0.9 * h},
                             {0.0, h}});
}

namespace detail {

Model doorknob_model() {
  Model m;
  m.name = "doorknob";
  m.description = "thesis Fig 3.1: profile product of a circle and a Catmull-Rom profile (surface of revolution)";
  m.parameters = {{"plate_radius", 0.45, "radius of the plate against the door"},
                  {"neck_radius", 0.25, "radius of the narrow neck"},
                  {"bulge_radius", 0.8, "largest radius of the knob"},
                  {"height", 2.0, "length along the axis (z from -height/2 to height/2)"}};
  m.build = [](const ParameterValues& p) {
    const Fn theta = x(0) * (2.0 * std::numbers::pi);
    const Fn cross = cat({cos(theta), sin(theta)});
    const Fn profile = doorknob_profile(p)(x(1));
    return profile_product(cross, profile);
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
