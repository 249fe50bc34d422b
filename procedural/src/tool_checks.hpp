// Input checks shared by the mesh tools: each names the tool in its message.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::detail {

// Throws unless every face is a live face of `mesh`, listed once.
// Cost proportional to the list, not the mesh (a small selection of a big mesh is checked in
// O(k log k)): repeats are found by sorting the indices.
inline void check_faces(const PolyMesh& mesh, const FaceList& faces, const char* tool) {
  for (PolyMesh::FaceHandle f : faces) {
    if (!f.is_valid() || f.idx() >= static_cast<int>(mesh.n_faces()))
      throw std::invalid_argument(std::string(tool) + ": face " + std::to_string(f.idx()) +
                                  " is not in the mesh");
    if (mesh.has_face_status() && mesh.status(f).deleted())
      throw std::invalid_argument(std::string(tool) + ": face " + std::to_string(f.idx()) +
                                  " is deleted");
  }
  std::vector<int> indices;
  indices.reserve(faces.size());
  for (PolyMesh::FaceHandle f : faces) indices.push_back(f.idx());
  std::sort(indices.begin(), indices.end());
  const auto repeat = std::adjacent_find(indices.begin(), indices.end());
  if (repeat != indices.end())
    throw std::invalid_argument(std::string(tool) + ": face " + std::to_string(*repeat) + " is listed twice");
}

inline void check_finite(const Vec3& v, const char* tool, const char* what) {
  if (!(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])))
    throw std::invalid_argument(std::string(tool) + ": " + what + " is not finite");
}

}  // namespace genmod::detail
