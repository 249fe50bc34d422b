// Patio tile (thesis Fig 3.2, research/snyder.md 7.3): the profile product of two polylines,
// a polyhedron:
//   cross = m_crv("cross.crv", m_x(0)); profile = m_crv("profile.crv", m_x(1));
//   block = m_profile(cross, profile);
// Substitute curves: a regular polygon cross section and a chamfered slab profile.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/sweep.hpp"
#include "model_definitions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod::models {

// The closed regular polygon of `sides` vertices on the circle of radius `radius` (the first
// vertex repeated at the end).
Curve patio_tile_cross(const ParameterValues& p) {
  const double sides_value = detail::param(p, "sides");
  if (!(sides_value >= 3.0 && sides_value <= 64.0) || sides_value != std::floor(sides_value))
    throw std::invalid_argument("parameter 'sides' must be an integer in [3, 64], got " + std::to_string(sides_value));
  const int sides = static_cast<int>(sides_value);
  const double r = detail::require_positive(p, "radius");
  Curve::Points points;
  for (int i = 0; i <= sides; ++i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i % sides) / static_cast<double>(sides);
    points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return Curve::polyline(points);
}

// (scale, height): bottom center, bottom edge, chamfer, side, chamfer, top edge, top center.
Curve patio_tile_profile(const ParameterValues& p) {
  const double h = detail::require_positive(p, "thickness") / 2.0;
  const double c = detail::param(p, "chamfer");
  if (!(c >= 0.0 && c < h && c < 1.0))
    throw std::invalid_argument("parameter 'chamfer' must be in [0, min(thickness/2, 1)), got " + std::to_string(c));
  if (c == 0.0) return Curve::polyline({{0.0, -h}, {1.0, -h}, {1.0, h}, {0.0, h}});
  return Curve::polyline({{0.0, -h}, {1.0 - c, -h}, {1.0, -h + c}, {1.0, h - c}, {1.0 - c, h}, {0.0, h}});
}

namespace detail {

Model patio_tile_model() {
  Model m;
  m.name = "patio_tile";
  m.description = "thesis Fig 3.2: profile product of two polylines (a chamfered polygonal slab, polyhedral)";
  m.parameters = {{"sides", 8.0, "number of sides of the polygonal cross section (integer, 3..64)"},
                  {"radius", 1.0, "circumradius of the polygon"},
                  {"thickness", 0.3, "height of the slab"},
                  {"chamfer", 0.05, "size of the 45-degree chamfer on the edges (relative to radius; 0 = none)"}};
  m.build = [](const ParameterValues& p) {
    return profile_product(patio_tile_cross(p)(x(0)), patio_tile_profile(p)(x(1)));
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
