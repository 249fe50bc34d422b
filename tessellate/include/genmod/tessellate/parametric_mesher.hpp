// Adaptive meshing of parametric surfaces (Snyder 1991, §5.2.3; research/snyder.md §5.3):
// a kd-tree subdivision of each patch's parameter rectangle driven by interval bounds, a
// conforming triangulation of its leaves, and one vertex per surface point where patches or
// edges meet.
//
// Example:
//   const double pi = std::numbers::pi;
//   Fn u = 2 * pi * x(0), v = pi * (x(1) - 0.5);
//   Fn sphere_surface = cat({cos(u) * cos(v), sin(u) * cos(v), sin(v)});
//   std::vector<SurfacePatch> patches{{sphere_surface, Interval(0, 1), Interval(0, 1), true}};
//   AdaptiveMesh m = mesh_adaptive(patches, {.tolerance = 1e-2});
//   // m.mesh is closed and outward; m.distance_bound <= 1e-2; write_mesh(m.mesh, "sphere.obj")
//
// What the result guarantees:
//  1. Distance. Every triangle lies inside one leaf X of the kd-tree (its corners are surface
//     samples S(p_i), p_i in X) and stands for the surface piece S(X). A mesh point A(p), the
//     affine interpolation over the triangle's parameter triangle, and the surface point S(p)
//     are at most the leaf's bound apart, so the Hausdorff distance between mesh and surface is
//     at most `distance_bound`. The bound of a leaf of parameter widths a x b is the smaller of
//       - the diameter of the interval box S(X) (always valid), and
//       - sum_j ((rad S_u,j(X) a + rad S_v,j(X) b) / 2)^2, square-rooted, where rad is the
//         half-width of the interval Jacobian: the linear interpolation error, since
//         S(p) - sum_i l_i S(p_i) = sum_i l_i (J_i - J_mid)(p - p_i) by the mean value theorem
//         (valid where S is continuous on X with a bounded Jacobian; the interval evaluator
//         says when). It shrinks with the square of the leaf size.
//       - where S is C^2 on X (second derivatives bounded and continuous), the second-order
//         bound: half the norm over j of the magnitude of [0, a^2/4] S_uu,j(X) +
//         [-ab/4, ab/4] (S_uv,j + S_vu,j)(X) + [0, b^2/4] S_vv,j(X), by Taylor's theorem along
//         each segment from a triangle's point to its corners (the proof is at SecondOrder in
//         kd_subdivision.cpp). About half the linear bound, and tight for a quadratic.
//     A leaf is accepted when its bound is at most `tolerance`. Vertices merged across a seam
//     or a pole use one sample for several parameter points; the largest such deviation is
//     measured and added.
//  2. Conforming. Every corner of a leaf that lies on another leaf's edge is a vertex of both
//     (Fig 5.18): a leaf with n such boundary points is cut into n - 2 non-degenerate
//     triangles between them, any other leaf split along its shorter diagonal; so every
//     interior edge belongs to exactly two triangles.
//  3. One vertex per surface point at seams and poles. Periodic axes glue their two edges;
//     with `glue_edges`, edges that coincide geometrically (a solid's faces, a cylinder not
//     marked periodic, patches of one object) are glued too, and edges that collapse to a point
//     (the pole of a sphere, a profile ending on the axis) become one vertex; triangles left
//     with a repeated vertex are dropped. A closed object gives a closed mesh as written.
//  4. Orientation from the geometry: triangles are made consistent across glued edges, then
//     each closed component is turned so that its signed volume is positive (outward).
//  5. No folds: the distance bound allows in-plane distortion up to the tolerance where the
//     surface is flat, so a leaf much narrower than that could be triangulated into a
//     triangle facing backwards over its neighbours. A mesh triangle whose normal points
//     against S_u x S_v at its parameter centroid has its leaf split in two (across its longer
//     side in space, keeping its bound, which bounds the halves too) and the leaves are
//     triangulated again, up to 8 rounds (and not below max_depth).
// Deterministic: the same input gives bitwise the same mesh for any thread count.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/mesh.hpp"

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace genmod {

// One parametric surface S(u, v) = surface(x(0), x(1)) in R^3 over u x v.
struct SurfacePatch {
  Fn surface;
  Interval u = Interval(0.0, 1.0), v = Interval(0.0, 1.0);
  bool periodic_u = false, periodic_v = false;
};

enum class LeafBound {
  Best,      // the smallest of the box diameter, the linear and the second-order bounds (above)
  BoxWidth,  // Snyder's criterion w(S(X)) <= tolerance alone (claim 37)
};

struct AdaptiveMeshOptions {
  double tolerance = 1e-3;  // largest distance between mesh and surface (> 0)
  LeafBound bound = LeafBound::Best;
  // Limits, reported in AdaptiveMesh::limits_hit when reached ("depth", "leaves", "time",
  // "cancelled").
  int max_depth = 24;                 // splits per parameter axis (a leaf is >= 2^-24 of the range)
  // Where the interval bounds are not finite (an operator without a finite enclosure there),
  // splitting may never give a bound: such leaves are split to this depth per axis only,
  // then kept and counted in AdaptiveMesh::unbounded_leaves (distance_bound is then infinite).
  int unbounded_depth = 8;
  std::size_t max_leaves = 4'000'000;  // over all patches
  double max_seconds = 0.0;           // 0: no time limit
  // The caller's stop request (not owned; null = none): when it becomes true splitting stops,
  // as when time is up, reported as "cancelled". Python's Ctrl-C sets it.
  const std::atomic<bool>* cancel = nullptr;
  bool glue_edges = true;             // find edges that coincide or collapse (see above)
  double glue_tolerance = 1e-9;       // relative to the surface's extent
  int threads = 0;                    // 0: all cores
  // An extra criterion: a leaf (patch index, its u and v ranges) is split further while this
  // returns true (up to max_depth). For user criteria and for tests of the triangulation.
  std::function<bool(std::size_t patch, const Interval& u, const Interval& v)> refine = {};
};

struct AdaptiveMesh {
  Mesh mesh;
  double distance_bound = 0.0;    // certified, see above (infinite if a leaf had no finite bound)
  std::size_t leaves = 0;
  std::size_t unbounded_leaves = 0;  // leaves without a finite distance bound (see above)
  std::size_t interval_evaluations = 0;
  std::size_t glued_edges = 0, collapsed_edges = 0;  // patch edges glued to another / to a point
  std::size_t dropped_triangles = 0;                 // with a repeated vertex (at poles)
  std::size_t boundary_edges = 0;                    // mesh edges with one triangle (open parts)
  std::size_t flipped_components = 0;                // turned to point outward
  double seam_deviation = 0.0;                       // largest measured merge deviation
  std::vector<std::string> limits_hit;
  bool closed() const noexcept { return boundary_edges == 0 && !mesh.triangles.empty(); }
};

// Throws std::invalid_argument for no patches, a surface that is not 3-D or depends on other
// coordinates than x(0) and x(1), an empty, unbounded or degenerate parameter range, or a
// tolerance that is not a positive finite number; std::domain_error naming the patch and the
// parameter point where the surface is undefined (NaN) at a vertex.
AdaptiveMesh mesh_adaptive(const std::vector<SurfacePatch>& patches, const AdaptiveMeshOptions& options = {});

}  // namespace genmod
