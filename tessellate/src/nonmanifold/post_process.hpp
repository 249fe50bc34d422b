// The polygonizer's own call of the post-process (§5.7.5), with the lattice simplex of each
// vertex (lattice_simplex.hpp), so that no vertex leaves the tetrahedra whose triangles use
// it. The public remove_small_triangles knows no lattice: it moves vertices as the source.
#pragma once

#include "genmod/tessellate/nonmanifold_polygonizer.hpp"
#include "nonmanifold/lattice_simplex.hpp"

#include <vector>

namespace genmod::nonmanifold {

// As remove_small_triangles; `cells` (one per vertex, size 0 = not known) is kept in step
// with the vertices.
void remove_small_triangles(RegionMesh& mesh, double min_length, std::vector<LatticeSimplex>& cells);

}  // namespace genmod::nonmanifold
