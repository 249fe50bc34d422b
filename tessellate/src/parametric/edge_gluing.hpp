// Which patch edges are one curve of the surface (a seam) or one point (a pole).
//
// Edge `side` of a patch: 0 is v = v.lo (running along u), 1 is u = u.hi (along v), 2 is
// v = v.hi (along u), 3 is u = u.lo (along v). A glue identifies grid index t on edge a with
// t (or kGridSize - t when reversed) on edge b. Periodic axes are glued by declaration; other
// edges by geometry (with options.glue_edges): two edges are glued when their samples at 33
// evenly spaced parameters agree within the glue tolerance, directly or reversed, and an edge
// collapses when all its samples do.
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
