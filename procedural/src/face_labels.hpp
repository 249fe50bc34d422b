// The face label property (poly_mesh.hpp: "genmod:label") by handle, for loops over many faces:
// set_face_label / face_label look the property up by name on every call (a string compare
// per property) and face_label returns a copy, which showed up in the whole-mesh tools.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <string>

namespace genmod::detail {

inline constexpr const char* kLabelProperty = "genmod:label";

// The label property of `mesh`, added (every face unlabelled) when missing.
inline OpenMesh::FPropHandleT<std::string> label_property(PolyMesh& mesh) {
  OpenMesh::FPropHandleT<std::string> handle;
  if (!mesh.get_property_handle(handle, kLabelProperty)) mesh.add_property(handle, kLabelProperty);
  return handle;
}

// The label property of `mesh`, or an invalid handle when the mesh has none (no face labelled).
inline OpenMesh::FPropHandleT<std::string> find_label_property(const PolyMesh& mesh) {
  OpenMesh::FPropHandleT<std::string> handle;
  mesh.get_property_handle(handle, kLabelProperty);
  return handle;
}

// The label of `f` through a handle from find_label_property ("" when it is invalid).
inline const std::string& label_of(const PolyMesh& mesh, OpenMesh::FPropHandleT<std::string> labels,
                                   PolyMesh::FaceHandle f) {
  static const std::string none;
  return labels.is_valid() ? mesh.property(labels, f) : none;
}

}  // namespace genmod::detail
