// Mesh: the library's one triangle-mesh type, plain arrays.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace genmod {

// A triangle mesh as plain arrays. Triangles index `vertices`; a closed mesh shares its
// vertices between triangles (nothing is duplicated per face).
struct Mesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // vertex indices
};

}  // namespace genmod
