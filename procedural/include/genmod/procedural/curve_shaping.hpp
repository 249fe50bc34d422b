// Curve shaping (Morkel §4.1.6): move the vertices of a face selection along a direction until,
// seen along a projection normal, they lie on a curve. The selection falls onto the surface
// swept by the curve along the normal; each vertex keeps its height along the normal.
#pragma once

#include "genmod/procedural/bezier_curve.hpp"
#include "genmod/procedural/poly_mesh.hpp"

#include <cstddef>

namespace genmod {

// shape_to_curve(mesh, faces, curve, direction, normal), in place:
//   n = normal / |normal|; d = direction with its component along n removed, normalised;
//   every distinct vertex of `faces` (in vertex index order) meets the line v + s d with the
//   curve projected along n (intersect_line: the hit nearest to v, either sign of s, so a
//   vertex beyond the curve moves back) and moves by s d. Coordinates where d is exactly zero
//   are left untouched, so with n a coordinate axis (the thesis's use) the coordinate along n
//   is bitwise unchanged; otherwise v . n changes only by rounding.
//   A vertex whose line misses the curve does not move; vertices outside `faces` never move.
// Returns the number of vertices that met the curve (moved or already on it).
//
// An empty `faces` returns 0 at once and changes nothing, whatever the other arguments (a
// procedure may build its curve from the bounds of an empty selection). Otherwise throws
// std::invalid_argument naming shape_to_curve for: a face handle that is invalid, out of range
// or deleted; a non-finite or zero direction or normal; a direction parallel to the normal
// (its part perpendicular to the normal at most 1e-12 of its length).
std::size_t shape_to_curve(PolyMesh& mesh, const FaceList& faces, const BezierCurve& curve, const Vec3& direction,
                           const Vec3& normal);

}  // namespace genmod
