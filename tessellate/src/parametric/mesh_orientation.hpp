// Orientation from the geometry: triangles made consistent across shared edges, then each
// closed component turned so that its signed volume is positive (normals point out).
#pragma once

#include "genmod/tessellate/mesh.hpp"

#include <cstddef>

namespace genmod::parametric {

struct OrientationReport {
  std::size_t boundary_edges = 0;      // edges of one triangle
  std::size_t flipped_components = 0;  // closed components turned outward
  std::size_t conflicts = 0;           // edges left inconsistent (a non-orientable piece)
};

OrientationReport orient_outward(Mesh& mesh);

}  // namespace genmod::parametric
