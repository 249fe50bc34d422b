// An axis-aligned box whose six sides are n x n grids of quads: a closed manifold test and
// benchmark mesh for the tools (selection needs faces small enough to fit a region; a 2 x 2
// patch of a side is the extrusion case with an interior vertex).
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <string>

namespace genmod {

// 6 n^2 outward quads, 6 n^2 + 2 vertices, 12 n^2 edges, all labelled `label`; vertex
// positions are lo + (hi - lo) * i / n per axis. Throws std::invalid_argument unless n >= 1
// and lo < hi (finite) on every axis.
PolyMesh make_grid_box(const Vec3& lo, const Vec3& hi, int n, const std::string& label = "");

}  // namespace genmod
