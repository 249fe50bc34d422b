// GENMOD's m_solve (snyder.md section 2.4.13) as an Fn operator: the constraint solved for some
// coordinates, as a function of the others. Point evaluation, an inclusion function over boxes
// of the free coordinates and an implicit-function-theorem derivative, so a solve can be nested
// inside a function that is itself solved, minimized or tessellated. The operators are named
// *_operator; genmod::solve() (constraint_solver.hpp) is the search itself, which returns boxes.
//
// Example:
//   using namespace genmod;
//   const int unknowns[] = {0};
//   Fn r = solve_operator(eq(square(x(0)) + square(x(1)), 1.0), unknowns, {Interval(0, 2)}, 1e-9);
//   // r(x1) = sqrt(1 - x1^2);  derivative(r, 1) = -x1 / sqrt(1 - x1^2)
//
// The result has dimension n = unknowns.size(): component k is x(unknowns[k]) of a solution
// point. The unknowns become bound; the result depends on the constraint's other coordinates
// (the free coordinates, ascending).
//
// Point evaluation at free values p: genmod::solve() with p as degenerate parameters and the
// given epsilon. The solution chosen is the component (section 4.9 aggregate) whose hull has
// the lexicographically smallest lower corner (x(unknowns[0]) first); the value is the
// midpoint of its hull, refined by Newton steps on the equality system while they stay inside
// the hull and reduce the residual (so a certified solution is accurate to rounding, not to
// epsilon). No solution, or a search that hit a limit -> NaN in every component.
//
// Inclusion over a box P of the free coordinates: genmod::solve() with P as parameters (it never
// loses a solution, even when a limit stops it: unexplored boxes are returned), accepting boxes
// of width max(epsilon, w(P) / 100); the result is the hull of all returned boxes per unknown,
// widened by epsilon and clipped to the domain. It holds every solution for every p in P, and
// so every point value that lies within epsilon of a true solution (always, for a certified
// component; for an uncertified one this is the solver's own epsilon promise). Errors: no box
// at all -> empty + kCertainError; kNoError only when some returned box or component is
// certified (a CertifiedUnique or Feasible box, or a component certified unique, which hold a
// solution for every parameter value) and the search was complete; otherwise kMaybeError.
// Unbounded arguments give the domain and kMaybeError.
//
// Continuity (CustomOp::inclusion_continuous), claimed on a box P only for solve_operator() (one
// solution), a complete search and a single component certified (Krawczyk) to hold exactly one
// solution for every p in P: then the solution map is continuous on P, so interval Newton and
// Krawczyk go through a nested solve. With several solutions the first one may jump to
// another; solve_all_operator's count is a step function: no claim.
//
// Derivative (implicit function theorem, snyder.md section 3.3): when the top-level
// conjunction of the constraint holds exactly n equalities h_i = 0 (inequalities are assumed
// inactive), dR/dp = -J_x^{-1} J_p with J_x = dh/dx (n x n) and J_p = dh/dp, evaluated at the
// solution. It is built symbolically by Cramer's rule (cofactor determinants, n <= 4) with
// the operator itself substituted for the unknowns, so derivatives of derivatives work. It is
// NaN where J_x is singular, and NaN everywhere when the system is not square or n > 4.
//
// Restriction: the domain is a constant box (GENMOD allows a parametric domain).
#pragma once

#include "genmod/kernel/coordinates.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/solvers/box.hpp"

#include <span>

namespace genmod {

// Throws std::invalid_argument naming the problem for: a non-scalar constraint, no unknowns, an
// unknown repeated or outside [0, kMaxInputs), a domain of the wrong dimension or with an empty,
// NaN or unbounded side, an epsilon that is not finite and > 0.
Fn solve_operator(const Fn& constraint, Coordinates unknowns, const Box& domain, double epsilon);

// GENMOD's "all solutions up to a maximum": 1 + K n components (K = max_solutions >= 1):
// the number of solutions found (at most K), then K solution points in the order above (NaN
// where fewer were found). Point values as for solve_operator(); each solution is a separate solution
// component of the aggregation, so two solutions closer than about epsilon count as one.
// Inclusion over a parameter box: the count is [number of components certified unique, K] (or
// the exact number when every component is certified), and every slot holds the hull of all
// solutions (any of them may come j-th for some parameter value), kMaybeError beyond the
// certified count. Derivatives: the implicit function theorem at each slot (0 for the count).
Fn solve_all_operator(const Fn& constraint, Coordinates unknowns, const Box& domain, double epsilon,
                        int max_solutions);

}  // namespace genmod
