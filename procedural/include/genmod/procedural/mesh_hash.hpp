// A content hash of a PolyMesh: vertex positions bitwise, each face's vertex index list in face
// order, and face labels. Two meshes with equal hashes are (up to 2^-128 collision odds) the
// same bytes; used by the cache key of in-out procedures and by reproducibility tests.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <cstdint>
#include <string>

namespace genmod {

struct MeshHash {
  std::uint64_t a = 0, b = 0;  // two independent 64-bit hashes of the same bytes
  bool operator==(const MeshHash&) const = default;
  std::string hex() const;
};

// Deleted elements are skipped; indices are the mesh's own (not garbage-collected).
MeshHash content_hash(const PolyMesh& mesh);

}  // namespace genmod
