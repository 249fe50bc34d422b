// A box whose six faces are n x n grids of quads: a closed test and modeling primitive with
// enough faces for selections, curve shaping and bridges to have something to work on.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <string>

namespace genmod {

// The axis-aligned box [lo, hi] with every face split into n x n quads, oriented outward
// (counter-clockwise seen from outside), every face labelled `label`. Grid vertices shared by
// neighbouring faces are one vertex, so the mesh is closed: V = 6n^2 + 2, E = 12n^2, F = 6n^2.
// Vertex coordinates on the box's planes are exactly lo[a] or hi[a]. Faces come in the order
// -x, +x, -y, +y, -z, +z, each row by row. n = 1 gives make_box's counts (not its indices).
// Throws std::invalid_argument unless lo < hi on every axis (finite) and 1 <= n <= 1024.
PolyMesh make_grid_box(const Vec3& lo, const Vec3& hi, int n, const std::string& label = "");

}  // namespace genmod
