// Meshes in Python: vertex (V, 3) and triangle (F, 3) numpy arrays, files, the validator's
// report, previews (Mesh._repr_png_ shows a mesh in a notebook), the implicit mesher, the
// continuation polygonizer and the non-manifold polygonizer for several regions.
#include "bindings.hpp"
#include "interruptible.hpp"

#include "genmod/kernel/fn.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/nonmanifold_polygonizer.hpp"
#include "genmod/tessellate/png_io.hpp"
#include "genmod/tessellate/preview.hpp"
#include "genmod/tessellate/validate.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

namespace py = pybind11;

namespace genmod::python {
namespace {

py::array_t<double> vertex_array(const Mesh& m) {
  py::array_t<double> a({static_cast<py::ssize_t>(m.vertices.size()), py::ssize_t{3}});
  double* p = a.mutable_data();
  for (const auto& v : m.vertices) p = std::copy(v.begin(), v.end(), p);
  return a;
}

py::array_t<std::uint32_t> triangle_array(const Mesh& m) {
  py::array_t<std::uint32_t> a({static_cast<py::ssize_t>(m.triangles.size()), py::ssize_t{3}});
  std::uint32_t* p = a.mutable_data();
  for (const auto& t : m.triangles) p = std::copy(t.begin(), t.end(), p);
  return a;
}

Mesh mesh_from_arrays(const py::array_t<double, py::array::c_style | py::array::forcecast>& v,
                      const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& t) {
  if (v.ndim() != 2 || v.shape(1) != 3) throw std::invalid_argument("genmod.Mesh: vertices must have shape (V, 3)");
  if (t.ndim() != 2 || t.shape(1) != 3) throw std::invalid_argument("genmod.Mesh: triangles must have shape (F, 3)");
  Mesh m;
  for (py::ssize_t i = 0; i < v.shape(0); ++i) m.vertices.push_back({v.at(i, 0), v.at(i, 1), v.at(i, 2)});
  for (py::ssize_t i = 0; i < t.shape(0); ++i) {
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const std::int64_t idx = t.at(i, k);
      if (idx < 0 || idx >= v.shape(0))
        throw std::invalid_argument("genmod.Mesh: triangle " + std::to_string(i) + " names vertex " + std::to_string(idx) +
                                    " of " + std::to_string(v.shape(0)));
      tri[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(idx);
    }
    m.triangles.push_back(tri);
  }
  return m;
}

py::dict report(const MeshValidity& v) {
  py::dict d;
  d["valid"] = v.valid();
  d["closed"] = v.closed();
  d["manifold"] = v.manifold();
  d["oriented"] = v.oriented();
  d["outward"] = v.outward;
  d["self_intersections"] = v.self_intersections;
  d["degenerate_triangles"] = v.degenerate_triangles;
  d["boundary_edges"] = v.boundary_edges;
  d["components"] = v.components;
  d["euler_characteristic"] = v.euler_characteristic;
  d["volume"] = v.volume;
  d["vertices"] = v.vertices;
  d["triangles"] = v.triangles;
  d["description"] = describe(v);
  return d;
}

py::bytes png_of(const Mesh& m, int size) {
  PreviewOptions o;
  o.width = o.height = size;
  Image image;
  {
    py::gil_scoped_release unlocked;
    image = preview(m, o);
  }
  const std::vector<std::uint8_t> bytes = encode_png(image);
  return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

Box3 box_from(const py::array_t<double, py::array::c_style | py::array::forcecast>& b) {
  if (b.ndim() != 2 || b.shape(0) != 3 || b.shape(1) != 2)
    throw std::invalid_argument("genmod: a 3-D box must be an array of shape (3, 2) of [lo, hi] rows");
  Box3 box;
  for (int k = 0; k < 3; ++k) {
    if (!(b.at(k, 0) < b.at(k, 1))) throw std::invalid_argument("genmod: box row " + std::to_string(k) + " needs lo < hi");
    box[static_cast<std::size_t>(k)] = Interval(b.at(k, 0), b.at(k, 1));
  }
  return box;
}

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<Mesh>(m, "Mesh", R"doc(A triangle mesh: vertices (V, 3) float64 and triangles (F, 3) uint32 arrays.

mesh.write(path) writes OBJ, PLY, STL or OFF by the extension; mesh.validate() is the
validator's report (closed, manifold, oriented outward, no self-intersections, ...);
mesh.png() a shaded preview (a notebook shows a mesh through _repr_png_).)doc")
      .def(py::init(&mesh_from_arrays), py::arg("vertices"), py::arg("triangles"))
      .def_property_readonly("vertices", &vertex_array)
      .def_property_readonly("triangles", &triangle_array)
      .def("__len__", [](const Mesh& mesh) { return mesh.triangles.size(); })
      .def("__repr__", [](const Mesh& mesh) {
        return "<genmod.Mesh " + std::to_string(mesh.vertices.size()) + " vertices, " +
               std::to_string(mesh.triangles.size()) + " triangles>";
      })
      .def("write", [](const Mesh& mesh, const std::filesystem::path& path) { write_mesh(mesh, path); }, py::arg("path"))
      .def("validate", [](const Mesh& mesh) {
        MeshValidity v;
        {
          py::gil_scoped_release unlocked;
          v = validate(mesh);
        }
        return report(v);
      })
      .def("png", &png_of, py::arg("size") = 512, "A shaded preview as PNG bytes.")
      .def("_repr_png_", [](const Mesh& mesh) { return png_of(mesh, 384); });
  m.def("read_mesh", [](const std::filesystem::path& path) { return read_mesh(path); }, py::arg("path"),
        "Reads an OBJ, PLY, STL or OFF mesh file (the format from the extension).");

  m.def("mesh_implicit", [](const Fn& f, const py::array_t<double, py::array::c_style | py::array::forcecast>& box,
                            double min_feature, double tolerance, double max_seconds, int threads) {
        ImplicitMeshSettings s;
        s.min_feature = min_feature;
        s.tolerance = tolerance;
        s.max_seconds = max_seconds;
        s.threads = threads;
        const Box3 b = box_from(box);
        std::atomic<bool> cancel{false};
        s.cancel = &cancel;
        const ImplicitMesh result = run_interruptible(cancel, [&] { return mesh_implicit(f, b, s); });
        py::dict stats;
        stats["max_vertex_error"] = result.stats.max_vertex_error;
        stats["uncertified_vertices"] = result.stats.uncertified_vertices;
        stats["limits_hit"] = result.stats.limits_hit;
        stats["leaves"] = result.stats.leaves;
        return py::make_tuple(result.mesh, stats);
      }, py::arg("f"), py::arg("box"), py::arg("min_feature"), py::arg("tolerance") = 0.0,
      py::arg("max_seconds") = 0.0, py::arg("threads") = 0,
      R"doc(Meshes the solid {f < 0} inside box (shape (3, 2)): closed, manifold and intersection-free.

Returns (mesh, stats); stats names the limits hit (the mesh is then coarser, still valid).)doc");

  m.def("polygonize_continuation", [](const Fn& f, double cube_size, const py::object& starts, const py::object& box,
                                      bool cubes, int bisections, std::size_t max_cubes, int threads) {
        ContinuationSettings s;
        s.threads = threads;
        s.cube_size = cube_size;
        if (!starts.is_none()) {
          const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(starts);
          if (!a || a.ndim() != 2 || a.shape(1) != 3)
            throw std::invalid_argument("genmod: polygonize_continuation: starts must have shape (N, 3)");
          for (py::ssize_t i = 0; i < a.shape(0); ++i) s.starts.push_back({a.at(i, 0), a.at(i, 1), a.at(i, 2)});
        }
        if (!box.is_none()) s.bounds = box_from(box.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>());
        s.decomposition = cubes ? CellDecomposition::cubes : CellDecomposition::tetrahedra;
        s.bisections = bisections;
        s.max_cubes = max_cubes;
        std::atomic<bool> cancel{false};
        s.cancel = &cancel;
        const ContinuationMesh result = run_interruptible(cancel, [&] { return polygonize_continuation(f, s); });
        py::array_t<double> normals({static_cast<py::ssize_t>(result.normals.size()), py::ssize_t{3}});
        double* p = normals.mutable_data();
        for (const auto& n : result.normals) p = std::copy(n.begin(), n.end(), p);
        py::dict stats;
        stats["cubes"] = result.stats.cubes;
        stats["evaluations"] = result.stats.evaluations();
        stats["max_vertex_error"] = 0.5 * result.stats.max_bracket;
        stats["seeds"] = result.stats.seeds;
        stats["limits_hit"] = result.stats.limits_hit;
        stats["normals"] = normals;
        return py::make_tuple(result.mesh, stats);
      }, py::arg("f"), py::arg("cube_size"), py::arg("starts") = py::none(), py::arg("box") = py::none(),
      py::arg("cubes") = false, py::arg("bisections") = 10, py::arg("max_cubes") = std::size_t{10'000'000},
      py::arg("threads") = 0,
      R"doc(Bloomenthal's continuation polygonizer: the pieces of the surface f = 0 reached from the
start points (shape (N, 3); default: a seed searched in box), cubes of edge cube_size, only cubes
whose centre is in box (shape (3, 2)) visited. cubes=True uses the cube table instead of six
tetrahedra per cube. threads: worker threads (0 = all cores); the mesh is the same for any count.

Returns (mesh, stats); stats has the cubes visited, evaluations of f, the vertex error bound,
the seeds, the limits hit and the per-vertex normals (V, 3).)doc");

  m.def("polygonize_regions", [](const std::vector<Fn>& regions, double cube_size, const py::object& box,
                                 const py::object& interest, int sections, int steps, double close_factor,
                                 std::size_t max_cubes, bool split, int threads) {
        NonmanifoldSettings s;
        s.threads = threads;
        s.cube_size = cube_size;
        s.bounds = box_from(box.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>());
        if (!interest.is_none())
          for (const auto& item : interest.cast<std::vector<std::pair<int, int>>>()) s.interest.push_back(item);
        s.sections = sections;
        s.steps = steps;
        s.close_factor = close_factor;
        s.max_cubes = max_cubes;
        Mesh split_mesh;
        std::vector<std::pair<int, int>> vertex_pairs;
        std::vector<std::uint32_t> origin;
        std::vector<std::array<double, 3>> normals;
        std::atomic<bool> cancel{false};
        s.cancel = &cancel;
        const RegionMesh result = run_interruptible(cancel, [&] {
          RegionMesh r = polygonize_regions(regions, s);
          if (split) {
            split_mesh = split_by_region_pair(r, &vertex_pairs, &origin);
            normals = region_pair_normals(regions, split_mesh, vertex_pairs, 0.01 * cube_size);
          }
          return r;
        });
        py::array_t<std::int32_t> pairs({static_cast<py::ssize_t>(result.regions.size()), py::ssize_t{2}});
        std::int32_t* p = pairs.mutable_data();
        for (const auto& [a, b] : result.regions) {
          *p++ = a;
          *p++ = b;
        }
        py::array_t<std::uint8_t> kinds(static_cast<py::ssize_t>(result.vertex_kinds.size()));
        std::uint8_t* k = kinds.mutable_data();
        for (RegionVertexKind kind : result.vertex_kinds) *k++ = static_cast<std::uint8_t>(kind);
        const auto& st = result.stats;
        py::dict stats;
        stats["cubes"] = st.cubes;
        stats["evaluations"] = st.evaluations();
        stats["corner_evaluations"] = st.corner_evaluations;
        stats["sample_evaluations"] = st.sample_evaluations;
        stats["refine_evaluations"] = st.refine_evaluations;
        stats["face_evaluations"] = st.face_evaluations;
        stats["face_vertices"] = st.face_vertices;
        stats["face_vertex_fallbacks"] = st.face_vertex_fallbacks;
        stats["internal_vertices"] = st.internal_vertices;
        stats["eps"] = st.eps;
        stats["limits_hit"] = st.limits_hit;
        stats["vertex_kinds"] = kinds;
        if (!split) return py::make_tuple(result.mesh, pairs, stats);
        py::array_t<double> n({static_cast<py::ssize_t>(normals.size()), py::ssize_t{3}});
        double* q = n.mutable_data();
        for (const auto& v : normals) q = std::copy(v.begin(), v.end(), q);
        py::array_t<std::int32_t> vp({static_cast<py::ssize_t>(vertex_pairs.size()), py::ssize_t{2}});
        std::int32_t* r = vp.mutable_data();
        for (const auto& [a, b] : vertex_pairs) {
          *r++ = a;
          *r++ = b;
        }
        py::array_t<std::uint32_t> o(static_cast<py::ssize_t>(origin.size()));
        std::copy(origin.begin(), origin.end(), o.mutable_data());
        stats["normals"] = n;
        stats["vertex_pairs"] = vp;
        stats["origin"] = o;
        return py::make_tuple(split_mesh, pairs, stats);
      }, py::arg("regions"), py::arg("cube_size"), py::arg("box"), py::arg("interest") = py::none(),
      py::arg("sections") = 16, py::arg("steps") = 4, py::arg("close_factor") = 1.0,
      py::arg("max_cubes") = std::size_t{10'000'000}, py::arg("split") = false, py::arg("threads") = 0,
      R"doc(Bloomenthal's non-manifold polygonizer: the boundaries between regions of space. The region of
a point is the index of the largest of the functions `regions` (K >= 2 scalar functions of x, y,
z); interest is a list of region pairs to mesh (default: all). Cubes of edge cube_size fill box
(shape (3, 2)); each tetrahedron edge is sampled at `sections` points and each crossing refined
by `steps` halvings. threads: worker threads (0 = all cores); the mesh is the same for any count.

Returns (mesh, pairs, stats): pairs (F, 2) int32 gives each triangle's regions (first < second;
the normal points into the second); stats has the evaluations of the region function by
purpose, eps (the edge-vertex tolerance), the face and internal vertices, the limits hit and
vertex_kinds (V,) uint8: 0 edge, 1 face, 2 internal vertex. split=True returns instead the mesh
with each vertex duplicated once per region pair of the triangles around it (one copy per sheet
along a junction), and adds stats normals (V, 3) (each sheet's own normal, the gradient of
g_b - g_a, into the greater region), vertex_pairs (V, 2) and origin (V,) (the vertex of the
welded mesh each copies; vertex_kinds stays per welded vertex).)doc");
}

}  // namespace genmod::python
