// Where a vertex of the non-manifold polygonizer lies in the tetrahedral lattice: a lattice
// corner, edge (cube edge or face diagonal), tetrahedron face or tetrahedron, named by its
// corners. Every triangle the polygonizer makes lies in one tetrahedron, its vertices on the
// edges and faces of that tetrahedron or inside it; so triangles of different tetrahedra can
// meet only on the faces they share, and there only along the lines both took from the
// shared face record. The post-process keeps this so by moving a vertex only within the
// closure of its simplex (issue 11: a face vertex moved off its face, onto a segment inside
// one of its two tetrahedra, laid triangles of the other one across their neighbours).
#pragma once

#include <array>
#include <cstdint>

namespace genmod::nonmanifold {

using SimplexPoint = std::array<double, 3>;

struct LatticeSimplex {
  int size = 0;                          // corners: 1..4; 0 = not known (no lattice)
  std::array<std::uint64_t, 4> keys{};   // lattice corner keys, increasing
  std::array<SimplexPoint, 4> corners{};  // their positions, in the same order
};

// The simplex on these corners (any order, no repeats, 1..4 of them).
LatticeSimplex make_simplex(const std::uint64_t* keys, const SimplexPoint* corners, int size);

// Whether every corner of `inner` is a corner of `outer` (inner is outer or one of its faces).
bool is_face_of(const LatticeSimplex& inner, const LatticeSimplex& outer);

// The corners of both (size 0 when there would be more than four: not one simplex).
LatticeSimplex join(const LatticeSimplex& a, const LatticeSimplex& b);

// The corners they share (size 0 when none).
LatticeSimplex meet(const LatticeSimplex& a, const LatticeSimplex& b);

// The point of the closed corner or edge `s` (size 1 or 2) nearest p, and the simplex whose
// relative interior holds it (`s`, or one of its ends).
SimplexPoint nearest_on(const LatticeSimplex& s, const SimplexPoint& p, LatticeSimplex& holder);

}  // namespace genmod::nonmanifold
