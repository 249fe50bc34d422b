// Writing procedures in Python (Morkel's language as a Python API): the polygon mesh with face
// labels (OpenMesh underneath), the mesh tools (ratio-box selection, extrusion, sqrt(2)
// subdivision, curve shaping, bridge and stitch), and registries of procedures whose bodies
// are Python functions, with typed defaulted parameters, named arguments, seed inheritance
// and the memo cache. Face lists are numpy arrays of face indices.
#include "bindings.hpp"
#include "param_values.hpp"

#include "genmod/procedural/bezier_curve.hpp"
#include "genmod/procedural/curve_shaping.hpp"
#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/poly_mesh.hpp"
#include "genmod/procedural/procedure.hpp"
#include "genmod/procedural/selection.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"
#include "genmod/procedural/stitching.hpp"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace genmod::python {

namespace {

Vec3 vec(const std::array<double, 3>& p) { return Vec3(p[0], p[1], p[2]); }

FaceList faces_of(const PolyMesh& mesh, const std::vector<long>& indices) {
  FaceList faces;
  for (long i : indices) {
    if (i < 0 || static_cast<std::size_t>(i) >= mesh.n_faces())
      throw std::invalid_argument("genmod.procedural: face " + std::to_string(i) + " is not in the mesh (" +
                                  std::to_string(mesh.n_faces()) + " faces)");
    faces.push_back(PolyMesh::FaceHandle(static_cast<int>(i)));
  }
  return faces;
}

py::array_t<long> indices_of(const FaceList& faces) {
  py::array_t<long> a(static_cast<py::ssize_t>(faces.size()));
  for (std::size_t k = 0; k < faces.size(); ++k) a.mutable_at(k) = faces[k].idx();
  return a;
}

void bind_poly_mesh(py::module_& m) {
  py::class_<PolyMesh>(m, "PolyMesh", R"doc(A polygon mesh with a label per face (OpenMesh), what procedures build and
the mesh tools change. Faces are named by their indices; mesh.to_mesh() triangulates it into a
genmod.Mesh for validation, writing and previews.)doc")
      .def_static("box", [](std::array<double, 3> lo, std::array<double, 3> hi, const std::string& label) {
        return make_box(vec(lo), vec(hi), label);
      }, py::arg("lo"), py::arg("hi"), py::arg("label") = "", "The box [lo, hi] as six outward quads.")
      .def_static("grid_box", [](std::array<double, 3> lo, std::array<double, 3> hi, int n, const std::string& label) {
        return make_grid_box(vec(lo), vec(hi), n, label);
      }, py::arg("lo"), py::arg("hi"), py::arg("n"), py::arg("label") = "",
      "The box [lo, hi] with every side split into n x n quads.")
      .def("copy", [](const PolyMesh& mesh) { return PolyMesh(mesh); }, "An independent copy.")
      .def_property_readonly("counts", [](const PolyMesh& mesh) {
        const MeshCounts c = counts(mesh);
        return py::make_tuple(c.vertices, c.edges, c.faces);
      }, "(vertices, edges, faces).")
      .def("is_closed_manifold", &is_closed_manifold, "Every edge between two faces, every vertex one fan.")
      .def("faces", [](const PolyMesh& mesh) { return indices_of(all_faces(mesh)); }, "Every face, in index order.")
      .def("faces_labelled", [](const PolyMesh& mesh, const std::string& label) {
        return indices_of(faces_labelled(mesh, label));
      }, py::arg("label"), "The faces with that label.")
      .def("label", [](const PolyMesh& mesh, long face) { return face_label(mesh, faces_of(mesh, {face})[0]); },
           py::arg("face"), "The label of a face.")
      .def("set_label", [](PolyMesh& mesh, const std::vector<long>& faces, const std::string& label) {
        for (PolyMesh::FaceHandle f : faces_of(mesh, faces)) set_face_label(mesh, f, label);
      }, py::arg("faces"), py::arg("label"), "Labels the faces.")
      .def("bounds", [](const PolyMesh& mesh, std::optional<std::vector<long>> faces) {
        const auto b = bounds(mesh, faces ? faces_of(mesh, *faces) : all_faces(mesh));
        return py::make_tuple(py::make_tuple(b[0][0], b[0][1], b[0][2]), py::make_tuple(b[1][0], b[1][1], b[1][2]));
      }, py::arg("faces") = std::optional<std::vector<long>>{}, "(lo, hi) of the faces' vertices (all faces by default).")
      .def("to_mesh", &to_triangle_mesh, "The triangulated mesh (genmod.Mesh).");
}

void bind_tools(py::module_& m) {
  m.def("select", [](const PolyMesh& mesh, const std::vector<long>& parent, std::array<double, 6> r) {
        return indices_of(select_faces(mesh, faces_of(mesh, parent), RatioBox{r[0], r[1], r[2], r[3], r[4], r[5]}));
      }, py::arg("mesh"), py::arg("parent"), py::arg("box"),
      "The faces of parent whose vertices all lie in box = (x0, x1, y0, y1, z0, z1), ratios of parent's bounds.");
  m.def("extrude", [](PolyMesh& mesh, const std::vector<long>& faces, std::array<double, 3> by) {
        return indices_of(extrude(mesh, faces_of(mesh, faces), vec(by)));
      }, py::arg("mesh"), py::arg("faces"), py::arg("by"),
      "Extrudes the faces by a vector, keeping the mesh closed; returns the caps.");
  m.def("sqrt2_subdivide", [](PolyMesh& mesh, const std::vector<long>& faces, int levels, double smoothing) {
        return indices_of(sqrt2_subdivide(mesh, faces_of(mesh, faces), levels, smoothing));
      }, py::arg("mesh"), py::arg("faces"), py::arg("levels"), py::arg("smoothing"),
      "Adaptive sqrt(2) subdivision of the faces with the smoothing factor; returns the new faces.");
  m.def("shape_to_curve", [](PolyMesh& mesh, const std::vector<long>& faces, const std::vector<std::array<double, 3>>& curve,
                             std::array<double, 3> direction, std::array<double, 3> normal) {
        std::vector<Vec3> points;
        for (const auto& p : curve) points.push_back(vec(p));
        return shape_to_curve(mesh, faces_of(mesh, faces), BezierCurve(points), vec(direction), vec(normal));
      }, py::arg("mesh"), py::arg("faces"), py::arg("curve"), py::arg("direction"), py::arg("normal"),
      "Moves the faces' vertices along direction onto the Bezier curve (control points), seen along normal; "
      "returns how many moved.");
  m.def("bridge", [](PolyMesh& mesh, const std::vector<long>& a, const std::vector<long>& b, const std::string& label) {
        return indices_of(bridge(mesh, faces_of(mesh, a), faces_of(mesh, b), label));
      }, py::arg("mesh"), py::arg("a"), py::arg("b"), py::arg("label") = "",
      "Removes two disk-like selections and joins their boundary loops by a tube; returns its faces.");
  m.def("stitch", [](const PolyMesh& a, const std::vector<long>& sel_a, const PolyMesh& b, const std::vector<long>& sel_b,
                     const std::string& label) {
        return stitch(a, faces_of(a, sel_a), b, faces_of(b, sel_b), label);
      }, py::arg("a"), py::arg("sel_a"), py::arg("b"), py::arg("sel_b"), py::arg("label") = "",
      "A new mesh: sel_a of a put in place of sel_b of b, joined along their boundary loops.");
}

// What a Python procedure body sees: its resolved arguments (a dict) and the call context
// (seed, lod, and call() for the procedures it calls, which inherit the context).
struct PyCallContext {
  const CallContext* context;
};

void bind_registry(py::module_& m) {
  py::class_<PyCallContext>(m, "CallContext", "The context of a procedure call: seed, lod and call() of callees.")
      .def_property_readonly("seed", [](const PyCallContext& c) { return c.context->seed(); })
      .def_property_readonly("lod", [](const PyCallContext& c) { return c.context->lod(); })
      .def("call", [](const PyCallContext& c, const std::string& name, std::optional<std::int64_t> seed, py::kwargs args) {
        NamedArgs named;
        for (const auto& [k, v] : args) named.emplace_back(py::str(k), param_from_python(name, py::str(k), v));
        CallOptions o;
        o.seed = seed;
        return c.context->call(name, named, o);
      }, py::arg("name"), py::arg("seed") = std::optional<std::int64_t>{},
      "Calls a procedure of the same registry with named arguments (the context is inherited; seed overrides it).");

  py::class_<ProcedureRegistry, std::unique_ptr<ProcedureRegistry>>(m, "Registry", R"doc(Procedures with Python bodies.

registry.add(name, body, params={"height": 2.0, "legs": 4}, cacheable=False): every parameter
has a default (its type is the default's: float, int, bool, str or a 3-tuple); body(args,
context) returns a PolyMesh, args a dict of every parameter. registry.call(name, seed=0,
**args) resolves named arguments in any order (refusing unknown names and wrong types, naming
the procedure and the parameter) and returns an independent PolyMesh; cacheable procedures are
built once per distinct (arguments, seed).)doc")
      .def(py::init([] { return std::make_unique<ProcedureRegistry>(); }))
      .def("add", [](ProcedureRegistry& r, const std::string& name, py::function body, const py::dict& params,
                     bool cacheable) {
        ProcedureSpec spec;
        spec.name = name;
        spec.mode = Mode::Out;
        spec.cacheable = cacheable;
        for (const auto& [k, v] : params) spec.params.push_back(param(py::str(k), param_from_python(name, py::str(k), v)));
        std::vector<std::string> names;
        for (const ParamDecl& p : spec.params) names.push_back(p.name);
        spec.out_body = [body, names](const Arguments& args, const CallContext& context) {
          py::dict a;
          for (std::size_t k = 0; k < names.size(); ++k) a[py::str(names[k])] = param_to_python(args.values()[k]);
          PyCallContext c{&context};
          return body(a, c).cast<PolyMesh>();
        };
        r.add(std::move(spec));
      }, py::arg("name"), py::arg("body"), py::arg("params") = py::dict(), py::arg("cacheable") = false,
      "Registers a procedure (ValueError for a duplicate name or a bad default).")
      .def("call", [](const ProcedureRegistry& r, const std::string& name, std::int64_t seed, py::kwargs args) {
        NamedArgs named;
        for (const auto& [k, v] : args) named.emplace_back(py::str(k), param_from_python(name, py::str(k), v));
        Context context;
        context.seed = seed;
        return r.call(name, named, context);
      }, py::arg("name"), py::arg("seed") = 0, "Calls a procedure with named arguments.")
      .def("signature", &ProcedureRegistry::signature, py::arg("name"), "The thesis's signature string.")
      .def("cache_stats", [](const ProcedureRegistry& r, const std::string& name) {
        const CacheStats s = r.cache_stats(name);
        return py::dict(py::arg("hits") = s.hits, py::arg("misses") = s.misses, py::arg("evictions") = s.evictions,
                        py::arg("entries") = s.entries);
      }, py::arg("name"), "Hits, misses, evictions and entries of a procedure's cache.")
      .def_property("caching", &ProcedureRegistry::caching, &ProcedureRegistry::set_caching, "The caches' switch.");
}

}  // namespace

void bind_procedure_tools(py::module_& m) {
  // Their own namespace (genmod.procedural re-exports them): `select` and `bridge` would
  // collide with the language's names.
  py::module_ tools = m.def_submodule("_procedural", "Polygon meshes, mesh tools and Python procedures");
  bind_poly_mesh(tools);
  bind_tools(tools);
  bind_registry(tools);
}

}  // namespace genmod::python
