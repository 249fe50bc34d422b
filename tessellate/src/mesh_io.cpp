// Mesh file I/O: the format from the extension, the checks of a mesh before it is written,
// and the dispatch to the format's reader and writer (src/mesh_io/).
#include "genmod/tessellate/mesh_io.hpp"

#include "mesh_io/mesh_io_internal.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

namespace genmod {
namespace {

MeshFormat format_or_throw(const std::filesystem::path& path, const char* caller) {
  const std::optional<MeshFormat> format = mesh_format(path);
  if (!format)
    throw std::invalid_argument(std::string("genmod: ") + caller + ": unknown mesh file extension '" +
                                path.extension().string() + "' in '" + path.string() +
                                "' (use .obj, .ply, .stl or .off)");
  return *format;
}

void check_writable(const Mesh& mesh) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (double c : mesh.vertices[v])
      if (!std::isfinite(c))
        throw std::invalid_argument("genmod: write_mesh: vertex " + std::to_string(v) + " has a coordinate that is not finite");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t k : mesh.triangles[t])
      if (k >= mesh.vertices.size())
        throw std::invalid_argument("genmod: write_mesh: triangle " + std::to_string(t) + " uses vertex " +
                                    std::to_string(k) + " of " + std::to_string(mesh.vertices.size()));
}

}  // namespace

std::optional<MeshFormat> mesh_format(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".off") return MeshFormat::Off;
  return std::nullopt;
}

void write_mesh(const Mesh& mesh, const std::filesystem::path& path) {
  const MeshFormat format = format_or_throw(path, "write_mesh");
  check_writable(mesh);
  mesh_io::OutputFile out(path);
  switch (format) {
    case MeshFormat::Obj: mesh_io::write_obj(mesh, out); break;
    case MeshFormat::Ply: mesh_io::write_ply(mesh, out); break;
    case MeshFormat::Stl: mesh_io::write_stl(mesh, out); break;
    case MeshFormat::Off: mesh_io::write_off(mesh, out); break;
  }
  out.finish();
}

Mesh read_mesh(const std::filesystem::path& path) {
  const MeshFormat format = format_or_throw(path, "read_mesh");
  const std::string bytes = mesh_io::read_file(path);
  switch (format) {
    case MeshFormat::Obj: return mesh_io::read_obj(bytes, path);
    case MeshFormat::Ply: return mesh_io::read_ply(bytes, path);
    case MeshFormat::Stl: return mesh_io::read_stl(bytes, path);
    case MeshFormat::Off: return mesh_io::read_off(bytes, path);
  }
  return {};
}

}  // namespace genmod
