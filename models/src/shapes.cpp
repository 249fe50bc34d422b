// Standard shapes of operators/shapes.hpp as gallery models.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/shapes.hpp"
#include "model_definitions.hpp"

#include <stdexcept>
#include <string>

namespace genmod::models::detail {

Model sphere_model() {
  Model m;
  m.name = "sphere";
  m.description = "sphere_surface: a sphere about the origin (poles at v = 0, 1)";
  m.parameters = {{"radius", 1.0, "radius"}};
  m.build = [](const ParameterValues& p) { return sphere_surface(require_positive(p, "radius")); };
  m.periodic_u = true;
  return m;
}

Model torus_model() {
  Model m;
  m.name = "torus";
  m.description = "torus_surface: a torus about the z axis (closed in u and v)";
  m.parameters = {{"major_radius", 1.0, "radius of the tube's center circle"},
                  {"minor_radius", 0.3, "radius of the tube"}};
  m.build = [](const ParameterValues& p) {
    const double major = require_positive(p, "major_radius");
    const double minor = require_positive(p, "minor_radius");
    if (!(minor < major))
      throw std::invalid_argument("parameter 'minor_radius' must be < major_radius, got " + std::to_string(minor));
    return torus_surface(major, minor);
  };
  m.periodic_u = true;
  m.periodic_v = true;
  return m;
}

}  // namespace genmod::models::detail
