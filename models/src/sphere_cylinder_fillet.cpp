// Sphere / cylinder fillet (thesis Fig 3.9, App. B.1, research/snyder.md 7.11): the complete
// App. B.1 construction. A circle of vertical lines (the "fillet cylinder": radius
// ray_radius about the z axis) is intersected with a horizontal cylinder (axis x, through the
// origin, radius cylinder_radius; the nearest hit going down, -z) and with a sphere (centre
// (0, sphere_center_y, sphere_center_z), radius sphere_radius; the nearest hit going up,
// +z). Along each intersection curve c the fillet leaves in the direction n x c' (n the unit
// surface normal, c' the unit tangent), so F_u x F_v is parallel to n there (G1 continuity):
//   fillet = m_interp_hermite(v, c1, c2, c1d*z, c2d*z),  z = m_interp(w, 0.01, 1.0).
// The thesis's third input w (a one-parameter family of fillets) is the model parameter
// `bulge`; sphere_cylinder_fillet_family() keeps it as x(2).
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/vector.hpp"
#include "model_definitions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {

// Solves || u + v t ||^2 == r^2, the smaller root (m_solve_len).
Fn solve_len(const Fn& u, const Fn& v, const Fn& r) {
  const Fn a = dot(v, v);
  const Fn b = 2.0 * dot(u, v);
  const Fn c = dot(u, u) - square(r);
  return (-b - sqrt(square(b) - 4.0 * a * c)) / (2.0 * a);
}
// Nearest intersection of the line a + b t with the sphere (o, r) (m_ray_sph).
Fn ray_sph(const Fn& a, const Fn& b, const Fn& o, const Fn& r) { return a + b * solve_len(a - o, b, r); }
// Nearest intersection with the cylinder of origin o, unit direction d, radius r (m_ray_cyl).
Fn ray_cyl(const Fn& a, const Fn& b, const Fn& o, const Fn& d, const Fn& r) {
  return a + b * solve_len(o - a + d * dot(a - o, d), d * dot(b, d) - b, r);
}
Fn sph_nor(const Fn& o, const Fn& p) { return normalize(p - o); }
Fn cyl_nor(const Fn& o, const Fn& d, const Fn& p) { return normalize(p - (o + d * dot(p - o, d))); }

// The fillet for the tangent-magnitude input w (a constant or x(2)).
Fn fillet(const ParameterValues& p, const Fn& w) {
  const double cyl_radius = detail::require_positive(p, "cylinder_radius");
  const double sph_radius = detail::require_positive(p, "sphere_radius");
  const double sph_y = detail::param(p, "sphere_center_y");
  const double sph_z = detail::param(p, "sphere_center_z");
  const double ray_radius = detail::require_positive(p, "ray_radius");
  if (!(ray_radius < cyl_radius))
    throw std::invalid_argument("parameter 'ray_radius' must be < cylinder_radius (every line must hit the cylinder), got " +
                                std::to_string(ray_radius));
  if (!(ray_radius + std::abs(sph_y) < sph_radius))
    throw std::invalid_argument("parameter 'ray_radius' must be < sphere_radius - |sphere_center_y| (every line must hit the sphere), got " +
                                std::to_string(ray_radius));
  const Fn cyl_o = cat({0.0, 0.0, 0.0}), cyl_d = cat({1.0, 0.0, 0.0});
  const Fn sph_o = cat({0.0, sph_y, sph_z});
  // Rays arranged in a circle in the xy plane (origin height 0.5 as in the thesis; only the
  // lines matter).
  const Fn theta = x(0) * (2.0 * std::numbers::pi);
  const Fn a = cat({cos(theta) * ray_radius, sin(theta) * ray_radius, Fn(0.5)});
  const Fn b = cat({0.0, 0.0, 1.0});

  const Fn c1 = ray_cyl(a, -b, cyl_o, cyl_d, cyl_radius);
  const Fn c1tan = normalize(derivative(c1, 0));
  const Fn c1nor = cyl_nor(cyl_o, cyl_d, c1);
  const Fn c1d = cross(c1nor, c1tan);

  const Fn c2 = ray_sph(a, b, sph_o, sph_radius);
  const Fn c2tan = normalize(derivative(c2, 0));
  const Fn c2nor = sph_nor(sph_o, c2);
  const Fn c2d = cross(c2nor, c2tan);

  const Fn z = interp(w, 0.01, 1.0);
  return hermite_interp(x(1), c1, c2, c1d * z, c2d * z);
}

}  // namespace

Fn sphere_cylinder_fillet_family(const ParameterValues& p) { return fillet(p, x(2)); }

namespace detail {

Model sphere_cylinder_fillet_model() {
  Model m;
  m.name = "sphere_cylinder_fillet";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.9 / App. B.1: Hermite fillet from the top of a horizontal cylinder to the bottom of a sphere, G1 at both ends";
  m.parameters = {{"bulge", 0.5, "the thesis's w in [0, 1]: tangent magnitude z = interp(w, 0.01, 1) at both ends"},
                  {"cylinder_radius", 0.6, "radius of the cylinder about the x axis"},
                  {"sphere_radius", 0.6, "radius of the sphere"},
                  {"sphere_center_y", -0.1, "y of the sphere's centre"},
                  {"sphere_center_z", 1.5, "z of the sphere's centre"},
                  {"ray_radius", 0.4, "radius of the circle of vertical lines that cut both surfaces"}};
  m.build = [](const ParameterValues& p) {
    const double bulge = param(p, "bulge");
    if (!(bulge >= 0.0 && bulge <= 1.0))
      throw std::invalid_argument("parameter 'bulge' must be in [0, 1], got " + std::to_string(bulge));
    return fillet(p, Fn(bulge));
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
