// Builds a PolyMesh from flat arrays, the last step of the tools that change topology.
//
// Why rebuild instead of editing in place: OpenMesh's add_face into a mesh with holes can refuse
// faces depending on insertion order (complex vertices); building a fresh mesh from a
// manifold face list in index order is robust, deterministic and garbage-free. The price is
// that handles of the old mesh are invalid afterwards (named sets are recomputed from labels).
//
// Why the rebuild also costs the whole mesh, and why it stays (issue 12): the rebuilt mesh is
// canonical. Its edges come in order of first use by the faces, each oriented as in its first
// face, and each vertex's outgoing half-edge is what add_face leaves; later tools read that
// order (sqrt(2) emits faces in edge order and sums a vertex's face points in its fan order
// from the outgoing half-edge), so every model's bytes depend on it. An in-place extrusion or
// sqrt(2) step (delete the set's faces, append the new ones) would cost the selection but
// leave old edges where they were and other outgoing half-edges: the same surface with other
// bytes. Making it byte-identical needs those tools to read a canonical order that does not
// come from the rebuild (or a faster rebuild that reproduces add_face's result exactly).
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include "face_labels.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace genmod::detail {

struct MeshParts {
  std::vector<Vec3> points;
  std::vector<int> corners;        // vertex indices of all faces, concatenated
  std::vector<int> face_start{0};  // face i = corners[face_start[i] .. face_start[i+1])
  std::vector<std::string> labels; // one per face

  void add_face(std::initializer_list<int> ring, const std::string& label) {
    corners.insert(corners.end(), ring.begin(), ring.end());
    face_start.push_back(static_cast<int>(corners.size()));
    labels.push_back(label);
  }
};

// Vertices keep their index; faces keep their order. Throws std::invalid_argument (naming
// `tool`) if OpenMesh refuses a face: the input made the result non-manifold (an extruded set
// whose faces touch at a vertex only).
inline PolyMesh build_mesh(const MeshParts& parts, const char* tool) {
  PolyMesh mesh;
  const std::size_t n_faces = parts.labels.size();
  mesh.reserve(parts.points.size(), parts.corners.size(), n_faces);
  for (const Vec3& p : parts.points) mesh.add_vertex(p);
  std::vector<PolyMesh::VertexHandle> ring;
  OpenMesh::FPropHandleT<std::string> labels;  // added at the first label (none: no property)
  for (std::size_t i = 0; i < n_faces; ++i) {
    ring.clear();
    for (int c = parts.face_start[i]; c < parts.face_start[i + 1]; ++c)
      ring.push_back(PolyMesh::VertexHandle(parts.corners[c]));
    PolyMesh::FaceHandle f = mesh.add_face(ring);
    if (!f.is_valid()) throw std::invalid_argument(std::string(tool) +
                                  ": the result would not be a manifold (faces of the set touch at a vertex only?)");
    if (parts.labels[i].empty()) continue;
    if (!labels.is_valid()) labels = label_property(mesh);
    mesh.property(labels, f) = parts.labels[i];
  }
  return mesh;
}

}  // namespace genmod::detail
