// GENMOD's m_integrate (thesis App. A.3.6): R(x) = integral of f over x(parameter) from
// lower(x) to upper(x). The integrand may have any dimension and depend on any
// coordinates; the limits may depend on parameters, including x(parameter) itself (which
// outside the integral is free: integrate(f, 0, x(0), 0) is a function of x(0)).
//
//  * point: Romberg integration (trapezoid refinement with Richardson extrapolation), at
//    least `min_levels` and at most `max_levels` halvings, stopping when two successive
//    diagonal estimates differ by at most tolerance * |upper - lower| * max |f| (over the
//    samples so far). A NaN integrand sample or limit makes the result NaN (error). A
//    non-converged result is returned as is (the last estimate).
//  * inclusion: rigorous for the exact integral. With a = min(lo L, lo H),
//    integral_l^h = G(h) - G(l), G(y) = sum over `pieces` equal pieces of [a, lo Y] of
//    width * F(piece) + [0, y - lo Y] * F(Y) (F bounded by its natural inclusion over each
//    piece and the boxes of the other arguments; no continuity needed). The result is
//    widened by 4 tolerance * |hull of the limits| * max |F| so that it also holds the
//    converged Romberg value.
//  * continuity (CustomOp::inclusion_continuous): claimed on a box where the integrand's
//    interval evaluation is continuous on every piece (no jump, no possible error): then the
//    integral is continuous in the limits and the free coordinates, and interval Newton goes
//    through it. An integrand that may jump (a step in a free coordinate) gives no claim.
//  * derivative: the Leibniz rule: d/dl = -f(x_p := l), d/dh = f(x_p := h), and for the
//    other coordinates the integral of the partial derivative (a new integral operator).
//
// Thread safety: evaluation uses per-call evaluators, so nested and concurrent integrals work.
#pragma once

#include "genmod/kernel/fn.hpp"

namespace genmod {

struct IntegrateOptions {
  double tolerance = 1e-11;  // relative acceptance of Romberg (see above)
  int min_levels = 5;        // at least 2^min_levels + 1 samples (avoids aliasing on periodic f)
  int max_levels = 16;       // at most 2^max_levels + 1 samples
  int pieces = 32;           // pieces of the inclusion function's Riemann enclosure
};

// lower and upper are scalar functions; std::invalid_argument for a bad parameter index,
// non-scalar limits or bad options.
Fn integrate(const Fn& integrand, const Fn& lower, const Fn& upper, int parameter, const IntegrateOptions& options = {});

}  // namespace genmod
