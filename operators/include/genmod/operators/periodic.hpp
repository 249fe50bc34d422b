// periodic(c, parm, s): a closed curve c of x(parm) on [0, 1] continued periodically,
// c(s - floor(s)) for every s.
//
// Why one operator: written with floor, or with a clamp and a select on s < 0 / s > 1, an
// interval evaluation over a box that straddles an integer takes the hull of branches that
// include a clamped (constant) piece, so the enclosures of the derivatives keep 0 (and of
// the value a jump) however small the box. This operator splits the box at the integers and
// encloses each piece on c's own tape, so value and derivative enclosures shrink with the
// box across the seam; its derivative is periodic(c', parm, s).
//
// c must depend on x(parm) alone and be closed: c(0) = c(1) up to rounding (a relative gap
// of at most 1e-12 of its size, checked when built). The result is reported continuous
// (to interval Newton, mean-value forms) wherever c is, and across the integers only when
// c(0) and c(1) evaluate to the same doubles (a periodic B-spline's do; cos(2 pi t) with pi
// rounded does not: the jump is real, if tiny).
//
// Example:
//   Fn circle = cat({cos(2 * 3.141592653589793 * x(0)), sin(2 * 3.141592653589793 * x(0))});
//   Fn around = periodic(circle, 0, x(1) - 0.25);   // defined for every x(1)
// A c that depends on another coordinate, does not depend on x(parm), or is not closed
// throws std::invalid_argument naming the operator.
#pragma once

#include "genmod/kernel/fn.hpp"

namespace genmod {

Fn periodic(const Fn& c, int parm, const Fn& s);

// Whether c is a closed curve periodic() accepts: it depends on x(parm) alone, and c(0), c(1)
// are finite and agree to 1e-12 of their size (at least 1).
bool is_closed_curve(const Fn& c, int parm);

}  // namespace genmod
