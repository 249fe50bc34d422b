// Higher-level operators of GENMOD (thesis App. A.4), written on the primitives:
//
//  * interp(t, a, b) = a + (b - a) t  (linear interpolation, a at t = 0, b at t = 1);
//  * concat(parm, in, fns): uniform concatenation in coordinate `parm`: piece i runs over
//    in in [i/n, (i+1)/n] with x(parm) := n in - i; the index is clamped so in = 1 gives the
//    last piece at its end. Each piece sees its parameter clamped to [0, 1] as well, so a
//    curve defined only on [0, 1] never receives an argument outside its domain (at every
//    point the clamp is the identity for the selected piece);
//  * hermite_interp(a, p1, p2, t1, t2): the cubic Hermite blend (thesis section 3.1.2.1.2)
//    with H(0) = p1, H(1) = p2, H'(0) = t1, H'(1) = t2; the arguments may be functions.
//
// Reparameterization by arclength needs the `inverse` operator of the solver layer and
// is not here.
#pragma once

#include "genmod/kernel/fn.hpp"

#include <initializer_list>
#include <span>

namespace genmod {

Fn interp(const Fn& t, const Fn& a, const Fn& b);
Fn concat(int parm, const Fn& in, std::span<const Fn> fns);
Fn concat(int parm, const Fn& in, std::initializer_list<Fn> fns);
Fn hermite_interp(const Fn& alpha, const Fn& p1, const Fn& p2, const Fn& t1, const Fn& t2);

}  // namespace genmod
