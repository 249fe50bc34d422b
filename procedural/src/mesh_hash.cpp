#include "genmod/procedural/mesh_hash.hpp"

#include "face_labels.hpp"

#include <bit>
#include <cstdio>

namespace genmod {
namespace {

// FNV-1a and a multiply-xorshift mix over the same 64-bit words.
struct Hasher {
  std::uint64_t fnv = 0xcbf29ce484222325ULL, mix = 0x9E3779B97F4A7C15ULL;
  void word(std::uint64_t w) {
    for (int i = 0; i < 8; ++i) fnv = (fnv ^ ((w >> (8 * i)) & 0xFF)) * 0x100000001B3ULL;
    mix ^= w + 0x9E3779B97F4A7C15ULL + (mix << 6) + (mix >> 2);
    mix = (mix ^ (mix >> 31)) * 0xBF58476D1CE4E5B9ULL;
  }
};

}  // namespace

std::string MeshHash::hex() const {
  char text[40];
  std::snprintf(text, sizeof text, "%016llx%016llx", static_cast<unsigned long long>(a),
                static_cast<unsigned long long>(b));
  return text;
}

MeshHash content_hash(const PolyMesh& mesh) {
  Hasher h;
  h.word(mesh.n_vertices());
  for (PolyMesh::VertexHandle v : mesh.vertices()) {
    h.word(static_cast<std::uint64_t>(v.idx()));
    const Vec3& p = mesh.point(v);
    for (int a = 0; a < 3; ++a) h.word(std::bit_cast<std::uint64_t>(p[a]));
  }
  h.word(mesh.n_faces());
  const auto labels = detail::find_label_property(mesh);
  for (PolyMesh::FaceHandle f : mesh.faces()) {
    h.word(~static_cast<std::uint64_t>(f.idx()));  // face separator
    for (PolyMesh::VertexHandle v : mesh.fv_range(f)) h.word(static_cast<std::uint64_t>(v.idx()));
    const std::string& label = detail::label_of(mesh, labels, f);
    h.word(label.size());
    for (unsigned char c : label) h.word(c);
  }
  return {h.fnv, h.mix};
}

}  // namespace genmod
