// Meshing implicit solids f(x, y, z) < 0 into closed, manifold, intersection-free triangle
// meshes (the algorithm is described in tessellate/README.md).
//
// Example:
//   ImplicitSurface shape(implicit_sphere(1.0));                  // compiled once
//   ImplicitMeshSettings s{.min_feature = 0.1, .tolerance = 0.01};
//   ImplicitMesh m = mesh_implicit(shape, {Interval(-2, 2), Interval(-2, 2), Interval(-2, 2)}, s);
//   // m.mesh is closed and manifold; write_mesh(m.mesh, "ball.obj") saves it
//
// The mesh bounds the solid intersected with the box: where the solid crosses the box, the
// box faces close it. By construction (and checked by validate() in the tests) it is
//  1. closed (no boundary edges, as written: vertices are shared, never duplicated);
//  2. 2-manifold and consistently oriented with normals pointing out of the solid;
//  3. free of self-intersections and degenerate triangles;
//  4. within `tolerance` of the surface at every vertex: vertices are roots of f bracketed by a
//     sign change no wider than the tolerance (certified for functions continuous there; the
//     bracket widths are reported);
//  5. sharp at features: edges and corners of CSG shapes and of the box are placed by quadric
//     error minimization and kept (not cut off);
//  6. adaptive: cells are as large as the tolerance and the normal variation allow;
//  7. honest about topology: a surface cell is *certified* when interval bounds of the
//     gradient show that the normals inside it stay within a cone of half-angle below 90 degrees
//     (Plantinga and Vegter's small-normal-variation test), so the surface inside is a graph
//     without closed components or handles. Cells at `min_feature` where the test fails
//     (singular points, sharp features, parts thinner than a cell) are counted in the stats.
//
// Parallel on oneTBB; the output is bitwise the same for any thread count.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/box3.hpp"
#include "genmod/tessellate/mesh.hpp"

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace genmod {

// A scalar implicit function of (x, y, z) = (x(0), x(1), x(2)) compiled for meshing: its tape
// and the tapes of its symbolic gradient and Hessian (interval bounds of the gradient decide
// adaptivity and certify topology; the Hessian tightens them). Immutable; share one between
// threads and meshing runs.
class ImplicitSurface {
 public:
  // Throws std::invalid_argument if f is not scalar or depends on coordinates other than
  // x(0), x(1), x(2).
  explicit ImplicitSurface(const Fn& f);
  const Tape& value() const noexcept { return value_; }
  const Tape& gradient() const noexcept { return gradient_; }  // three outputs
  // The six second derivatives xx, xy, xz, yy, yz, zz: the gradient's mean value form.
  const Tape& hessian() const noexcept { return hessian_; }

 private:
  Tape value_, gradient_, hessian_;
};

struct ImplicitMeshSettings {
  // Smallest cell edge length: cells are never split below it. Required, > 0.
  double min_feature = 0.0;
  // Largest distance of a vertex from the surface, and the target distance of the faces
  // (estimated at face samples; cells whose estimate exceeds it are split). 0 = min_feature.
  double tolerance = 0.0;
  // Largest edge of a cell that contains surface. 0 = the box's largest side / 8.
  double max_cell = 0.0;
  // Feature points on cell faces and quadric-placed cell vertices (sharp edges and corners).
  // Off: cell vertices are placed on the surface near the centroid of their loop.
  bool sharp_features = true;
  // Two normals at a cell face's crossings closer than this angle (radians) are one smooth
  // piece; wider, and a feature point is put where their tangent lines meet.
  double feature_angle = 0.5;
  // Rounds of re-splitting cells that fail the accuracy or single-loop checks.
  int max_rounds = 16;
  // Limits, each reported in ImplicitMeshStats::limits_hit when reached (the mesh stays
  // closed, manifold and intersection-free, only coarser): octree cells, bytes held by the
  // octree and its pruned per-cell tapes, triangles, seconds.
  std::size_t max_cells = 50'000'000;
  std::size_t max_memory = std::size_t{8} << 30;
  std::size_t max_triangles = 100'000'000;
  double max_seconds = 0.0;  // 0 = no time limit
  // The caller's stop request (not owned; null = none): when it becomes true the mesher stops
  // splitting, as when time is up, and reports "cancelled". Python's Ctrl-C sets it.
  const std::atomic<bool>* cancel = nullptr;
  int threads = 0;           // 0 = all cores
  // Called now and then with the fraction done (0..1), from the calling thread.
  std::function<void(double)> progress = nullptr;
};

struct ImplicitMeshStats {
  std::size_t interval_evaluations = 0;  // octree cells classified by interval arithmetic
  std::size_t leaves = 0;                // octree leaves
  std::size_t inside_leaves = 0, outside_leaves = 0, surface_cells = 0;
  int min_surface_level = 0, max_surface_level = 0;  // octree depth of surface cells
  double smallest_cell = 0.0, largest_surface_cell = 0.0;
  std::size_t certified_cells = 0;       // surface cells where the normal-cone test held
  std::size_t uncertified_cells = 0;     // surface cells at min_feature where it failed
  // Surface cells where the gradient formula could not be bounded (its derivative has an
  // error, e.g. 0/0 in |max(q, 0)|): split by the meshing checks only, topology not certified.
  std::size_t unbounded_gradient_cells = 0;
  std::size_t multi_loop_cells = 0;      // cells meshed by the tetrahedral fallback
  std::size_t inaccurate_cells = 0;      // cells whose face estimate stayed above tolerance
  std::size_t folded_cells = 0;          // cells with a triangle facing against the normal
  // Cells split after meshing, over all rounds, by reason (a cell may count twice).
  std::size_t splits_for_loops = 0, splits_for_accuracy = 0, splits_for_folds = 0;
  std::size_t feature_points = 0;        // face feature points
  int rounds = 0;                        // meshing rounds done
  std::size_t cell_meshings = 0;         // cells meshed, over all rounds
  double max_vertex_error = 0.0;         // largest certified vertex distance bound
  std::size_t uncertified_vertices = 0;  // vertices without a sign-change bracket within tolerance
  double mean_tape_length = 0.0;         // of the pruned tapes of surface cells
  std::size_t full_tape_length = 0;
  std::vector<std::string> limits_hit;   // "cells", "memory", "triangles", "seconds", "rounds", "cancelled"
  double seconds_octree = 0.0, seconds_mesh = 0.0, seconds_assemble = 0.0;
};

struct ImplicitMesh {
  Mesh mesh;
  ImplicitMeshStats stats;
};

// Meshes the solid {f < 0} intersected with `box` (bounded, positive widths). Throws
// std::invalid_argument naming the problem for a bad box or settings (min_feature below
// 2^-19 of the box size, negative tolerance, ...).
ImplicitMesh mesh_implicit(const ImplicitSurface& surface, const Box3& box, const ImplicitMeshSettings& settings);
ImplicitMesh mesh_implicit(const Fn& f, const Box3& box, const ImplicitMeshSettings& settings);

}  // namespace genmod
