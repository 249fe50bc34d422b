// append_mesh (affine.hpp): the assembly step of every model that attaches parts (the luggage's
// 30 legs, the human's limbs, the tree's branches), so it must cost little per element.
//
// Why not add_face per face: OpenMesh's add_face searches each corner's fan for the edge
// (find_halfedge), links boundary half-edges and adjusts outgoing half-edges; on the luggage
// that was half of a warm call. A part without deleted elements is already a consistent
// half-edge structure, so its arrays are copied with the indices shifted: new vertices, edges
// (half-edge 2e keeps its direction) and faces in the part's order, next/face/outgoing links
// offset. The result is the same mesh as the add_face loop gives: vertices and faces in the
// part's order, each face's vertex ring starting at the same corner (its half-edge is the
// part's), labels copied. Only the order of the new edges differs (the part's instead of
// first use), which no tool's output depends on (tools visit faces and vertices in index order).
#include "genmod/procedural/affine.hpp"

#include "face_labels.hpp"

#include <vector>

namespace genmod {
namespace {

bool has_deleted_elements(const PolyMesh& part) {
  if (part.has_vertex_status())
    for (std::size_t i = 0; i < part.n_vertices(); ++i)
      if (part.status(PolyMesh::VertexHandle(static_cast<int>(i))).deleted()) return true;
  if (part.has_edge_status())
    for (std::size_t i = 0; i < part.n_edges(); ++i)
      if (part.status(PolyMesh::EdgeHandle(static_cast<int>(i))).deleted()) return true;
  if (part.has_face_status())
    for (std::size_t i = 0; i < part.n_faces(); ++i)
      if (part.status(PolyMesh::FaceHandle(static_cast<int>(i))).deleted()) return true;
  return false;
}

// The general path: a part with deleted elements (holes in its index ranges) is rebuilt face
// by face from its live elements.
void append_by_faces(PolyMesh& mesh, const PolyMesh& part, const Affine& xf) {
  const auto labels = detail::label_property(mesh);
  const auto part_labels = detail::find_label_property(part);
  std::vector<PolyMesh::VertexHandle> map(part.n_vertices());
  for (PolyMesh::VertexHandle v : part.vertices()) map[v.idx()] = mesh.add_vertex(xf.apply(part.point(v)));
  std::vector<PolyMesh::VertexHandle> corners;
  for (PolyMesh::FaceHandle f : part.faces()) {
    corners.clear();
    for (PolyMesh::VertexHandle v : part.fv_range(f)) corners.push_back(map[v.idx()]);
    PolyMesh::FaceHandle g = mesh.add_face(corners);
    mesh.property(labels, g) = detail::label_of(part, part_labels, f);
  }
}

}  // namespace

void append_mesh(PolyMesh& mesh, const PolyMesh& part, const Affine& xf) {
  if (has_deleted_elements(part)) {
    append_by_faces(mesh, part, xf);
    return;
  }
  using VH = PolyMesh::VertexHandle;
  using HH = PolyMesh::HalfedgeHandle;
  using FH = PolyMesh::FaceHandle;
  const int v0 = static_cast<int>(mesh.n_vertices()), h0 = static_cast<int>(mesh.n_halfedges()),
            f0 = static_cast<int>(mesh.n_faces());
  const auto shifted = [](auto handle, int offset) {
    return handle.is_valid() ? decltype(handle)(handle.idx() + offset) : handle;
  };
  for (std::size_t i = 0; i < part.n_vertices(); ++i) mesh.add_vertex(xf.apply(part.point(VH(static_cast<int>(i)))));
  for (std::size_t e = 0; e < part.n_edges(); ++e) {
    const HH h(2 * static_cast<int>(e));
    mesh.new_edge(VH(part.from_vertex_handle(h).idx() + v0), VH(part.to_vertex_handle(h).idx() + v0));
  }
  for (std::size_t i = 0; i < part.n_faces(); ++i) mesh.new_face();
  for (std::size_t i = 0; i < part.n_halfedges(); ++i) {
    const HH h(static_cast<int>(i)), g(static_cast<int>(i) + h0);
    mesh.set_next_halfedge_handle(g, shifted(part.next_halfedge_handle(h), h0));
    mesh.set_face_handle(g, shifted(part.face_handle(h), f0));
  }
  for (std::size_t i = 0; i < part.n_vertices(); ++i) {
    const VH v(static_cast<int>(i));
    mesh.set_halfedge_handle(VH(v.idx() + v0), shifted(part.halfedge_handle(v), h0));
  }
  const auto labels = detail::label_property(mesh);
  const auto part_labels = detail::find_label_property(part);
  for (std::size_t i = 0; i < part.n_faces(); ++i) {
    const FH f(static_cast<int>(i));
    mesh.set_halfedge_handle(FH(f.idx() + f0), shifted(part.halfedge_handle(f), h0));
    mesh.property(labels, FH(f.idx() + f0)) = detail::label_of(part, part_labels, f);
  }
}

}  // namespace genmod
