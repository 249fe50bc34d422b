// Wavefront OBJ: `v x y z` and `f a b c` lines (indices from 1).
#include "mesh_io_internal.hpp"

#include <cctype>
#include <vector>

namespace genmod::mesh_io {
namespace {

bool is_keyword(std::string_view s) {
  for (char c : s)
    if (!std::isalpha(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

// One face corner "i", "i/t", "i/t/n" or "i//n": the vertex index, 0-based.
std::uint32_t corner_index(const TextReader& r, std::string_view corner, std::size_t vertex_count) {
  const std::string_view index_text = corner.substr(0, corner.find('/'));
  const long long i = r.to_integer(index_text, "vertex index");
  const long long n = static_cast<long long>(vertex_count);
  if (i == 0) r.fail("vertex index 0 (OBJ indices start at 1)");
  const long long zero_based = i > 0 ? i - 1 : n + i;  // negative: counted back from the last vertex
  if (zero_based < 0 || zero_based >= n)
    r.fail("vertex index " + std::to_string(i) + " refers to none of the " + std::to_string(n) +
           " vertices defined so far");
  return static_cast<std::uint32_t>(zero_based);
}

}  // namespace

void write_obj(const Mesh& mesh, OutputFile& out) {
  out.write("# genmod mesh: ");
  out.write_uint(mesh.vertices.size());
  out.write(" vertices, ");
  out.write_uint(mesh.triangles.size());
  out.write(" triangles\n");
  for (const auto& p : mesh.vertices) {
    out.write("v ");
    out.write_point(p);
    out.write("\n");
  }
  for (const auto& t : mesh.triangles) {
    out.write("f ");
    out.write_indices(t, 1);
    out.write("\n");
  }
}

Mesh read_obj(std::string_view text, const std::filesystem::path& path) {
  TextReader r(text, path);
  Mesh mesh;
  std::vector<std::uint32_t> corners;
  while (r.next_line()) {
    const std::string_view key = r.token();
    if (key.empty() || key.front() == '#') continue;
    if (key == "v") {
      const double x = r.next_double("x coordinate"), y = r.next_double("y coordinate"),
                   z = r.next_double("z coordinate");
      for (std::string_view extra = r.token(); !extra.empty(); extra = r.token())
        (void)r.to_double(extra, "vertex value");  // w or a colour: checked, not kept
      mesh.vertices.push_back({x, y, z});
    } else if (key == "f") {
      corners.clear();
      for (std::string_view c = r.token(); !c.empty(); c = r.token())
        corners.push_back(corner_index(r, c, mesh.vertices.size()));
      if (corners.size() < 3) r.fail("a face needs at least 3 corners, got " + std::to_string(corners.size()));
      add_polygon(mesh, corners.data(), corners.size());
    } else if (!is_keyword(key)) {
      r.fail("unknown statement '" + std::string(key) + "'");
    }  // vt, vn, g, o, s, usemtl, mtllib, l, ...: not part of the triangle mesh
  }
  return mesh;
}

}  // namespace genmod::mesh_io
