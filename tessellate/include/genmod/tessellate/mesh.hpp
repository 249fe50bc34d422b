// Triangle meshes of parametric surfaces by uniform lattice sampling (and, through
// mesh_io.hpp, mesh file I/O).
//
// A surface S(u, v) of dimension 3 is sampled on an N_u x N_v lattice (lattice.hpp, with
// subfunction tables); vertex (i, j) is S(u_i, v_j) and has index i + N_u j. Each lattice quad
// (i, j)-(i+1, j)-(i+1, j+1)-(i, j+1) becomes the two triangles
//   (i, j) (i+1, j) (i+1, j+1)   and   (i, j) (i+1, j+1) (i, j+1),
// so every triangle is oriented the same way in parameter space (counter-clockwise in (u, v);
// the geometric normal points along S_u x S_v).
//
// Periodic axes: with `periodic_u`, the u range [lo, hi) is sampled at N_u points
// u_i = lo + (i (hi - lo)) / N_u (the lattice of N_u + 1 points without its last one, which
// would repeat the first), and the quads of column N_u - 1 close onto column 0, so the seam
// shares its vertices. Same for v. A torus with both periodic is a closed 2-manifold.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/tessellate/lattice.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/triangle_mesh.hpp"

namespace genmod {

struct ParametricMeshOptions {
  bool periodic_u = false;
  bool periodic_v = false;
  LatticeMethod method = LatticeMethod::Tables;
};

// Samples the 3-D surface S over the lattice axes u and v (u.samples / v.samples are the
// vertex counts per direction: >= 2, or >= 3 on a periodic axis). Throws
// std::invalid_argument for a surface that is not 3-dimensional, depends on a coordinate
// other than u's and v's, or too few samples.
Mesh mesh_parametric(const Fn& surface, const LatticeAxis& u, const LatticeAxis& v,
                     const ParametricMeshOptions& options = {});

}  // namespace genmod
