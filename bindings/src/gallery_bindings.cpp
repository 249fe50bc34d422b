// The model gallery from Python (genmod.gallery wraps these): the parametric and implicit
// models with their parameters, built as Fn values and meshed adaptively.
#include "bindings.hpp"
#include "interruptible.hpp"

#include "genmod/models/gallery.hpp"
#include "genmod/models/implicit_gallery.hpp"
#include "genmod/models/region_gallery.hpp"
#include "genmod/models/trimmed_csg.hpp"

#include <pybind11/stl.h>

#include <stdexcept>
#include <string>

namespace py = pybind11;

namespace genmod::python {
namespace {

py::list parameters(const std::vector<models::ModelParameter>& ps) {
  py::list out;
  for (const auto& p : ps) out.append(py::make_tuple(p.name, p.value, p.doc));
  return out;
}

}  // namespace

void bind_gallery(py::module_& m) {
  m.def("_gallery_models", [] {
    py::list out;
    for (const models::Model& model : models::gallery())
      out.append(py::make_tuple(model.name, "parametric", model.description, parameters(model.parameters), model.open));
    for (const models::ImplicitModel& model : models::implicit_gallery())
      out.append(py::make_tuple(model.name, "implicit", model.description, parameters(model.parameters), false));
    for (const models::CsgModel& model : models::csg_models())
      out.append(py::make_tuple(model.name, "csg", model.description, py::list(), false));
    for (const models::RegionModel& model : models::region_models())
      out.append(py::make_tuple(model.name, "regions", model.description, parameters(model.parameters), true));
    return out;
  });
  m.def("_build_model", [](const std::string& name, const models::ParameterValues& params) {
    if (models::is_csg_model(name))
      throw std::invalid_argument("CSG model '" + name +
                                  "' is a Boolean combination of trimmed surfaces, not one function: mesh it with gallery.mesh");
    if (models::find_region_model(name))
      throw std::invalid_argument("region model '" + name +
                                  "' is several region functions, not one: mesh it with gallery.mesh");
    if (const models::ImplicitModel* implicit = models::find_implicit_model(name))
      return models::build_implicit_model(*implicit, params);
    return models::build_model(models::find_model(name), params);
  });
  m.def("_mesh_model", [](const std::string& name, const models::ParameterValues& params, double tolerance,
                          double max_seconds, int threads) {
    py::dict info;
    Mesh mesh;
    if (models::is_csg_model(name)) {
      if (!params.empty()) throw std::invalid_argument("CSG model '" + name + "' has no parameters");
      models::TrimmedCsgOptions o;
      if (tolerance > 0) o.tolerance = tolerance;
      o.curve_time = max_seconds;
      // No cancel flag reaches the CSG pipeline: max_seconds bounds its intersection curve.
      const models::TrimmedCsgResult r = [&] {
        py::gil_scoped_release release;
        return models::mesh_csg_model(name, o);
      }();
      info["tolerance"] = o.tolerance;
      info["curve_complete"] = r.curve_complete;
      info["seam_vertices"] = r.seam.size();
      mesh = r.mesh;
    } else if (models::find_region_model(name)) {
      // tolerance is the lattice's cube edge here (0: the model's default).
      const models::RegionModelMesh r = [&] {
        py::gil_scoped_release release;
        return models::mesh_region_model(name, params, tolerance);
      }();
      py::dict sheets;
      for (const auto& [a, b] : r.result.regions) {
        const std::string key = r.region_names.at(static_cast<std::size_t>(a)) + " | " +
                                r.region_names.at(static_cast<std::size_t>(b));
        sheets[key.c_str()] = sheets.contains(key) ? sheets[key.c_str()].cast<std::size_t>() + 1 : std::size_t{1};
      }
      info["sheets"] = sheets;
      info["limits_hit"] = r.result.stats.limits_hit;
      mesh = r.result.mesh;
    } else if (const models::ImplicitModel* implicit = models::find_implicit_model(name)) {
      const Fn f = models::build_implicit_model(*implicit, params);
      ImplicitMeshSettings s;
      s.min_feature = implicit->min_feature;
      s.tolerance = tolerance;
      s.max_seconds = max_seconds;
      s.threads = threads;
      std::atomic<bool> cancel{false};
      s.cancel = &cancel;
      const ImplicitMesh r = run_interruptible(cancel, [&] { return mesh_implicit(f, implicit->box, s); });
      info["distance_bound"] = r.stats.max_vertex_error;
      info["limits_hit"] = r.stats.limits_hit;
      mesh = r.mesh;
    } else {
      const models::Model& model = models::find_model(name);
      const models::ParameterValues p = models::resolve_parameters(model, params);
      const Fn surface = models::build_model(model, p);
      AdaptiveMeshOptions o;
      o.tolerance = tolerance > 0 ? tolerance : 1e-3 * models::model_extent(model, surface, p);
      o.max_seconds = max_seconds;
      o.threads = threads;
      std::atomic<bool> cancel{false};
      o.cancel = &cancel;
      const AdaptiveMesh r = run_interruptible(cancel, [&] { return models::mesh_model_adaptive(model, surface, p, o); });
      info["distance_bound"] = r.distance_bound;
      info["tolerance"] = o.tolerance;
      info["limits_hit"] = r.limits_hit;
      info["closed"] = r.closed();
      mesh = r.mesh;
    }
    return py::make_tuple(mesh, info);
  });
}

}  // namespace genmod::python
