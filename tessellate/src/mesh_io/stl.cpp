// STL: written as ASCII with round-trip doubles; read as ASCII or binary (float32). STL lists
// each triangle's corners, so reading merges corners at bitwise-equal positions.
#include "mesh_io_internal.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace genmod::mesh_io {
namespace {

// Vertex numbering by exact position, in the order of first appearance.
class Welder {
 public:
  explicit Welder(Mesh& mesh, std::size_t expected_vertices = 0) : mesh_(mesh) { ids_.reserve(expected_vertices); }
  std::uint32_t index(const std::array<double, 3>& p) {
    const Key key{std::bit_cast<std::uint64_t>(p[0]), std::bit_cast<std::uint64_t>(p[1]),
                  std::bit_cast<std::uint64_t>(p[2])};
    const auto [it, added] = ids_.try_emplace(key, static_cast<std::uint32_t>(mesh_.vertices.size()));
    if (added) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
      std::uint64_t h = 0x9e3779b97f4a7c15u;
      for (std::uint64_t v : k) h = (h ^ v) * 0x100000001b3u + (h >> 29);
      return static_cast<std::size_t>(h);
    }
  };
  Mesh& mesh_;
  std::unordered_map<Key, std::uint32_t, KeyHash> ids_;
};

std::array<double, 3> unit_normal(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                  const std::array<double, 3>& c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(length > 0) || !std::isfinite(length)) return {0, 0, 0};
  for (double& x : n) x /= length;
  return n;
}

std::uint32_t little_endian_u32(const char* p) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(p[k]);
  return v;
}

float little_endian_float(const char* p) { return std::bit_cast<float>(little_endian_u32(p)); }

bool is_binary_stl(std::string_view bytes) {
  if (bytes.size() < 84) return false;
  const std::uint64_t n = little_endian_u32(bytes.data() + 80);
  return 84 + 50 * n == bytes.size();
}

Mesh read_binary_stl(std::string_view bytes, const std::filesystem::path& path) {
  const std::size_t n = little_endian_u32(bytes.data() + 80);
  Mesh mesh;
  Welder welder(mesh, n / 2 + 3);  // a closed mesh has about half as many vertices as triangles
  mesh.triangles.reserve(n);
  for (std::size_t t = 0; t < n; ++t) {
    const char* facet = bytes.data() + 84 + 50 * t;
    std::array<std::uint32_t, 3> tri{};
    for (std::size_t k = 0; k < 3; ++k) {
      std::array<double, 3> p{};
      for (std::size_t a = 0; a < 3; ++a) {
        p[a] = little_endian_float(facet + 12 + 12 * k + 4 * a);
        if (!std::isfinite(p[a]))
          fail_reading(path, "binary STL triangle " + std::to_string(t) + " has a coordinate that is not finite");
      }
      tri[k] = welder.index(p);
    }
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

Mesh read_ascii_stl(std::string_view text, const std::filesystem::path& path) {
  TextReader r(text, path);
  // The next token of the file, across lines; empty at its end.
  auto next = [&r]() -> std::string_view {
    for (;;) {
      const std::string_view t = r.token();
      if (!t.empty()) return t;
      if (!r.next_line()) return {};
    }
  };
  auto expect = [&](std::string_view word, std::string_view got) {
    if (got != word)
      r.fail("expected " + quoted(word) + ", got " + (got.empty() ? std::string("the end of the file") : quoted(got)));
  };
  r.next_line();
  expect("solid", next());
  (void)r.rest_of_line();  // the solid's name
  r.next_line();
  Mesh mesh;
  Welder welder(mesh);
  std::vector<std::uint32_t> corners;
  for (std::string_view t = next(); t != "endsolid"; t = next()) {
    expect("facet", t);
    expect("normal", next());
    for (int k = 0; k < 3; ++k) (void)r.to_double(next(), "normal component");
    expect("outer", next());
    expect("loop", next());
    corners.clear();
    for (t = next(); t == "vertex"; t = next()) {
      std::array<double, 3> p{};
      for (double& x : p) x = r.to_double(next(), "vertex coordinate");
      corners.push_back(welder.index(p));
    }
    expect("endloop", t);
    if (corners.size() < 3) r.fail("a facet needs at least 3 vertices, got " + std::to_string(corners.size()));
    add_polygon(mesh, corners.data(), corners.size());
    expect("endfacet", next());
  }
  return mesh;
}

}  // namespace

void write_stl(const Mesh& mesh, OutputFile& out) {
  out.write("solid genmod\n");
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.vertices[t[0]];
    const auto& b = mesh.vertices[t[1]];
    const auto& c = mesh.vertices[t[2]];
    out.write("facet normal ");
    out.write_point(unit_normal(a, b, c));
    out.write("\n outer loop\n");
    for (const auto* p : {&a, &b, &c}) {
      out.write("  vertex ");
      out.write_point(*p);
      out.write("\n");
    }
    out.write(" endloop\nendfacet\n");
  }
  out.write("endsolid genmod\n");
}

Mesh read_stl(std::string_view bytes, const std::filesystem::path& path) {
  if (is_binary_stl(bytes)) return read_binary_stl(bytes, path);
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && bytes.substr(first, 5) == "solid") return read_ascii_stl(bytes, path);
  if (bytes.size() >= 84)
    fail_reading(path, "neither ASCII STL (no 'solid' at the start) nor binary STL (" + std::to_string(bytes.size()) +
                           " bytes, but the header announces " + std::to_string(little_endian_u32(bytes.data() + 80)) +
                           " triangles = " + std::to_string(84 + 50 * std::uint64_t{little_endian_u32(bytes.data() + 80)}) +
                           " bytes)");
  fail_reading(path, "neither ASCII STL (no 'solid' at the start) nor binary STL (shorter than its 84-byte header)");
}

}  // namespace genmod::mesh_io
