#include "face_checks.hpp"

#include <cmath>
#include <stdexcept>

namespace genmod {

void require_faces_in_mesh(const PolyMesh& mesh, const FaceList& faces, const std::string& tool) {
  for (PolyMesh::FaceHandle f : faces) {
    const bool present = f.is_valid() && f.idx() < static_cast<int>(mesh.n_faces()) &&
                         !(mesh.has_face_status() && mesh.status(f).deleted());
    if (!present) throw std::invalid_argument(tool + ": face " + std::to_string(f.idx()) + " is not in the mesh");
  }
}

void require_finite_nonzero(const Vec3& v, const std::string& tool, const std::string& what) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(v[a])) throw std::invalid_argument(tool + ": " + what + " is not finite");
  if (v.sqrnorm() == 0.0) throw std::invalid_argument(tool + ": " + what + " is zero");
}

}  // namespace genmod
