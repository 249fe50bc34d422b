#include "genmod/procedural/stitching.hpp"

#include "face_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace genmod {
namespace {

using VH = PolyMesh::VertexHandle;
using FH = PolyMesh::FaceHandle;

FaceList sorted_unique(FaceList faces) {
  std::sort(faces.begin(), faces.end(), [](FH x, FH y) { return x.idx() < y.idx(); });
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

// Membership in a selection, by binary search in its sorted faces: the cost of a bridge is its
// selections' size (times a log), not the mesh's (the luggage bridges 30 small cells on a
// mesh of 35,000 faces; a mask per call was a pass over the whole mesh).
class FaceSetIndex {
 public:
  explicit FaceSetIndex(const FaceList& sorted) : sorted_(sorted) {}
  // The position of `f` in the selection, or -1.
  long position(FH f) const {
    if (!f.is_valid()) return -1;
    const auto it = std::lower_bound(sorted_.begin(), sorted_.end(), f, [](FH x, FH y) { return x.idx() < y.idx(); });
    return it != sorted_.end() && *it == f ? it - sorted_.begin() : -1;
  }
  bool contains(FH f) const { return position(f) >= 0; }

 private:
  const FaceList& sorted_;
};

// The vertices of sorted faces, as a sorted index list.
std::vector<int> vertices_of(const PolyMesh& mesh, const FaceList& faces) {
  std::vector<int> vertices;
  for (FH f : faces)
    for (auto v : mesh.fv_range(f)) vertices.push_back(v.idx());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

bool contains(const std::vector<int>& sorted, int value) { return std::binary_search(sorted.begin(), sorted.end(), value); }

// The boundary loop of a disk-like selection (`faces` sorted by index, no repeats), in the
// winding of its faces, starting at its smallest vertex index. Throws std::invalid_argument
// "<tool>: <name> ..." otherwise.
std::vector<VH> disk_boundary_loop(const PolyMesh& mesh, const FaceList& faces, const std::string& tool,
                                   const std::string& name) {
  const FaceSetIndex in(faces);
  auto fail = [&](const std::string& why) { throw std::invalid_argument(tool + ": " + name + " is not disk-like (" + why + ")"); };
  std::map<int, int> next;  // boundary half-edges, from vertex -> to vertex
  std::vector<int> vertices, edges;
  for (FH f : faces)
    for (auto h : mesh.fh_range(f)) {
      vertices.push_back(mesh.from_vertex_handle(h).idx());
      edges.push_back(mesh.edge_handle(h).idx());
      const FH across = mesh.face_handle(mesh.opposite_halfedge_handle(h));
      if (!across.is_valid()) fail("it touches an open boundary of the mesh");
      if (in.contains(across)) continue;
      if (!next.emplace(mesh.from_vertex_handle(h).idx(), mesh.to_vertex_handle(h).idx()).second)
        fail("its boundary passes twice through vertex " + std::to_string(mesh.from_vertex_handle(h).idx()));
    }
  if (next.empty()) fail("it has no boundary: it is a whole closed component");
  std::vector<VH> loop;
  int v = next.begin()->first;
  do {
    loop.push_back(VH(v));
    auto it = next.find(v);
    if (it == next.end()) fail("its boundary is not closed");
    v = it->second;
  } while (v != next.begin()->first && loop.size() <= next.size());
  if (loop.size() != next.size()) fail("it has more than one boundary loop");
  // Edge-connected: a flood over shared edges reaches every face.
  std::vector<char> reached(faces.size(), 0);  // by position in `faces`
  std::vector<FH> stack{faces.front()};
  reached[0] = 1;
  std::size_t count = 0;
  while (!stack.empty()) {
    FH f = stack.back();
    stack.pop_back();
    ++count;
    for (auto h : mesh.fh_range(f)) {
      const long g = in.position(mesh.face_handle(mesh.opposite_halfedge_handle(h)));
      if (g >= 0 && !reached[g]) {
        reached[g] = 1;
        stack.push_back(faces[g]);
      }
    }
  }
  if (count != faces.size()) fail("its faces are not edge-connected");
  std::sort(vertices.begin(), vertices.end());
  std::sort(edges.begin(), edges.end());
  const long chi = static_cast<long>(std::unique(vertices.begin(), vertices.end()) - vertices.begin()) -
                   static_cast<long>(std::unique(edges.begin(), edges.end()) - edges.begin()) +
                   static_cast<long>(faces.size());
  if (chi != 1) fail("Euler characteristic " + std::to_string(chi) + ", a disk has 1");
  return loop;
}

double triangle_area2(const PolyMesh& mesh, VH x, VH y, VH z) {
  return OpenMesh::cross(mesh.point(y) - mesh.point(x), mesh.point(z) - mesh.point(x)).norm();
}

// The zipper between two loops whose consecutive vertices are free half-edges (no face yet):
// A walked forward, B backward. Returns the triangles; the mesh is not changed. Sets
// `degenerate_left` when a zero-area triangle could not be avoided.
std::vector<std::array<VH, 3>> plan_zipper(const PolyMesh& mesh, const std::vector<VH>& loop_a,
                                           const std::vector<VH>& loop_b, bool& degenerate_left) {
  degenerate_left = false;
  const std::size_t n = loop_a.size(), m = loop_b.size();
  std::size_t best_i = 0, best_j = 0;
  double best = std::numeric_limits<double>::infinity();
  double size2 = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      const double d2 = (mesh.point(loop_a[i]) - mesh.point(loop_b[j])).sqrnorm();
      size2 = std::max(size2, d2);
      if (d2 < best && !(d2 >= best - 1e-9 * best)) {  // near ties keep the first pair (scale-independent)
        best = d2;
        best_i = i;
        best_j = j;
      }
    }
  auto a = [&](std::size_t k) { return loop_a[(best_i + k) % n]; };
  auto c = [&](std::size_t k) { return loop_b[(best_j + m - k % m) % m]; };
  const double degenerate = 1e-14 * size2;
  std::vector<std::array<VH, 3>> triangles;
  std::size_t i = 0, k = 0;
  // The rungs the strip starts with, (a(0), c(0..k_first)) and (a(0..i_first), c(0)): a step
  // that closed a loop onto one of them again would give that rung a third face (a loop used
  // up while the other is still at its first vertex: a fan round one vertex).
  std::size_t i_first = 0, k_first = 0;
  while (i < n || k < m) {
    if (i == 0) k_first = k;
    if (k == 0) i_first = i;
    const std::array<VH, 3> along_a{a(i), a(i + 1), c(k)}, along_b{a(i), c(k + 1), c(k)};
    bool take_a;
    if (i == n) {
      take_a = false;
    } else if (k == m) {
      take_a = true;
    } else {
      // Near ties (within 1e-9 relative, far above rounding) count as ties, so that a scaled
      // or moved copy of the same loops is joined the same way.
      const double along_a_rung = (mesh.point(a(i + 1)) - mesh.point(c(k))).sqrnorm();
      const double along_b_rung = (mesh.point(a(i)) - mesh.point(c(k + 1))).sqrnorm();
      take_a = along_a_rung <= along_b_rung + 1e-9 * std::max(along_a_rung, along_b_rung);
      const bool a_flat = triangle_area2(mesh, along_a[0], along_a[1], along_a[2]) <= degenerate;
      const bool b_flat = triangle_area2(mesh, along_b[0], along_b[1], along_b[2]) <= degenerate;
      if (take_a && a_flat && !b_flat) take_a = false;
      if (!take_a && b_flat && !a_flat) take_a = true;
      const bool a_repeats = i + 1 == n && k == k_first, b_repeats = k + 1 == m && i == i_first;
      if (take_a && a_repeats && !b_repeats) take_a = false;
      if (!take_a && b_repeats && !a_repeats) take_a = true;
    }
    const std::array<VH, 3>& t = take_a ? along_a : along_b;
    if (triangle_area2(mesh, t[0], t[1], t[2]) <= degenerate) degenerate_left = true;
    triangles.push_back(t);
    (take_a ? i : k) += 1;
  }
  return triangles;
}

void require_status(PolyMesh& mesh) {
  mesh.request_face_status();
  mesh.request_edge_status();
  mesh.request_halfedge_status();
  mesh.request_vertex_status();
}

FaceList add_triangles(PolyMesh& mesh, const std::vector<std::array<VH, 3>>& triangles, const std::string& label,
                       const std::string& tool) {
  FaceList added;
  for (const auto& t : triangles) {
    const FH f = mesh.add_face(t[0], t[1], t[2]);
    if (!f.is_valid()) throw std::logic_error(tool + ": OpenMesh refused a joining triangle");
    set_face_label(mesh, f, label);
    added.push_back(f);
  }
  return added;
}

}  // namespace

FaceList bridge(PolyMesh& mesh, const FaceList& sel_a_in, const FaceList& sel_b_in, const std::string& label) {
  if (sel_a_in.empty() || sel_b_in.empty()) return {};
  const std::string tool = "bridge";
  require_faces_in_mesh(mesh, sel_a_in, tool);
  require_faces_in_mesh(mesh, sel_b_in, tool);
  const FaceList sel_a = sorted_unique(sel_a_in), sel_b = sorted_unique(sel_b_in);
  const FaceSetIndex in_a(sel_a);
  for (FH f : sel_b)
    if (in_a.contains(f)) throw std::invalid_argument("bridge: the selections share face " + std::to_string(f.idx()));
  const std::vector<VH> loop_a = disk_boundary_loop(mesh, sel_a, tool, "selection A");
  const std::vector<VH> loop_b = disk_boundary_loop(mesh, sel_b, tool, "selection B");
  const std::vector<int> vertices_a = vertices_of(mesh, sel_a);
  const auto vertex_in_a = [&](VH v) { return contains(vertices_a, v.idx()); };
  for (FH f : sel_b)
    for (auto v : mesh.fv_range(f))
      if (vertex_in_a(v)) throw std::invalid_argument("bridge: the selections share vertex " + std::to_string(v.idx()));
  bool degenerate = false;
  const auto triangles = plan_zipper(mesh, loop_a, loop_b, degenerate);
  // A rung between the loops that is already an edge would get a third face.
  for (const auto& t : triangles)
    for (int e = 0; e < 3; ++e)
      if (vertex_in_a(t[e]) != vertex_in_a(t[(e + 1) % 3]) && mesh.find_halfedge(t[e], t[(e + 1) % 3]).is_valid())
        throw std::invalid_argument("bridge: vertices " + std::to_string(t[e].idx()) + " and " +
                                    std::to_string(t[(e + 1) % 3].idx()) + " of the two loops are already joined by an edge");
  if (degenerate) throw std::invalid_argument("bridge: the loops would be joined by a zero-area triangle");
  require_status(mesh);
  for (FH f : sel_a) mesh.delete_face(f, true);
  for (FH f : sel_b) mesh.delete_face(f, true);
  return add_triangles(mesh, triangles, label, tool);
}

PolyMesh stitch(const PolyMesh& a, const FaceList& sel_a_in, const PolyMesh& b, const FaceList& sel_b_in,
                const std::string& label) {
  const std::string tool = "stitch";
  require_faces_in_mesh(a, sel_a_in, tool);
  require_faces_in_mesh(b, sel_b_in, tool);
  const FaceList sel_a = sorted_unique(sel_a_in), sel_b = sorted_unique(sel_b_in);
  const bool join = !sel_a.empty() && !sel_b.empty();
  std::vector<VH> loop_a, loop_b;
  if (join) {
    loop_a = disk_boundary_loop(a, sel_a, tool, "selection A");
    loop_b = disk_boundary_loop(b, sel_b, tool, "selection B");
  }
  PolyMesh out;
  // Copies the given faces of `source` (index order) with the vertices they use (index order).
  auto copy_faces = [&](const PolyMesh& source, const FaceList& faces) {
    std::vector<int> used;
    for (FH f : faces)
      for (auto v : source.fv_range(f)) used.push_back(v.idx());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::map<int, VH> map;
    for (int v : used) map[v] = out.add_vertex(source.point(VH(v)));
    for (FH f : faces) {
      std::vector<VH> ring;
      for (auto v : source.fv_range(f)) ring.push_back(map.at(v.idx()));
      set_face_label(out, out.add_face(ring), face_label(source, f));
    }
    return map;
  };
  const auto map_a = copy_faces(a, sel_a);
  const FaceSetIndex in_b(sel_b);
  FaceList kept_b;
  for (FH f : b.faces())
    if (!in_b.contains(f)) kept_b.push_back(f);
  const auto map_b = copy_faces(b, kept_b);
  if (!join) return out;
  // The free half-edges of a's part run against sel_a's winding; those of b's hole with it.
  std::vector<VH> free_a, free_b;
  for (auto it = loop_a.rbegin(); it != loop_a.rend(); ++it) free_a.push_back(map_a.at(it->idx()));
  for (VH v : loop_b) free_b.push_back(map_b.at(v.idx()));
  bool degenerate = false;
  const auto triangles = plan_zipper(out, free_a, free_b, degenerate);
  if (degenerate) throw std::invalid_argument("stitch: the loops would be joined by a zero-area triangle");
  add_triangles(out, triangles, label, tool);
  return out;
}

}  // namespace genmod
