// Folds: a leaf's distance bound limits how far a mesh point is from its surface point, not
// whether the mesh turns over. Where the surface is flat the bound allows in-plane
// distortion of the order of the tolerance, and a leaf much narrower than that (a sliver
// fanning out from a small hole: the furry bear's scalp pieces around a hair root) can be
// triangulated into a triangle that faces backwards and overlaps its neighbours (bear at
// tolerance 0.02: 20 intersecting pairs, all in such pieces). A triangle folds when its
// normal points against the surface's normal S_u x S_v at its parameter centroid; its leaf
// is then split in two (along its longer side in space) and the leaves triangulated again.
#pragma once

#include "kd_subdivision.hpp"
#include "leaf_triangulation.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace genmod::parametric {

// A mesh triangle by its three triangulation points and its leaf (flattened index).
struct LeafTriangle {
  std::array<std::uint32_t, 3> points;
  std::uint32_t leaf;
};

// The leaves (flattened indices, ascending, unique) of triangles whose normal, from the
// positions `at` of their points' representatives, points against S_u x S_v at their
// parameter centroid (where that normal is zero nothing is decided).
std::vector<std::uint32_t> folded_leaves(const std::vector<CompiledPatch>& patches, const LeafTriangulation& tri,
                                         const std::vector<std::array<double, 3>>& at,
                                         const std::vector<LeafTriangle>& triangles);

// Splits each listed leaf into two halves, across its longer side in space (|S_u| du against
// |S_v| dv at its centre), unless it is one grid step wide there already. The halves keep the
// leaf's bound: a sub-box's interval enclosures are within the box's, so its bound is no
// larger. Returns how many leaves were split.
std::size_t split_leaves(const std::vector<CompiledPatch>& patches, std::vector<std::vector<Leaf>>& leaves,
                         const std::vector<std::uint32_t>& which, int max_depth);

}  // namespace genmod::parametric
