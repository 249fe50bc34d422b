// The procedural models' registry and list (procedural_models.hpp).
#include "genmod/models/procedural_models.hpp"

#include "procedural_model_defs.hpp"


#include <cmath>
#include <stdexcept>

namespace genmod::models {
namespace {

std::vector<detail::ProceduralModelDef> definitions() {
  std::vector<detail::ProceduralModelDef> defs;
  defs.push_back(detail::leg_definition());
  defs.push_back(detail::chair_definition());
  defs.push_back(detail::couch_definition());
  defs.push_back(detail::table_definition());
  defs.push_back(detail::luggage_definition());
  defs.push_back(detail::luggage_chest_definition());
  defs.push_back(detail::foot_definition());
  defs.push_back(detail::arm_definition());
  defs.push_back(detail::torso_definition());
  defs.push_back(detail::head_definition());
  defs.push_back(detail::human_definition());
  defs.push_back(detail::branch_definition());
  defs.push_back(detail::tree_definition());
  // Each documented parameter is a declared one, in the same order.
  for (const auto& d : defs) {
    bool same = d.spec.params.size() == d.info.parameter_docs.size() && d.spec.name == d.info.name;
    for (std::size_t i = 0; same && i < d.spec.params.size(); ++i)
      same = d.spec.params[i].name == d.info.parameter_docs[i].first;
    if (!same) throw std::logic_error("procedural model '" + d.info.name + "': documentation and signature differ");
  }
  return defs;
}

}  // namespace

const std::vector<ProceduralModel>& procedural_gallery() {
  static const std::vector<ProceduralModel> gallery = [] {
    std::vector<ProceduralModel> g;
    for (auto& d : definitions()) g.push_back(std::move(d.info));
    return g;
  }();
  return gallery;
}

const ProceduralModel* find_procedural_model(const std::string& name) {
  for (const ProceduralModel& m : procedural_gallery())
    if (m.name == name) return &m;
  return nullptr;
}

void register_procedural_models(ProcedureRegistry& registry, const std::function<void(ProcedureSpec&)>& adjust) {
  for (auto& d : definitions()) {
    if (adjust) adjust(d.spec);
    registry.add(std::move(d.spec));
  }
}

ProcedureRegistry& procedural_registry() {
  static ProcedureRegistry registry;
  static const bool registered = [] {
    register_procedural_models(registry);
    return true;
  }();
  (void)registered;
  return registry;
}

namespace {

// The registry's shared mesh is only read here (no copy of a cached model: a hit costs a lookup).
Mesh meshed_z_up(const std::string& name, const NamedArgs& args, const Context& context) {
  const std::shared_ptr<const PolyMesh> mesh = procedural_registry().call_shared(name, args, context);
  Mesh triangles = to_triangle_mesh(*mesh);
  // y up -> z up: (x, y, z) -> (x, -z, y), a rotation (orientation kept), exact in doubles;
  // "+ 0.0" turns -0 into +0, as the affine map used before did (the same bytes in files).
  for (auto& v : triangles.vertices) v = {v[0] + 0.0, -v[2] + 0.0, v[1] + 0.0};
  return triangles;
}

Vec3 to_y_up(const Vec3& v) { return Vec3(v[0], v[2], -v[1]); }

}  // namespace

Mesh mesh_procedural_model(const std::string& name, const NamedArgs& args, std::int64_t seed, int lod) {
  Context context;
  context.seed = seed;
  context.lod = lod;
  return meshed_z_up(name, args, context);
}

Camera camera_looking_at(const Vec3& eye, const Vec3& target) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(eye[k]) || !std::isfinite(target[k]))
      throw std::invalid_argument("camera: the eye and the target must be finite points");
  Camera c;
  c.position = eye;
  c.direction = target - eye;
  c.up = Vec3(0, 0, 1);
  if (c.direction.sqrnorm() == 0) throw std::invalid_argument("camera: the eye and the target are the same point");
  if (c.direction[0] == 0 && c.direction[1] == 0)
    throw std::invalid_argument("camera: the view is vertical; the camera's up is +z, so look at a target that is "
                                "not straight above or below the eye");
  return c;
}

Camera procedure_frame_camera(const Camera& z_up) {
  Camera c = z_up;
  c.position = to_y_up(z_up.position);
  c.direction = to_y_up(z_up.direction);
  c.up = to_y_up(z_up.up);
  return c;
}

std::optional<BoxView> procedural_model_view(const std::string& name, const NamedArgs& args, const Camera& camera) {
  const Camera c = procedure_frame_camera(camera);
  check_camera(c);
  const std::optional<std::array<Vec3, 2>> box = procedural_registry().bounds(name, args);
  if (!box) return std::nullopt;
  return view_of_box(c, *box);
}

Mesh mesh_procedural_model(const std::string& name, const NamedArgs& args, std::int64_t seed, const Camera& camera) {
  Context context;
  context.seed = seed;
  context.camera = procedure_frame_camera(camera);
  return meshed_z_up(name, args, context);
}

}  // namespace genmod::models
