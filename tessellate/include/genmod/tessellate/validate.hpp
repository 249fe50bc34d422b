// Mesh validation: is a triangle mesh one a user can use as it is written?
//
// validate() reads the mesh as plain arrays (no welding, no repair), so a mesh that is closed
// only after merging duplicate vertices is reported open. It checks
//   * combinatorics: boundary edges (in one triangle), non-manifold edges (in three or more),
//     non-manifold vertices (whose triangles do not form one fan), edges used twice in the same
//     direction (inconsistent orientation), unused and coincident vertices, components and the
//     Euler characteristic V - E + F;
//   * geometry, with CGAL's exact predicates: degenerate triangles (a repeated index or three
//     collinear corners) and self-intersections (two triangles that meet anywhere except in
//     the vertices and edge they share), and, for a closed, manifold, oriented and
//     intersection-free mesh, whether every component is oriented outward (its normals point
//     away from the solid it bounds, nested components alternating) and the enclosed volume;
//   * optionally the distance to the true surface f = 0 of an implicit function (see
//     SurfaceDistance).
// CGAL lives in this layer's validation translation unit only.
//
// Example:
//   Mesh mesh = mesh_implicit(implicit_sphere(1.0), {Interval(-2, 2), Interval(-2, 2), Interval(-2, 2)},
//                             {.min_feature = 0.25}).mesh;
//   MeshValidity v = validate(mesh);
//   if (!v.valid()) std::cerr << describe(v);
#pragma once

#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/mesh.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace genmod {

// Distance of a mesh from the surface f = 0 of a scalar implicit function f(x, y, z).
//
// For each vertex v (and each sample point inside each triangle) the estimate is
// |f(v)| / |grad f(v)|. The bound is certified by a sign change: genmod looks for a point q
// on the ray from v along -sign(f(v)) grad f with f(q) of the other sign (or zero); the
// segment [v, q] crosses the surface, so the distance is at most |q - v|. Where that ray finds
// no sign change, or one farther than the estimate (near a kink or a crease of f the gradient
// can point away from the nearest surface), the 26 lattice directions (axes, face and body
// diagonals) are searched too and the nearest sign change kept. Points where none is found within `search_radius` are counted as
// uncertified (vertices also on their own). Signs are those of
// genmod's point evaluation (exact up to its rounding).
struct SurfaceDistance {
  std::size_t points = 0;                // vertices + triangle samples examined
  double max_vertex_bound = 0.0;         // largest certified bound over the vertices
  double max_vertex_estimate = 0.0;      // largest |f| / |grad f| over the vertices
  double max_face_bound = 0.0;           // same over the triangle samples
  double max_face_estimate = 0.0;
  double mean_face_estimate = 0.0;
  std::size_t uncertified = 0;           // points with no sign change found
  std::size_t uncertified_vertices = 0;  // of those, vertices
};

struct ComponentValidity {
  std::size_t triangles = 0;
  long euler_characteristic = 0;
  double volume = 0.0;   // signed volume enclosed (positive when oriented outward), if closed
  bool closed = false;
  int nesting_level = -1;  // 0 = outermost; -1 when not computed
  bool outward = false;    // computed only when MeshValidity::orientation_checked
};

struct MeshValidity {
  std::size_t vertices = 0, triangles = 0, edges = 0;
  std::size_t unused_vertices = 0;
  std::size_t coincident_vertices = 0;   // vertices at the same position as an earlier one
  std::size_t invalid_indices = 0;       // triangle corners that are not vertex indices
  std::size_t boundary_edges = 0;
  std::size_t nonmanifold_edges = 0;
  std::size_t nonmanifold_vertices = 0;
  std::size_t misoriented_edges = 0;     // manifold edges whose two triangles disagree in direction
  std::size_t degenerate_triangles = 0;
  std::size_t self_intersections = 0;    // intersecting triangle pairs (not counted if not checked)
  bool self_intersections_checked = false;
  std::size_t components = 0;            // connected through shared edges
  long euler_characteristic = 0;         // V - E + F over the used vertices
  double volume = 0.0;                   // signed volume sum over all triangles
  // Outward orientation is only well defined for a closed, manifold, oriented and
  // intersection-free mesh; for any other mesh orientation_checked is false.
  bool orientation_checked = false;
  bool outward = false;
  std::vector<ComponentValidity> component_info;
  bool has_surface_distance = false;
  SurfaceDistance surface;

  bool closed() const noexcept { return boundary_edges == 0 && invalid_indices == 0; }
  bool manifold() const noexcept { return nonmanifold_edges == 0 && nonmanifold_vertices == 0; }
  bool oriented() const noexcept { return misoriented_edges == 0; }
  // Closed, 2-manifold, consistently oriented, outward, no degenerate triangles and no
  // self-intersections (which must have been checked).
  bool valid() const noexcept {
    return closed() && manifold() && oriented() && degenerate_triangles == 0 && self_intersections_checked &&
           self_intersections == 0 && orientation_checked && outward && triangles > 0;
  }
};

struct ValidateOptions {
  bool check_self_intersections = true;
  // If set, the distance of the mesh from the surface f = 0 of this scalar tape of three
  // inputs (x, y, z) is measured. Triangle samples: `face_samples` points per triangle.
  const Tape* surface = nullptr;
  int face_samples = 3;
  double search_radius = 0.0;  // 0: 5% of the mesh's bounding-box diagonal
  int threads = 0;             // 0 = all cores
};

// Throws std::invalid_argument for a tape that is not scalar with three inputs, or
// face_samples outside [0, 64].
MeshValidity validate(const Mesh& mesh, const ValidateOptions& options = {});

// A human-readable report, one fact per line (used by `genmod check` and in test messages).
std::string describe(const MeshValidity& validity);

}  // namespace genmod
