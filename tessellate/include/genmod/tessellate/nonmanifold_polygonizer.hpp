// The non-manifold polygonizer for several regions (Bloomenthal and Ferguson; research/
// bloomenthal.md §5.7): meshes the boundaries between regions of space, where more than two
// regions may meet along curves, so the mesh can have edges shared by three or more triangles
// (a leaf's vein meeting its blade, a sphere cut by a plane), and sheets that end in free
// borders.
//
// Example:
//   const Fn r = sqrt(square(x(0)) + square(x(1)) + square(x(2)));
//   const Fn inside = 1.0 - r, outside = r - 1.0;
//   const Fn regions[2] = {inside, outside};
//   RegionMesh m = polygonize_regions(regions, {.cube_size = 0.2,
//       .bounds = {Interval(-1.5, 1.5), Interval(-1.5, 1.5), Interval(-1.5, 1.5)}});
//   // m.mesh is the closed sphere, m.regions[t] == {0, 1} for every triangle t: normals
//   // point from region 0 (inside) into region 1
//
// Regions. The client gives K >= 2 scalar functions g_0..g_{K-1} of x(0), x(1), x(2); the
// region of a point p is the index of the largest g_i(p) (the spec's integer-valued region
// function f_reg, written as an arg max so that the difference g_b - g_a is a continuous
// function of the boundary between regions a and b). Ties go to the lower index; a value that
// is not a number counts as -infinity (so a point where every g_i is NaN is in region 0).
// Only f_reg is used to place vertices, as in the source: the functions' values are compared,
// never interpolated. `interest` is the set of unordered region pairs wanted (the spec's
// Interest(); empty: every pair); only boundaries between such pairs become triangles, and
// the walk only propagates across them.
//
// Lattice. Cubes of edge `cube_size` fill `bounds` (bounded, required) from its low corner;
// f_reg is evaluated at every lattice corner (dense, once). Every cube whose corners are not
// all in one region is polygonized, and from there the walk also visits neighbours across
// cube faces that hold a face line of interest (a boundary can cross a cube between corners
// of one region), never leaving the lattice. A region thinner than a cube between corners of
// one other region (a thin slab, a small bubble) crosses each edge twice in a row: looped
// intersections, ignored as in the source, so it is lost; use a smaller cube_size. Each cube is cut into five tetrahedra, the
// decomposition alternating with the parity of i + j + k so the face diagonals of neighbours
// coincide (§5.7.2 item 2).
//
// Edge vertices (§5.7.3). Every tetrahedron edge (cube edge or face diagonal) is inspected,
// also between corners of one region: it is sampled at `sections` equal sections and each
// section whose ends differ is refined by halving (`steps` levels; a midpoint in a third,
// "foreign", region splits the search in two, so two crossings in one section are both
// found). Each crossing is a vertex at the midpoint of its last interval, within
// eps = edge length / (2^(steps+1) * sections) of the boundary crossing, labelled with the
// ordered region pair seen along the edge from its lower to its higher lattice corner. All
// edge vertices are kept per lattice edge, so neighbouring tetrahedra share them.
//
// Faces (§5.7.4). The edge vertices around a tetrahedron face, in cyclic order, are matched
// by repeatedly pairing neighbours whose pairs are reversed ((a,b) then (b,a)), the spec's
// stack test. If all match, the face holds disjoint lines; a line between two vertices on one
// edge (a looped intersection) is ignored. Otherwise three or more regions meet in the face
// and the vertices left unmatched are joined to one face vertex, found (only when one of them
// separates regions of interest) by following the boundary from such an edge vertex with a
// strip of small triangles of side <= eps / 2 until a third region is met; its centroid is the
// face vertex. If no start reaches a third region inside the face, the face vertex is the
// average of the unmatched vertices (counted in stats.face_vertex_fallbacks). Face records
// are computed in a canonical order of the face's corners, so both tetrahedra sharing a face
// get the same lines and face vertex.
//
// Polygons. In a tetrahedron without a face vertex of interest, each line of interest is
// chained to its partners across the tetrahedron's faces into a polygon of 3 or 4 sides
// (a quadrilateral is split along the diagonal that bends it least). In a tetrahedron with face vertices of interest, one
// internal vertex is put at their average (at the face vertex itself when there is one) and
// every line of interest makes one triangle with it; where four regions meet inside a
// tetrahedron this is the internal vertex of §5.7.4. Triangles are ordered so that, seen
// from the lesser region of their pair, they are counter-clockwise: the normal points from
// regions[t].first into regions[t].second (first < second).
//
// Post-process (§5.7.5, when close_factor > 0): triangle edges shorter than
// close_factor * eps are collapsed, and a vertex closer than that to the opposite edge of a
// triangle is moved onto that edge (to its nearest point, not its midpoint as in the source),
// the triangles across the edge split at it, so a closed mesh stays closed; degenerate
// triangles are removed and vertices no longer used are dropped. No vertex leaves the lattice
// edge, tetrahedron face or tetrahedron it was made on (its closure), since the triangles of
// every tetrahedron around that simplex use it: so the triangles of each tetrahedron stay in
// it and meet those of others only on shared faces (issue 11: the source's moves took junction
// vertices of the maple leaf off their faces, laying triangles across each other). A short edge
// is collapsed to its midpoint when both ends are on one simplex, onto the end on the
// smaller simplex when one is a face of the other, else onto the lattice corner or edge the
// two share (within 1.4 times the collapse length; vertices put on one corner are welded
// into one); a thin triangle's vertex moves onto the opposite edge only when that edge lies
// in its simplex's closure and no other triangle around it is laid flat into a lattice face
// (so an edge vertex, the only kind on a two-region surface, never does, and its thin
// triangle stays). Two triangles a collapse puts on the same vertices with opposite
// orientations are removed when they separate the same regions, and become one triangle
// between y and z when they separate (x, y) and (x, z): region x closed up between them.
// `split_by_region_pair` makes the spec's duplicated vertices (one copy of a junction vertex
// per region pair of the triangles around it), and `region_pair_normals` gives each copy the
// normal of its own sheet.
//
// Limits: `max_cubes` (cubes polygonized) and the lattice (a walk that would leave the bounds)
// are reported in stats.limits_hit ("cubes", "bounds", and "cancelled" for a stop request); the
// mesh is then cut there. The
// lattice has at most `max_corners` corners (else std::invalid_argument, naming the sizes).
//
// Deterministic: fixed visiting order (cubes with corners in several regions in lattice
// order, then the walk, FIFO, neighbours -x +x -y +y -z +z), vertices numbered as first used;
// hash tables are only looked up. The corner scan and the edge vertices (sampling and halving,
// most of the evaluations) run on `threads` threads, in batches fixed by the lattice (a chunk
// of corners in lattice order, one edge's samples), and edges computed ahead of the walk are
// numbered when the walk first uses them: the mesh is bitwise the same for every count.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/tessellate/box3.hpp"
#include "genmod/tessellate/triangle_mesh.hpp"

#include <atomic>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace genmod {

struct NonmanifoldSettings {
  double cube_size = 0.0;     // lattice cube edge; finite and > 0
  Box3 bounds{};              // the lattice fills it; bounded, not empty
  // Unordered region pairs whose boundaries are meshed (indices into the region list,
  // different). Empty: every pair.
  std::vector<std::pair<int, int>> interest{};
  int sections = 16;          // n: samples per tetrahedron edge, 1..4096
  int steps = 4;              // m: halvings per crossing, 0..40
  double close_factor = 1.0;  // post-process threshold in units of eps; 0 turns it off
  std::size_t max_cubes = 10'000'000;
  std::size_t max_corners = std::size_t{1} << 26;
  // The caller's stop request (not owned; null = none): when it becomes true the corner scan
  // or the walk stops, reported as "cancelled" (the mesh is cut there, or empty when the scan
  // was stopped). Python's Ctrl-C sets it.
  const std::atomic<bool>* cancel = nullptr;
  // Threads for the corner scan and the edge vertices; 0 = all cores. The mesh is bitwise the
  // same for every count.
  int threads = 0;
};

struct NonmanifoldStats {
  std::size_t cubes = 0;                  // cubes polygonized
  std::size_t tetrahedra = 0;             // tetrahedra with at least one triangle
  std::size_t internal_vertices = 0;
  std::size_t face_vertices = 0;          // face vertices computed (each face once)
  std::size_t face_vertex_fallbacks = 0;  // of which the boundary follower found none
  std::size_t open_polygons = 0;          // chains of lines that did not close (dropped)
  // Evaluations of f_reg (one point: all K functions), by purpose.
  std::size_t corner_evaluations = 0;
  std::size_t sample_evaluations = 0;     // section ends inside the edges
  std::size_t refine_evaluations = 0;     // halvings of the sections that change region
  std::size_t face_evaluations = 0;       // boundary follower
  // The cost model of claim 35 (§5.7.8): over the tetrahedra crossed by a boundary, the
  // evaluations their six edges took (each edge counted in every such tetrahedron, as if
  // nothing were shared) and their edges with a crossing.
  std::size_t crossing_tetrahedra = 0;
  std::size_t crossing_tetrahedron_edge_evaluations = 0;
  std::size_t crossing_tetrahedron_crossed_edges = 0;
  double eps = 0.0;                       // the edge-vertex tolerance of the longest edge
  std::size_t collapsed_edges = 0;        // post-process
  std::size_t split_edges = 0;
  std::size_t removed_triangles = 0;
  std::vector<std::string> limits_hit;    // "cubes", "bounds"

  std::size_t evaluations() const noexcept {
    return corner_evaluations + sample_evaluations + refine_evaluations + face_evaluations;
  }
};

enum class RegionVertexKind : std::uint8_t { edge, face, internal };

struct RegionMesh {
  Mesh mesh;
  // Per triangle: the two regions it separates, first < second; its normal points into second.
  std::vector<std::pair<int, int>> regions;
  std::vector<RegionVertexKind> vertex_kinds;  // per vertex
  NonmanifoldStats stats;
};

// Meshes the boundaries between the regions of interest. Throws std::invalid_argument naming
// the problem: fewer than two regions, a region function that is not scalar or depends on an
// input other than x(0..2), a bad cube size, bounds, interest pair, sections, steps,
// close_factor or max_cubes, or a lattice of more than max_corners corners.
RegionMesh polygonize_regions(std::span<const Fn> regions, const NonmanifoldSettings& settings);

// The region of each point under the arg-max rule above (for tests and clients).
std::vector<int> region_at(std::span<const Fn> regions, std::span<const std::array<double, 3>> points);

// The spec's post-process 1 on its own: collapses edges shorter than `min_length` (to their
// midpoints), moves vertices closer than it to an opposite edge onto the edge (splitting the
// triangles across it), removes degenerate triangles and unused vertices. Updates the stats'
// post-process counts. Without the lattice that polygonize_regions keeps its vertices on,
// this can lay triangles across each other where sheets meet closer than `min_length`.
void remove_small_triangles(RegionMesh& mesh, double min_length);

// Post-process 2: a mesh in which each vertex is duplicated once per distinct region pair of
// the triangles around it (so each sheet has its own copy, e.g. for its own normal and
// colour). `vertex_pairs`, if given, receives the pair of each new vertex, and `origin` the
// index of the vertex it copies.
Mesh split_by_region_pair(const RegionMesh& mesh, std::vector<std::pair<int, int>>* vertex_pairs = nullptr,
                          std::vector<std::uint32_t>* origin = nullptr);

// Normals of the split mesh (§5.7.6: f_reg has no gradient, so the client's continuous
// functions give it): at each vertex with pair (a, b), the unit gradient of g_b - g_a by
// central differences of half-width `step` (e.g. cube_size / 100), pointing into region b,
// the greater; (0, 0, 0) where that gradient vanishes or is not a number. Throws
// std::invalid_argument for a pair list that does not match the vertices, a pair naming a
// region that does not exist, a region function that is not scalar, or a bad step.
std::vector<std::array<double, 3>> region_pair_normals(std::span<const Fn> regions, const Mesh& split,
                                                       std::span<const std::pair<int, int>> vertex_pairs,
                                                       double step);

}  // namespace genmod
