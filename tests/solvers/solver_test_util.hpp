// Helpers shared by the constraint-solver tests.
#pragma once

#include "genmod/solvers/constraint_solver.hpp"

#include <cmath>
#include <vector>

namespace genmod::test {

// Distance (max norm) from a point to a box; 0 inside.
inline double distance(const Box& b, const std::vector<double>& p) {
  double d = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (p[i] < b[i].lo()) d = std::max(d, b[i].lo() - p[i]);
    if (p[i] > b[i].hi()) d = std::max(d, p[i] - b[i].hi());
  }
  return d;
}

// True if the point lies in a returned box, up to `tol` (the rounding of the point itself:
// a root given in closed form is computed in double precision).
inline bool covered(const SolveResult& r, const std::vector<double>& p, double tol = 0.0) {
  for (const SolutionBox& b : r.boxes)
    if (distance(b.box, p) <= tol) return true;
  return false;
}

}  // namespace genmod::test
