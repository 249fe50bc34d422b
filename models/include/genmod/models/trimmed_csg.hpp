// CSG-like operations of two closed parametric surfaces by trimming (Snyder 1991, §5.2.4,
// Algorithm 5.4; research snyder.md §5.4): S° ∘ T° for ∘ in {∪, ∩, −} as one triangle mesh.
//
// The algorithm lives in models/ because it combines the solvers (surface_intersection,
// classify_point) with the tessellate layer's kd-trees and mesh types; tessellate may not
// include solvers headers (DESIGN.md, layer order).
//
// Steps as implemented (trimmed_csg.cpp):
//  1. the intersection curve of S(u,v) = T(s,t) in (u,v,s,t) with Algorithm 5.3
//     (surface_intersection), periodic coordinates passed on;
//  2. its proximate boxes as a 4-D kd-tree, projected to (u,v) and to (s,t) (kd_tree.hpp
//     project);
//  3. segments cut by a periodic boundary: the crossing point is one curve vertex, used on
//     both sides of the cut rectangle and unbroken in the other surface's parameters;
//  5. an adaptive sampling kd-tree per surface (interval bound of the surface's box width);
//  6. merged with merge_addonly(projected intersection tree, sampling tree): no intersection
//     leaf is subdivided, and no sample point lies inside an intersection leaf;
//  7. a constrained Delaunay triangulation (CGAL) of the remaining sample points with the
//     projected curve polylines as constraints, in place of the thesis's per-leaf
//     triangulation and neighbour flooding. The regions cut out by the curve are labelled by
//     classify_point of one point per region against the other surface (instead of Step 4's
//     orientation + containment hierarchy + one classification), and the kept triangles are
//     mapped to space.
// GENMOD_CSG_DEBUG=1 in the environment prints the chains and the region classifications.
// Every curve vertex is one mesh vertex (its position is S at its (u,v)) shared by both trimmed
// pieces, so the seam is welded by construction; periodic seams and degenerate (pole) sides
// are welded too.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/tessellate/triangle_mesh.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace genmod::models {

enum class CsgOperation { Union, Intersection, Difference };

// A closed surface of (u, v) = (x(0), x(1)) over [0,1]^2, normal S_u x S_v pointing outward.
struct ClosedSurface {
  Fn surface;
  bool periodic_u = false, periodic_v = false;
};

struct TrimmedCsgOptions {
  double tolerance = 0.05;       // sampling: a leaf's interval box of S is at most this wide
  int max_depth = 16;            // sampling: bisections per path at most
  double curve_width = 0.02;     // Algorithm 5.3 acceptance width in (u,v,s,t)
  double curve_time = 60.0;      // seconds for the intersection curve at most
};

struct TrimmedCsgResult {
  Mesh mesh;                                // both trimmed pieces, welded
  std::vector<std::uint32_t> seam;          // mesh vertices on the intersection curve
  std::size_t triangles_first = 0, triangles_second = 0;  // the mesh's triangles: first's, then second's, ...
  std::vector<std::size_t> triangles_per_surface;
  std::size_t curve_components = 0;
  bool curve_complete = false;              // Algorithm 5.3 reported no limit / unresolved box
  std::size_t classifications = 0, unknown_classifications = 0;
  // Sampling leaves accepted at max_depth with their interval box still wider than the
  // tolerance (the criterion is the thesis's box-size one; interval overestimation of a bumpy
  // surface makes it stricter than the true width).
  std::size_t capped_leaves = 0;
  // Leaf corners of the merged kd-trees strictly inside a projected intersection leaf: 0 when
  // merge_addonly kept every intersection leaf whole (Step 6's invariant).
  std::size_t samples_inside_curve_leaves = 0;
  // Seam check: the seam vertices used by triangles of two (or more) pieces.
  std::size_t seam_vertices_in_both = 0;
  double seconds = 0.0;
};

// Throws std::runtime_error when the curve is incomplete or a region cannot be classified.
TrimmedCsgResult trimmed_csg(const ClosedSurface& first, const ClosedSurface& second, CsgOperation op,
                             const TrimmedCsgOptions& options = {});

// Full CSG (§5.2.5, snyder.md §5.5) of n closed surfaces: the solid is a Boolean function of
// "inside surface i" (in[i] != 0), e.g. (A - B) - C: in[0] && !in[1] && !in[2]. Steps 1-3 run
// for each of the C(n, 2) pairs; each surface is then trimmed by all its curves at once (the
// CPG of its trimmed regions is the labelling of the regions between all its curves), a region
// kept where the solid differs on its two sides and oriented towards the solid's outside.
// Assumes that the curves of different pairs do not meet (no triple points); a meeting is
// reported as a runtime_error.
using CsgSolid = std::function<bool(const std::vector<char>& inside)>;
TrimmedCsgResult trimmed_csg(const std::vector<ClosedSurface>& surfaces, const CsgSolid& solid,
                             const TrimmedCsgOptions& options = {});

// The thesis's hole-drilling surfaces (§5.4.1, Fig 5.20): the bumpy sphere (profile product,
// periodic in u) and the cylinder along x, x in [-1.5, 1.5], radius `radius` (periodic in s,
// open at its ends, which lie outside the sphere).
ClosedSurface bumpy_sphere();
ClosedSurface drill_cylinder(double radius = 0.3);
// A cylinder along y, y in [-1.5, 1.5], axis at x = 0, z = z0 (periodic in s, open ends).
ClosedSurface cross_cylinder(double radius = 0.2, double z0 = 0.55);
ClosedSurface sphere_surface(double radius, double cx, double cy, double cz);

// Named CSG models for `genmod mesh`, `genmod list` and Python's gallery: "drilled_sphere"
// (bumpy sphere minus cylinder) and "drilled_sphere_twice" ((A - B) - C, §5.5: the drilled
// sphere minus a second, thinner cylinder along y above the first, the two bores not meeting:
// genus 2). They have no parameters; TrimmedCsgOptions sets how finely they are meshed.
struct CsgModel {
  std::string name;
  std::string description;
};
const std::vector<CsgModel>& csg_models();
bool is_csg_model(const std::string& name);
TrimmedCsgResult mesh_csg_model(const std::string& name, const TrimmedCsgOptions& options = {});

}  // namespace genmod::models
