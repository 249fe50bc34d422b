// GENMOD's m_inverse (snyder.md section 2.4.12) as an Fn operator: monotone inversion in one
// coordinate, with point evaluation, an inclusion function and an implicit-function-theorem
// derivative, so it nests inside functions that are solved, minimized or tessellated.
//
// Example:
//   using namespace genmod;
//   Fn t = x(0);
//   Fn r = inverse(t * t * t + t, x(1), 0);   // t in [0,1] with t^3 + t = x(1); a function of x(1)
//   // evaluate(r, {_, 0.5}) ~ 0.4534;  derivative(r, 1) = 1 / (3 r^2 + 1)
//
// Semantics: R(x) = t such that invert(x with x_p := t) = match(x). `match` is evaluated at the
// outer point x *including its own x_p* (GENMOD's arclength reparameterization uses this), so
// the result depends on the coordinates of invert other than p, and on all of match's.
//
// Point evaluation: Brent's method on `domain` for F(t) = invert(x_p := t) - match. When F does
// not change sign between the ends of the domain (not bracketed), or F fails (NaN) at a point
// the method visits, the result is NaN (GENMOD's error condition). The result is a root of F to
// within `epsilon` (the final bracket width).
//
// Inclusion over a box P of the free coordinates. When dF/dt excludes 0 on domain x P (F
// strictly monotone in t, the usual case of a schedule), bisection with interval evaluations
// at single values of t finds a t below every root and one above it, for every parameter
// value in P (about 2 log2(domain width / epsilon') evaluations of invert, match enclosed once
// over P). Otherwise the constraint solver (no solution is ever lost) solves F = 0 for t in the
// domain with the free coordinates as interval parameters, and the result is the hull of its
// boxes. Either way epsilon' = max(epsilon, 0.01 width(P)), and the result is widened by the
// point value's tolerance and clipped to the domain: it holds every root of F in the domain
// for every parameter value in P, hence every point value.
// Errors: empty + kCertainError when F has no root for any parameter value; kMaybeError
// unless F(domain.lo) and F(domain.hi) have strictly opposite signs over all of P and F cannot
// fail on domain x P (then every point of P is bracketed). Unbounded arguments give the domain
// and kMaybeError.
//
// Continuity (CustomOp::inclusion_continuous), claimed on a box P only when F is continuous
// on domain x P, no point of P can fail (above), and F has exactly one root in the domain for
// every p in P: dF/dt excludes 0 there, or the solver's single component is certified
// (Krawczyk) to hold exactly one root for every p. Then R is continuous on P (a limit of roots
// R(p_k), p_k -> p, is a root at p, hence R(p)), so interval Newton and Krawczyk go through
// the operator (a root of solve(eq(inverse(...), c)) is certified). With several roots the
// point value (Brent's) may jump from one root to another: no claim.
//
// Derivative (implicit function theorem): with F(t, x) as above,
//   dR/dx_i = -(dF/dx_i) / (dF/dt)   at t = R(x),
// built symbolically with the operator itself substituted for t, so derivatives of any order
// work (and are NaN where dF/dt = 0). Monotonicity of invert is the caller's promise; without
// it the point value is one of the roots and the inclusion still holds all of them.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"

namespace genmod {

// Throws std::invalid_argument naming the problem for: a non-scalar invert or match, a
// parameter outside [0, kMaxInputs), an invert that does not depend on x(parameter), an empty,
// unbounded or degenerate domain, an epsilon that is not finite and > 0, or no free coordinate
// left for the bound variable (all 64 in use).
Fn inverse(const Fn& invert, const Fn& match, int parameter, Interval domain = Interval(0.0, 1.0),
           double epsilon = 1e-12);

}  // namespace genmod
