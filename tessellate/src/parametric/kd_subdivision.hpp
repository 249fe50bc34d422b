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

// A patch compiled for meshing: S and its Jacobian columns (S_u, S_v), inputs (x(0), x(1)).
struct CompiledPatch {
  Tape value, jacobian;
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
