// The gallery registry, parameter resolution and meshing.
#include "genmod/models/gallery.hpp"
#include "model_definitions.hpp"

#include <cmath>
#include <cstdint>
#include <utility>
#include <stdexcept>

namespace genmod::models {

const std::vector<Model>& gallery() {
  // The thesis models in the order of its Chapter 3 / Appendix B, then standard shapes.
  static const std::vector<Model> models{
      detail::doorknob_model(),
      detail::patio_tile_model(),
      detail::lamp_stand_model(),
      detail::tennis_racket_model(),
      detail::briefcase_handle_model(),
      detail::banana_model(),
      detail::turbine_blade_model(),
      detail::gear_model(),
      detail::sphere_cylinder_fillet_model(),
      detail::cross_section_matching_model(),
      detail::offsets_model(),
      detail::offset_plate_model(),
      detail::spoon_model(),
      detail::key_model(),
      detail::cpg_model(),
      detail::screwdriver_regular_model(),
      detail::screwdriver_phillips_model(),
      detail::cpg_fillet_model(),
      detail::bottle_model(),
      detail::circular_beam_model(),
      detail::time_varying_curve_model(),
      detail::wing_model(),
      detail::furry_bear_model(),
      detail::sphere_model(),
      detail::torus_model()};
  return models;
}

const Model& find_model(const std::string& name) {
  for (const Model& m : gallery())
    if (m.name == name) return m;
  std::string known;
  for (const Model& m : gallery()) known += (known.empty() ? "" : ", ") + m.name;
  throw std::invalid_argument("unknown model '" + name + "' (known models: " + known + ")");
}

ParameterValues resolve_parameters(const std::string& model_name, const std::vector<ModelParameter>& parameters,
                                   const ParameterValues& overrides) {
  ParameterValues values;
  for (const ModelParameter& p : parameters) values[p.name] = p.value;
  for (const auto& [name, value] : overrides) {
    if (values.find(name) == values.end()) {
      std::string known;
      for (const ModelParameter& p : parameters) known += (known.empty() ? "" : ", ") + p.name;
      throw std::invalid_argument("model '" + model_name + "' has no parameter '" + name +
                                  "' (its parameters: " + (known.empty() ? "none" : known) + ")");
    }
    if (!std::isfinite(value))
      throw std::invalid_argument("parameter '" + name + "' of model '" + model_name + "' must be finite");
    values[name] = value;
  }
  return values;
}

ParameterValues resolve_parameters(const Model& model, const ParameterValues& overrides) {
  return resolve_parameters(model.name, model.parameters, overrides);
}

Fn build_model(const Model& model, const ParameterValues& overrides) {
  return model.build(resolve_parameters(model, overrides));
}

namespace {

void append(Mesh& to, const Mesh& patch, bool flip) {
  const auto offset = static_cast<std::uint32_t>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), patch.vertices.begin(), patch.vertices.end());
  for (auto t : patch.triangles) {
    if (flip) std::swap(t[1], t[2]);
    to.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
}

// The six faces of the solid: coordinate k fixed at an end, the other two as lattice axes in
// increasing order. S_a x S_b points along +k for k = 0 and 2 and along -k for k = 1 (for
// the identity map), so the faces that would point inward are flipped.
Mesh mesh_solid(const Model& model, const Fn& solid, std::size_t n) {
  if (solid.dim() != 3) throw std::invalid_argument("solid model '" + model.name + "' must have 3 outputs");
  const Interval domain[3] = {model.u, model.v, model.w};
  Mesh mesh;
  for (int k = 0; k < 3; ++k)
    for (int end = 0; end < 2; ++end) {
      const int a = k == 0 ? 1 : 0, b = k == 2 ? 1 : 2;
      const Fn face = compose(solid, k, Fn(end == 0 ? domain[k].lo() : domain[k].hi()));
      const Mesh patch = mesh_parametric(face, {a, domain[a].lo(), domain[a].hi(), n},
                                         {b, domain[b].lo(), domain[b].hi(), n});
      const bool along_plus_k = k != 1;
      append(mesh, patch, along_plus_k == (end == 0));
    }
  return mesh;
}

}  // namespace

Mesh mesh_model(const Model& model, const Fn& surface, std::size_t n) {
  if (n < 3) throw std::invalid_argument("mesh resolution must be at least 3, got " + std::to_string(n));
  if (model.solid) return mesh_solid(model, surface, n);
  const LatticeAxis u{0, model.u.lo(), model.u.hi(), n};
  const LatticeAxis v{1, model.v.lo(), model.v.hi(), n};
  ParametricMeshOptions options;
  options.periodic_u = model.periodic_u;
  options.periodic_v = model.periodic_v;
  return mesh_parametric(surface, u, v, options);
}

namespace detail {

double param(const ParameterValues& p, const std::string& name) {
  const auto it = p.find(name);
  if (it == p.end()) throw std::invalid_argument("missing model parameter '" + name + "'");
  return it->second;
}

double require_positive(const ParameterValues& p, const std::string& name) {
  const double value = param(p, name);
  if (!(value > 0.0))
    throw std::invalid_argument("parameter '" + name + "' must be > 0, got " + std::to_string(value));
  return value;
}

}  // namespace detail
}  // namespace genmod::models
