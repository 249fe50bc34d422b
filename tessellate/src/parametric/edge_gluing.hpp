// Which patch edges are one curve of the surface (a seam) or one point (a pole).
//
// Edge `side` of a patch: 0 is v = v.lo (running along u), 1 is u = u.hi (along v), 2 is
// v = v.hi (along u), 3 is u = u.lo (along v). A glue identifies the part [b_lo, b_hi] of
// edge b with the part [a_lo, a_hi] of edge a, linearly in grid indices (reversed: b_lo
// goes to a_hi).
// Periodic axes are glued by declaration; other edges by geometry (with options.glue_edges):
//  - an edge collapses to a point when its samples at 33 evenly spaced parameters agree;
//  - two whole edges are glued when their samples agree, directly or reversed;
//  - a remaining edge b is glued to a part of another edge a (a cap fills a wall's rim in
//    several pieces) when b's ends lie on a's curve and b's samples agree with a's at the
//    linearly mapped parameters.
// A part's map is verified at the parameters found, before rounding; the glue's parameters
// are rounded to the grid (2^-30 of the range), which on a fast edge moves a point by more
// than the tolerance, and the mesher measures the resulting deviation.
#pragma once

#include "kd_subdivision.hpp"
#include "param_grid.hpp"

#include <vector>

namespace genmod::parametric {

struct EdgeRef {
  std::uint32_t patch = 0;
  int side = 0;
  friend bool operator==(const EdgeRef&, const EdgeRef&) = default;
};

struct Glue {
  EdgeRef a, b;
  bool reversed = false;
  std::int64_t a_lo = 0, a_hi = kGridSize;
  std::int64_t b_lo = 0, b_hi = kGridSize;

  // Grid index on a of index t on b (within [b_lo, b_hi]), and back (t within [a_lo, a_hi]).
  std::int64_t to_a(std::int64_t t) const;
  std::int64_t to_b(std::int64_t t) const;
};

struct EdgeTopology {
  std::vector<Glue> glues;
  std::vector<EdgeRef> collapsed;
};

// The grid point at index t along an edge.
GridPoint edge_point(const EdgeRef& e, std::int64_t t);
// The grid index along edge `side` of a point on it.
std::int64_t edge_index(int side, const GridPoint& p);
// True when the point lies on that edge of its patch.
bool on_edge(int side, const GridPoint& p);

EdgeTopology find_edge_topology(const std::vector<SurfacePatch>& patches, const std::vector<CompiledPatch>& compiled,
                                const AdaptiveMeshOptions& options);

}  // namespace genmod::parametric
