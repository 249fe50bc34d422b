// Cross-section deformation (thesis section 3.1.2.3, research/snyder.md section 7.16):
// GENMOD's m_warp_z_by_x, a parabolic warp of z as a function of x,
//   warp(a, b)(x, y, z) = (x, y, z + a x^2 + b),
// with scalar a and b that may vary along the sweep (the key: a = 0.2 v, b = -0.05 v, so no warp
// at v = 0).
// Example:
//   Fn cross3d = cat({x(0), x(1), Fn(0.0)});
//   Fn sides = warp_z_by_x(cross3d, 0.2 * x(1), -0.05 * x(1));
// A cross section of dimension other than 3, or non-scalar a or b, throws
// std::invalid_argument naming the operator.
#pragma once

#include "genmod/kernel/fn.hpp"

namespace genmod {

Fn warp_z_by_x(const Fn& cross, const Fn& a, const Fn& b);

}  // namespace genmod
