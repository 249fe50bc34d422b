// Affine transforms as 4x4 homogeneous matrices (last row 0 0 0 1) and their application to
// shapes, as in thesis section 3.1.1.4 (m_transform3d). Matrices premultiply, so in
// `rotate_z(a) * translate(t)` the translation is applied first. Angles are in radians and
// may be functions (a rotation that varies along a sweep); rotations are right-handed.
#pragma once

#include "genmod/operators/matrix.hpp"

namespace genmod {

Matrix translate(const Fn& tx, const Fn& ty, const Fn& tz);
// t of dimension 3.
Matrix translate(const Fn& t);
Matrix scale(const Fn& sx, const Fn& sy, const Fn& sz);
Matrix scale(const Fn& s);  // uniform
Matrix rotate_x(const Fn& angle);
Matrix rotate_y(const Fn& angle);
Matrix rotate_z(const Fn& angle);

// GENMOD's m_transform3d: applies a 4x4 affine matrix to a shape of dimension 3 (or 2, taken
// as z = 0). The result has dimension 3.
Fn transform3d(const Fn& shape, const Matrix& m);

}  // namespace genmod
