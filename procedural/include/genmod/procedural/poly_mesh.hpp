// PolyMesh: the polygon mesh of the procedural layer (OpenMesh's half-edge PolyMesh with double
// coordinates), with a label per face and conversions to genmod's triangle Mesh.
//
// Morkel's tools work on polygon meshes whose faces carry labels ("torso", "leg") from which
// named face sets are recomputed; OpenMesh replaces her winged-edge structure. Coordinates are
// doubles so that a tool's result is bitwise reproducible and a triangulation written to a
// file is the mesh that was built.
//
// Determinism: every tool visits faces, edges and vertices in index order (never by pointer),
// so the same input gives the same indices and the same bytes.
#pragma once

#include "genmod/tessellate/triangle_mesh.hpp"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace genmod {

struct PolyMeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<PolyMeshTraits>;
using Vec3 = OpenMesh::Vec3d;
// A list of faces, the tools' selections: in index order, without repeats.
using FaceList = std::vector<PolyMesh::FaceHandle>;

// Face labels: a string per face (empty when unlabelled), stored as an OpenMesh property named
// "genmod:label", so copying the mesh copies them.
void set_face_label(PolyMesh& mesh, PolyMesh::FaceHandle face, const std::string& label);
std::string face_label(const PolyMesh& mesh, PolyMesh::FaceHandle face);
// The faces carrying `label`, in index order.
FaceList faces_labelled(const PolyMesh& mesh, const std::string& label);

// The axis-aligned box [lo, hi] as six outward quads (8 vertices, 12 edges), each face labelled
// `label`. Throws std::invalid_argument unless lo < hi on every axis (and all are finite).
PolyMesh make_box(const Vec3& lo, const Vec3& hi, const std::string& label = "");

struct MeshCounts {
  std::size_t vertices = 0, edges = 0, faces = 0;
  bool operator==(const MeshCounts&) const = default;
};
// Counts of the mesh's non-deleted elements.
MeshCounts counts(const PolyMesh& mesh);

// True when every edge has a face on both sides and every vertex's faces form one fan (a
// closed 2-manifold; OpenMesh's half-edge structure already refuses non-manifold edges).
bool is_closed_manifold(const PolyMesh& mesh);

// All faces, in index order.
FaceList all_faces(const PolyMesh& mesh);
// The axis-aligned bounds of the vertices of `faces` (an empty list gives lo = +inf, hi = -inf).
std::array<Vec3, 2> bounds(const PolyMesh& mesh, const FaceList& faces);

// Triangulates every polygon for genmod's Mesh: a face of n vertices becomes the n - 2
// triangles of the fan from its first vertex (faces are convex in the procedural tools'
// output; a non-convex face would need another triangulation). Vertices keep their indices
// (after garbage collection of deleted elements), triangles follow face order.
Mesh to_triangle_mesh(const PolyMesh& mesh);

}  // namespace genmod
