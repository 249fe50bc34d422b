// GENMOD's m_minimize (snyder.md section 2.4.13) as Fn operators: the global minimizer point
// and the minimum value of an objective over the unknowns, as functions of the remaining (free)
// coordinates. The operators are named *_operator; genmod::minimize() (minimizer.hpp) is the
// search itself, which returns boxes and a bracket.
//
// Example:
//   using namespace genmod;
//   const int unknowns[] = {0};
//   Fn f = square(x(0) - x(1)) + square(x(1));            // min over x0 is x1^2, at x0 = x1
//   Fn v = minimum_value_operator(f, Fn(1.0), unknowns, {Interval(-2, 2)}, 1e-8);  // a function of x1
//   Fn m = minimize_operator(f, Fn(1.0), unknowns, {Interval(-2, 2)}, 1e-8);       // ~ x1
//
// Point evaluation at free values p: genmod::minimize() over the unknowns and the free
// coordinates together, the free sides degenerate ([p, p], never split), with options epsilon
// and delta = epsilon. minimum_value_operator = the midpoint of the guaranteed bracket;
// minimize_operator = the
// verified feasible best_point (within about epsilon of a minimizer, not refined). NaN when
// the problem is infeasible, no point was verified feasible (equality constraints: see
// minimizer.hpp) or the bracket is wider than delta (a limit stopped the search).
//
// Inclusion of the minimum value over a box P of the free coordinates, with f*(p) the minimum:
//  * lower: the guaranteed lower bound of the joint minimization over domain x P (<= f*(p)
//    for every p in P), minus delta;
//  * upper: if the x part x* of the joint best point satisfies the constraint on [x*] x P for
//    certain (no possible error), f(x*, P).hi() >= f*(p) for every p; otherwise the natural
//    bound of the objective over domain x P. Plus delta (point values lie within delta of f*).
// Errors: proven infeasible -> empty + kCertainError; kNoError when x* was feasible for all of
// P; otherwise kMaybeError. The minimizer point's inclusion: with U the value inclusion's upper
// end, every point value q at p in P is feasible with f(q, p) <= U, so it lies in a box the
// constraint solver returns for "f(x, p) <= U && constraint" over domain x P; the result is
// the hull of those boxes widened by epsilon, always with kMaybeError (a point value may fail
// to be verified).
//
// Continuity: none is claimed (CustomOp's default). The minimizer jumps when another point
// becomes the global minimizer, and the value shares the operator with it (one claim covers
// all outputs of an operator); so Newton does not go through these operators.
//
// Derivatives (valid for interior minima, or where the constraints are inactive): the minimum
// value by the envelope theorem, df*/dp = (df/dp)(x*(p), p); the minimizer point by the
// implicit function theorem on grad_x f = 0, dx*/dp = -H_xx^{-1} H_xp (Cramer's rule, n <= 4;
// NaN for larger n or a singular Hessian).
#pragma once

#include "genmod/kernel/coordinates.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/solvers/box.hpp"

#include <span>

namespace genmod {

// The global minimizer (dimension n = unknowns.size()). Throws std::invalid_argument naming the
// problem for: a non-scalar objective or constraint, no unknowns, an unknown repeated or out of
// range, a domain of the wrong dimension or with an empty, NaN or unbounded side, an epsilon
// that is not finite and > 0.
Fn minimize_operator(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& domain,
            double epsilon);

// GENMOD's "all solutions up to a maximum" form: 1 + K n components (K = max_solutions >= 1):
// the number of global minimizers found (at most K; minimizers closer than about epsilon count
// as one), then K minimizer points in lexicographic order (NaN where fewer). Inclusions: every
// slot holds the hull of all near-minimal feasible points, and the count is [0, K] with
// kMaybeError (the minimizer does not certify counts). Derivatives per slot as for minimize_operator().
Fn minimize_all_operator(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& domain,
                double epsilon, int max_solutions);

// The minimum value (scalar); same arguments and errors as minimize_operator().
Fn minimum_value_operator(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& domain,
                 double epsilon);

}  // namespace genmod
