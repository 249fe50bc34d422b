// The adaptive kd-tree subdivision of each patch's parameter rectangle (Snyder §5.2.3.1):
// a leaf is accepted once an interval bound of its distance from the mesh is within the
// tolerance (parametric_mesher.hpp explains the two bounds).
#pragma once

#include "param_grid.hpp"

#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/parametric_mesher.hpp"

#include <string>
#include <vector>

namespace genmod::parametric {

// A patch compiled for meshing: S, its Jacobian columns (S_u, S_v) and its second derivatives
// (S_uu, S_uv, S_vu, S_vv: S_uv = d/dv S_u and S_vu = d/du S_v, both kept so that the
// second-order bound needs no symmetry argument), inputs (x(0), x(1)).
struct CompiledPatch {
  Tape value, jacobian, hessian;
  Interval u, v;
  bool periodic_u = false, periodic_v = false;
};

CompiledPatch compile_patch(const SurfacePatch& patch);

struct Leaf {
  GridRect rect;
  double bound = 0.0;  // distance bound of the leaf (infinite when none is finite)
};

struct Subdivision {
  std::vector<std::vector<Leaf>> leaves;  // per patch, in a fixed order
  std::size_t interval_evaluations = 0;
  std::vector<std::string> limits_hit;
};

Subdivision subdivide(const std::vector<CompiledPatch>& patches, const AdaptiveMeshOptions& options);

}  // namespace genmod::parametric
