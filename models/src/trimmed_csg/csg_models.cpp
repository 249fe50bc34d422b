// The surfaces and named models of CSG with trimmed surfaces (trimmed_csg.hpp).
#include "genmod/models/trimmed_csg.hpp"

#include <numbers>
#include <stdexcept>

namespace genmod::models {

ClosedSurface bumpy_sphere() {
  // Profile product of c(u) = (cos 2πu, sin 2πu)(1 + 0.1 sin 16πu) and
  // p(v) = (cos(π(2v-1)/2), sin(π(2v-1)/2))(1 + 0.1 sin 8πv) (snyder.md §5.4.1).
  constexpr double pi = std::numbers::pi;
  const Fn u = x(0), v = x(1);
  const Fn cr = 1.0 + 0.1 * sin(u * (16.0 * pi));
  const Fn pr = 1.0 + 0.1 * sin(v * (8.0 * pi));
  const Fn phi = (v * 2.0 - 1.0) * (pi / 2.0);
  const Fn cx = cos(u * (2.0 * pi)) * cr, cy = sin(u * (2.0 * pi)) * cr;
  const Fn px = cos(phi) * pr, py = sin(phi) * pr;
  return {cat({cx * px, cy * px, py}), true, false};
}

ClosedSurface drill_cylinder(double radius) {
  if (!(radius > 0 && radius < 0.8)) throw std::invalid_argument("drill_cylinder: radius must be in (0, 0.8)");
  constexpr double pi = std::numbers::pi;
  const Fn s = x(0), t = x(1);
  // Along x from -1.5 to 1.5; S_s x S_t points away from the axis.
  return {cat({t * 3.0 - 1.5, cos(s * (2.0 * pi)) * radius, sin(s * (2.0 * pi)) * radius}), true, false};
}

ClosedSurface cross_cylinder(double radius, double z0) {
  if (!(radius > 0)) throw std::invalid_argument("cross_cylinder: radius must be > 0");
  constexpr double pi = std::numbers::pi;
  const Fn s = x(0), t = x(1);
  // Along y from -1.5 to 1.5 at height z0; S_s x S_t points away from the axis.
  return {cat({sin(s * (2.0 * pi)) * radius, t * 3.0 - 1.5, cos(s * (2.0 * pi)) * radius + z0}), true, false};
}

ClosedSurface sphere_surface(double radius, double cx, double cy, double cz) {
  constexpr double pi = std::numbers::pi;
  const Fn u = x(0), v = x(1);
  const Fn phi = (v * 2.0 - 1.0) * (pi / 2.0);
  return {cat({cos(u * (2.0 * pi)) * cos(phi) * radius + cx, sin(u * (2.0 * pi)) * cos(phi) * radius + cy,
               sin(phi) * radius + cz}),
          true, false};
}

const std::vector<CsgModel>& csg_models() {
  static const std::vector<CsgModel> models{
      {"drilled_sphere", "the bumpy sphere minus a cylinder: one closed mesh of genus 1 (Fig 5.20-5.22, Algorithm 5.4)"},
      {"drilled_sphere_twice",
       "(A - B) - C: the drilled sphere minus a second, thinner bore above the first: genus 2 (full CSG, §5.5)"}};
  return models;
}

bool is_csg_model(const std::string& name) {
  for (const CsgModel& m : csg_models())
    if (m.name == name) return true;
  return false;
}

TrimmedCsgResult mesh_csg_model(const std::string& name, const TrimmedCsgOptions& options) {
  if (name == "drilled_sphere") return trimmed_csg(bumpy_sphere(), drill_cylinder(0.3), CsgOperation::Difference, options);
  if (name == "drilled_sphere_twice")
    return trimmed_csg({bumpy_sphere(), drill_cylinder(0.3), cross_cylinder(0.2, 0.55)},
                       [](const std::vector<char>& in) { return in[0] && !in[1] && !in[2]; }, options);
  throw std::invalid_argument("unknown CSG model '" + name + "' (known: drilled_sphere, drilled_sphere_twice)");
}

}  // namespace genmod::models
