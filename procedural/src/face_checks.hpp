// Checks of tool inputs shared by the mesh tools (private to the layer).
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <string>

namespace genmod {

// Throws std::invalid_argument "<tool>: face k is not in the mesh" unless every handle of
// `faces` is valid, in range and not deleted.
void require_faces_in_mesh(const PolyMesh& mesh, const FaceList& faces, const std::string& tool);
// Throws std::invalid_argument "<tool>: <what> is not finite / is zero".
void require_finite_nonzero(const Vec3& v, const std::string& tool, const std::string& what);

}  // namespace genmod
