// Parametric surface meshing on a lattice and OpenMesh-based file I/O (see mesh.hpp).
#include "genmod/tessellate/mesh.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

namespace genmod {

namespace {

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// OpenMesh's readers and writers chat on its log stream ("[OBJWriter] : write file") on
// stderr; a library must not. Its error stream stays on, and failures are reported by the
// exceptions below.
void silence_openmesh_log() {
  static const bool silenced = [] {
    omlog().disable();
    return true;
  }();
  (void)silenced;
}

void check_axis(const LatticeAxis& a, bool periodic, const char* name) {
  const std::size_t min_samples = periodic ? 3 : 2;
  if (a.samples < min_samples)
    throw std::invalid_argument(std::string("genmod: mesh_parametric: axis ") + name + " needs at least " +
                                std::to_string(min_samples) + " samples" + (periodic ? " when periodic" : "") +
                                ", got " + std::to_string(a.samples));
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

Mesh mesh_parametric(const Fn& surface, const LatticeAxis& u, const LatticeAxis& v,
                     const ParametricMeshOptions& options) {
  if (surface.dim() != 3)
    throw std::invalid_argument("genmod: mesh_parametric: the surface must have dimension 3, got " +
                                std::to_string(surface.dim()));
  check_axis(u, options.periodic_u, "u");
  check_axis(v, options.periodic_v, "v");
  const std::size_t nu = u.samples, nv = v.samples;
  if (nu * nv > 0xffffffffu) throw std::invalid_argument("genmod: mesh_parametric: too many vertices");
  // A periodic axis samples one more point (the seam copy of the first) and drops it.
  LatticeAxis lu = u, lv = v;
  if (options.periodic_u) lu.samples = nu + 1;
  if (options.periodic_v) lv.samples = nv + 1;
  const Lattice lattice({lu, lv});
  const std::vector<double> xyz = evaluate_lattice(surface, lattice, options.method);

  Mesh mesh;
  mesh.vertices.reserve(nu * nv);
  for (std::size_t j = 0; j < nv; ++j)
    for (std::size_t i = 0; i < nu; ++i) {
      const std::size_t p = i + lu.samples * j;
      mesh.vertices.push_back({xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]});
    }
  const std::size_t qu = options.periodic_u ? nu : nu - 1;
  const std::size_t qv = options.periodic_v ? nv : nv - 1;
  mesh.triangles.reserve(2 * qu * qv);
  auto id = [nu](std::size_t i, std::size_t j) { return static_cast<std::uint32_t>(i + nu * j); };
  for (std::size_t j = 0; j < qv; ++j)
    for (std::size_t i = 0; i < qu; ++i) {
      const std::size_t i1 = (i + 1) % nu, j1 = (j + 1) % nv;
      mesh.triangles.push_back({id(i, j), id(i1, j), id(i1, j1)});
      mesh.triangles.push_back({id(i, j), id(i1, j1), id(i, j1)});
    }
  return mesh;
}

void write_mesh(const Mesh& mesh, const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".obj" && ext != ".ply" && ext != ".stl" && ext != ".off")
    throw std::invalid_argument("genmod: write_mesh: unknown mesh file extension '" + ext + "' in '" +
                                path.string() + "' (use .obj, .ply, .stl or .off)");
  OMesh om;
  std::vector<OMesh::VertexHandle> vh;
  vh.reserve(mesh.vertices.size());
  for (const auto& p : mesh.vertices) vh.push_back(om.add_vertex(OMesh::Point(p[0], p[1], p[2])));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (std::uint32_t k : tri)
      if (k >= vh.size())
        throw std::invalid_argument("genmod: write_mesh: triangle " + std::to_string(t) + " uses vertex " +
                                    std::to_string(k) + " of " + std::to_string(vh.size()));
    if (!om.add_face(vh[tri[0]], vh[tri[1]], vh[tri[2]]).is_valid())
      throw std::invalid_argument("genmod: write_mesh: triangle " + std::to_string(t) +
                                  " is degenerate or makes the mesh non-manifold (OpenMesh rejected it)");
  }
  const auto dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw std::runtime_error("genmod: write_mesh: cannot write '" + path.string() + "': directory '" +
                             dir.string() + "' does not exist");
  silence_openmesh_log();
  OpenMesh::IO::Options opt;
  if (ext == ".stl") {
    om.request_face_normals();
    om.update_face_normals();
    opt += OpenMesh::IO::Options::FaceNormal;
  }
  if (!OpenMesh::IO::write_mesh(om, path.string(), opt))
    throw std::runtime_error("genmod: write_mesh: cannot write '" + path.string() + "'");
}

Mesh read_mesh(const std::filesystem::path& path) {
  OMesh om;
  if (!std::filesystem::exists(path))
    throw std::runtime_error("genmod: read_mesh: '" + path.string() + "' does not exist");
  silence_openmesh_log();
  if (!OpenMesh::IO::read_mesh(om, path.string()))
    throw std::runtime_error("genmod: read_mesh: cannot read '" + path.string() + "' as a mesh");
  Mesh mesh;
  mesh.vertices.reserve(om.n_vertices());
  for (auto v : om.vertices()) {
    const auto& p = om.point(v);
    mesh.vertices.push_back({double(p[0]), double(p[1]), double(p[2])});
  }
  for (auto f : om.faces()) {
    std::array<std::uint32_t, 3> tri{};
    int k = 0;
    for (auto v : om.fv_range(f))
      if (k < 3) tri[static_cast<std::size_t>(k++)] = static_cast<std::uint32_t>(v.idx());
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

}  // namespace genmod
