// OFF: "OFF", then "V F E", V lines "x y z", F lines "n i_0 ... i_(n-1)" (indices from 0).
#include "mesh_io_internal.hpp"

#include <vector>

namespace genmod::mesh_io {
namespace {

// The next line that is neither blank nor a comment; false at the end of the text.
bool next_data_line(TextReader& r) {
  while (r.next_line()) {
    const std::string_view rest = r.rest_of_line();
    const std::size_t first = rest.find_first_not_of(" \t\v\f");
    if (first != std::string_view::npos && rest[first] != '#') return true;
  }
  return false;
}

}  // namespace

void write_off(const Mesh& mesh, OutputFile& out) {
  out.write("OFF\n");
  out.write_uint(mesh.vertices.size());
  out.write(" ");
  out.write_uint(mesh.triangles.size());
  out.write(" 0\n");
  for (const auto& p : mesh.vertices) {
    out.write_point(p);
    out.write("\n");
  }
  for (const auto& t : mesh.triangles) {
    out.write("3 ");
    out.write_indices(t);
    out.write("\n");
  }
}

Mesh read_off(std::string_view text, const std::filesystem::path& path) {
  TextReader r(text, path);
  if (!next_data_line(r)) fail_reading(path, "empty file (expected an OFF header)");
  const std::string_view magic = r.token();
  if (magic != "OFF")
    r.fail("expected the header 'OFF', got '" + std::string(magic) + "'" +
           (magic.size() > 3 && magic.substr(magic.size() - 3) == "OFF" ? " (OFF variants are not supported)" : ""));
  std::string_view counts_text = r.token();
  if (counts_text.empty()) {  // counts on their own line (the usual layout)
    if (!next_data_line(r)) r.fail("missing the vertex, face and edge counts");
    counts_text = r.token();
  }
  const std::uint64_t nv = r.to_count(counts_text, "vertex count");
  const std::uint64_t nf = r.next_count("face count");
  if (nv > 0xffffffffu) r.fail("vertex count " + std::to_string(nv) + " exceeds 32-bit indices");
  Mesh mesh;
  mesh.vertices.reserve(nv);
  for (std::uint64_t v = 0; v < nv; ++v) {
    if (!next_data_line(r))
      fail_reading(path, "the header announces " + std::to_string(nv) + " vertices, the file ends after " +
                             std::to_string(v));
    const double x = r.next_double("x coordinate"), y = r.next_double("y coordinate"),
                 z = r.next_double("z coordinate");
    mesh.vertices.push_back({x, y, z});
  }
  std::vector<std::uint32_t> corners;
  for (std::uint64_t f = 0; f < nf; ++f) {
    if (!next_data_line(r))
      fail_reading(path, "the header announces " + std::to_string(nf) + " faces, the file ends after " +
                             std::to_string(f));
    const std::uint64_t n = r.next_count("corner count");
    if (n < 3) r.fail("a face needs at least 3 corners, got " + std::to_string(n));
    corners.clear();
    for (std::uint64_t k = 0; k < n; ++k) {
      const std::uint64_t i = r.next_count("vertex index");
      if (i >= nv) r.fail("vertex index " + std::to_string(i) + " is not below the vertex count " + std::to_string(nv));
      corners.push_back(static_cast<std::uint32_t>(i));
    }
    add_polygon(mesh, corners.data(), corners.size());
  }
  if (next_data_line(r)) r.fail("data after the " + std::to_string(nf) + " faces the header announces");
  return mesh;
}

}  // namespace genmod::mesh_io
