// Morkel's procedural models from Python (genmod.procedural wraps these): the registered
// procedures with their typed parameters and signatures, called with named arguments and a
// seed to a triangle mesh, and the procedure caches (switch, counters, clearing).
#include "bindings.hpp"
#include "param_values.hpp"

#include "genmod/models/procedural_models.hpp"
#include "genmod/procedural/procedure.hpp"

#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace py = pybind11;

namespace genmod::python {

py::object param_to_python(const ParamValue& v) {
  switch (v.type()) {
    case ParamType::Double: return py::float_(v.as_double());
    case ParamType::Integer: return py::int_(v.as_integer());
    case ParamType::Boolean: return py::bool_(v.as_bool());
    case ParamType::String: return py::str(v.as_string());
    case ParamType::Vector: {
      const Vec3& p = v.as_vector();
      return py::make_tuple(p[0], p[1], p[2]);
    }
  }
  return py::none();
}

// A Python value as the parameter value of the same kind (bool before int: a Python bool is an
// int); the registry then checks it against the declared type and names the parameter.
ParamValue param_from_python(const std::string& procedure, const std::string& name, const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return ParamValue(v.cast<bool>());
  if (py::isinstance<py::int_>(v)) return ParamValue(v.cast<std::int64_t>());
  if (py::isinstance<py::float_>(v)) return ParamValue(v.cast<double>());
  if (py::isinstance<py::str>(v)) return ParamValue(v.cast<std::string>());
  if (py::isinstance<py::sequence>(v) && py::len(v) == 3) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(v);
    return ParamValue(Vec3(s[0].cast<double>(), s[1].cast<double>(), s[2].cast<double>()));
  }
  throw std::invalid_argument("call '" + procedure + "': parameter '" + name + "' has a value of Python type " +
                              std::string(py::str(v.get_type().attr("__name__"))) +
                              " (expected a number, a bool, a string or a 3-vector)");
}

// The arguments of a call of procedural model `name` (refused when there is no such model).
NamedArgs model_arguments(const std::string& name, const py::dict& args) {
  if (models::find_procedural_model(name) == nullptr)
    throw std::invalid_argument("genmod.procedural: no procedural model named '" + name + "'");
  NamedArgs named;
  for (const auto& [key, value] : args) {
    const std::string k = py::str(key);
    named.emplace_back(k, param_from_python(name, k, value));
  }
  return named;
}

Camera looking_at(const std::array<double, 3>& eye, const std::array<double, 3>& target) {
  return models::camera_looking_at(Vec3(eye[0], eye[1], eye[2]), Vec3(target[0], target[1], target[2]));
}

void bind_procedural(py::module_& m) {
  m.def("_procedural_models", [] {
    const ProcedureRegistry& registry = models::procedural_registry();
    py::list out;
    for (const models::ProceduralModel& model : models::procedural_gallery()) {
      const ProcedureSpec& spec = registry.spec(model.name);
      py::list params;
      for (const ParamDecl& p : spec.params) {
        std::string doc;
        for (const auto& [name, text] : model.parameter_docs)
          if (name == p.name) doc = text;
        params.append(py::make_tuple(p.name, std::string(java_type_name(p.type)), param_to_python(*p.default_value), doc));
      }
      out.append(py::make_tuple(model.name, model.description, registry.signature(model.name), params, spec.cacheable));
    }
    return out;
  });
  m.def("_mesh_procedural", [](const std::string& name, const py::dict& args, std::int64_t seed, int lod) {
    const NamedArgs named = model_arguments(name, args);
    py::gil_scoped_release unlocked;
    return models::mesh_procedural_model(name, named, seed, lod);
  }, py::arg("name"), py::arg("args"), py::arg("seed"), py::arg("lod") = 0);
  // With a camera (eye and target, z up): the mesh at the lod the camera chooses for the model's
  // bounds (empty when out of view), and that view (None for a model without bounds).
  m.def("_mesh_procedural_camera", [](const std::string& name, const py::dict& args, std::int64_t seed,
                                      std::array<double, 3> eye, std::array<double, 3> target) {
    const NamedArgs named = model_arguments(name, args);
    const Camera camera = looking_at(eye, target);
    py::gil_scoped_release unlocked;
    return models::mesh_procedural_model(name, named, seed, camera);
  }, py::arg("name"), py::arg("args"), py::arg("seed"), py::arg("eye"), py::arg("target"));
  m.def("_procedural_view", [](const std::string& name, const py::dict& args, std::array<double, 3> eye,
                               std::array<double, 3> target) -> py::object {
    const NamedArgs named = model_arguments(name, args);
    const Camera camera = looking_at(eye, target);
    const std::optional<BoxView> view = models::procedural_model_view(name, named, camera);
    if (!view) return py::none();
    py::dict d;
    d["visible"] = view->visible;
    d["lod"] = view->lod;
    d["pixels"] = view->pixels;
    return d;
  }, py::arg("name"), py::arg("args"), py::arg("eye"), py::arg("target"));
  m.def("_procedural_cache", [](const std::string& name) {
    const CacheStats s = models::procedural_registry().cache_stats(name);
    py::dict d;
    d["hits"] = s.hits;
    d["misses"] = s.misses;
    d["evictions"] = s.evictions;
    d["entries"] = s.entries;
    return d;
  });
  m.def("_set_procedural_caching", [](bool on) { models::procedural_registry().set_caching(on); });
  m.def("_procedural_caching", [] { return models::procedural_registry().caching(); });
  m.def("_clear_procedural_caches", [] { models::procedural_registry().clear_caches(); });
  m.def("_reset_procedural_cache_stats", [](const std::string& name) {
    models::procedural_registry().reset_cache_stats(name);
  });
}

}  // namespace genmod::python
