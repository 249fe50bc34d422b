// The conforming triangulation of the kd-tree leaves (Snyder §5.2.3.2, Fig 5.18), in
// parameter space, with the seams and poles of EdgeTopology folded in.
//
// A leaf's boundary points are its corners and every corner of another leaf on its edges
// (on a glued patch edge: also the partner edge's points, mapped). A leaf with only its four
// corners is a quad (split later along its shorter diagonal in space); any other polygon of
// n points is cut into n - 2 triangles without an extra point (a zipper between its two
// chains, never a triangle of points on one edge), which keeps every triangle non-degenerate
// in parameter space and makes every interior edge shared by exactly two triangles. A leaf on
// a collapsed patch edge (a pole) keeps one point of that edge and is cut by ear clipping in
// a plane where that edge is a point, so no triangle joins the pole to two points of one of
// its other edges (flat in space where that edge is a straight ray).
#pragma once

#include "edge_gluing.hpp"
#include "kd_subdivision.hpp"
#include "param_grid.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace genmod::parametric {

struct LeafTriangulation {
  std::vector<GridPoint> points;  // every sample point, sorted, unique
  // Per point: the index of the smallest point that is the same surface point (glued across
  // a seam, or on a collapsed edge); itself when alone.
  std::vector<std::uint32_t> representative;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise in (u, v)
  std::vector<std::array<std::uint32_t, 4>> quads;      // counter-clockwise in (u, v)
  // The leaf each triangle and quad comes from: its index in the leaves of all patches, in
  // order (patch 0's leaves first).
  std::vector<std::uint32_t> triangle_leaf, quad_leaf;
};

LeafTriangulation triangulate_leaves(const std::vector<std::vector<Leaf>>& leaves, const EdgeTopology& topology);

}  // namespace genmod::parametric
