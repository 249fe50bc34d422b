// Global minimization with constraints: Snyder's Algorithm 5.2 (snyder.md sections 4.13-4.15).
//
// Best-first branch and bound over boxes of the unknowns. Each box gets a lower bound of the
// objective from interval inclusion functions (natural extension, mean value form and
// monotonicity form, intersected; section 4.5-4.6); boxes the constraint proves infeasible or
// whose lower bound exceeds the best verified upper bound are discarded. The upper bound u
// comes only from points *proven* feasible, with the objective bounded rigorously there.
//
// Example:
//   Fn x0 = x(0), x1 = x(1);
//   Fn f = square(x0 - 0.3) + square(x1 + 0.2);
//   Fn c = x0 + x1 >= 1.0;                                 // 0/1 valued; Fn(1.0) for none
//   const int unknowns[] = {0, 1};
//   Box box = {Interval(-1, 1), Interval(-1, 1)};
//   MinimizeOptions opt;                                   // epsilon 1e-4, delta 1e-6
//   MinimizeResult r = minimize(f, c, unknowns, box, opt);
//   // r.minimum = [lo, hi] contains 0.405; r.candidates cover every minimizer ((0.75, 0.25));
//   // r.best_point is a proven-feasible point with f(best_point) <= hi.
//   Interval v = minimum_value(f, c, unknowns, box, opt); // faster: stops at width delta
//
// Guarantees (exact arithmetic is replaced by outward-rounded intervals throughout):
//  * feasible set S = { x in box : the constraint is nonzero at x and it and the objective
//    evaluate without error at x }. If S is nonempty, f* = min over S exists when f is
//    continuous (otherwise read f* as the infimum);
//  * minimum.lo() <= f* always (also when a limit was hit: unprocessed boxes count as
//    candidates);
//  * minimum.hi() is +inf unless a point was proven feasible: the constraint's interval
//    evaluation at the degenerate box [q, q] excludes 0 with no possible error; then
//    minimum.hi() >= f(q) >= f* and best_point = q; or (exact equalities, below) a box B was
//    certified to hold a feasible point: minimum.hi() >= sup f(B) >= f* and best_point is
//    B's midpoint (within B's tiny width of a feasible point, not itself proven feasible);
//  * every minimizer lies in the union of `candidates` (candidates are never dropped, even when
//    a limit stops the search);
//  * `infeasible` = true only when every box was proven infeasible (S is empty).
//
// Equality constraints (section 4.13 caveat): no floating point can be proven to satisfy
// g(x) = 0 exactly. With eta = 0 (the default) the top-level equalities g_1..g_m = 0 (m <= n,
// reached from the root through `and`) get certified feasible points instead (rule 3): in a
// box (every pushed box the constraint does not decide, and a small box around each local
// search result) n - m coordinates are fixed at the midpoint, interval Newton on the other m
// contracts and Krawczyk certifies a box B holding a zero of g; if every other atom of the
// constraint is true on all of B, B holds a feasible point and u = sup f(B) is rigorous. So
// minimize(x + y, x^2 + y^2 = 1) terminates with a bracket of width delta. Equalities below an
// `or`, or more equalities than unknowns, get no certified points (then the bracket may stay
// [lo, +inf)). Alternatively set `equality_tolerance` = eta > 0 to relax every equality
// eq(a, b) reached from the root through and / or to |a - b| <= eta (vector equalities: each
// component). The bracket is then a guaranteed bracket of the *relaxed* problem's minimum
// f*_eta, and since the relaxed feasible set contains the original one,
// minimum.lo() <= f*_eta <= f* still bounds the original problem from below.
//
// Constraint use in the bounds: every box is first contracted with HC4 against the constraint
// (only infeasible points are removed, so no minimizer is lost). When the constraint is a
// conjunction, its inequalities g <= 0 and equalities g = 0 also give a Lagrangian lower
// bound: f(x) >= f(x) + sum lambda_i g_i(x) at every feasible x for any lambda_i >= 0
// (inequalities; any sign for equalities), so the inclusion of that function over a box is a
// valid lower bound whatever lambda is. lambda is the least-squares KKT estimate at the best
// point (constraints with g >= -1e-3 there count as active; inequality multipliers clipped at
// 0); near a KKT point the Lagrangian is flat and its mean value form second order, so boxes at
// a constrained minimizer need not shrink to width delta. The upper bound u comes from points
// proven feasible: box midpoints, a local descent, and the KKT point near the descent's end
// (Newton's method on grad f + sum lambda_i grad g_i = 0 and the active g_i = 0), moved a few
// ulps inside its active inequalities where it can be proven feasible, so u is f* to about
// 1e-13 once the search is near a regular constrained minimum (Rosen-Suzuki at the default
// delta 1e-6: 4,071 boxes and a 5e-8 bracket; 110,204 boxes with the descent alone).
//
// The search is deterministic: the same input gives bitwise the same result, for any thread count
// (ties in the best-first list are broken by insertion order).
//
// Monotonicity test (section 4.15, sound version): if the constraint is true on a
// neighbourhood of a box Y (checked on Y widened by one ulp) and 0 is not in the enclosure of
// df/dx_j over Y, a minimizer in Y lies on the face where f is smaller; if that face is inside
// the search box Y is discarded, otherwise Y is reduced to it.
#pragma once

#include "genmod/kernel/coordinates.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/inclusion.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/solvers/box.hpp"
#include "genmod/solvers/limits.hpp"

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace genmod {

// One step of the search, for tracing the invariants of snyder.md claim 21.
struct MinimizeStep {
  std::size_t iteration = 0;  // boxes taken from the list so far
  double lower = 0.0;         // l_n: smallest lower bound over the list and the candidates
  double upper = 0.0;         // u_n: best verified upper bound (+inf before the first)
  std::size_t list_size = 0;  // boxes waiting
  std::size_t candidates = 0; // boxes accepted so far
};

struct MinimizeOptions {
  // A box is accepted as a candidate when its widest side is <= epsilon (parameter-space
  // tolerance, the thesis's acc), and, once a verified upper bound u exists, its lower bound is
  // >= u - delta (so that candidates never keep the bracket wider than delta).
  double epsilon = 1e-4;
  // Target width of the bracket [lo, hi]. minimum_value() stops as soon as hi - lo <= delta.
  double delta = 1e-6;
  SearchLimits limits;
  // Monotonicity test of section 4.15 (discard / reduce boxes where f is monotone).
  bool monotonicity_test = true;
  // Inclusion forms intersected for the objective's bounds (InclusionForm bits; the natural
  // extension is always used).
  unsigned inclusion_forms = kAllForms;
  // Local descent from box midpoints to lower the upper bound faster (section 4.13
  // enhancements); its points are verified rigorously before they are used.
  bool local_search = true;
  // eta of the equality relaxation (see above); 0 = no relaxation. Must be >= 0.
  double equality_tolerance = 0.0;
  // Worker threads (0 = oneTBB's default, 1 = none): the two halves of a split box are
  // contracted and bounded at once, then entered in order, so the result is bitwise the same
  // for any thread count. One by default: starting workers costs about a millisecond per
  // call, which nested operators and queries (one search per evaluation) would pay each
  // time; a single long search gains (Rosen-Suzuki: 1.2-1.3x less wall time on 2 cores).
  int threads = 1;
  // Called after every box taken from the list (optional).
  std::function<void(const MinimizeStep&)> on_step;
};

struct MinimizeResult {
  // Guaranteed bracket of the minimum value: lo <= f* <= hi (hi = +inf without a verified
  // feasible point). Empty when the problem is proven infeasible.
  Interval minimum = Interval::empty();
  // Boxes (one interval per unknown, in the order of `unknowns`) whose union holds every
  // global minimizer. Sorted by lower bound of the objective.
  std::vector<Box> candidates;
  // Lower bound of the objective on each candidate (same order).
  std::vector<double> candidate_lower_bounds;
  // A verified feasible point with f(best_point) <= minimum.hi() (empty if none was found):
  // either the point whose rigorous objective bound gave hi, or the midpoint of a box proven
  // feasible whose objective enclosure gave hi (update rules 1 and 2 of section 4.13), or the
  // midpoint of a tiny box certified to hold a feasible point (exact equalities, rule 3).
  std::vector<double> best_point;
  bool feasible_found = false;  // best_point is set and minimum.hi() is finite
  bool infeasible = false;      // proven: no point of the box satisfies the constraint
  bool delta_reached = false;   // minimum.width() <= delta
  SearchReport report;
  std::size_t local_searches = 0;   // local descents run
  std::size_t certified_points = 0; // boxes certified to hold a feasible point (exact equalities)
  std::size_t monotone_discards = 0;  // boxes discarded by the monotonicity test
  std::size_t monotone_reductions = 0;  // boxes reduced to a face by it
};

// Minimizes the scalar `objective` over the points of `box` (box[k] is the range of
// x(unknowns[k])) where the scalar `constraint` is nonzero. Both functions may depend only on
// the unknowns. Throws std::invalid_argument naming the problem for: a non-scalar objective
// or constraint, a dependency on a coordinate that is not an unknown, repeated or out of range
// unknowns, a box of the wrong dimension or with an empty / unbounded / NaN side,
// epsilon or delta not finite and > 0, a negative or NaN equality_tolerance, threads < 0.
MinimizeResult minimize(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& box,
                        const MinimizeOptions& options = {});

// The "minimum value" variant (snyder.md section 2.4.13): the guaranteed bracket only. Stops as
// soon as its width is <= options.delta, which is usually much earlier than minimize(); with
// several minimizers it bounds the value better than evaluating at one approximate minimizer.
// If a limit stops it first, the bracket returned is still guaranteed but may be wider than
// delta; minimize_value() gives the same computation with the full report.
Interval minimum_value(const Fn& objective, const Fn& constraint, Coordinates unknowns, const Box& box,
                       const MinimizeOptions& options = {});

// minimum_value() with the full result (candidates are the boxes still open when it stopped).
MinimizeResult minimize_value(const Fn& objective, const Fn& constraint, Coordinates unknowns,
                              const Box& box, const MinimizeOptions& options = {});

// The constraint with every equality reachable through and / or relaxed to |a - b| <= eta
// (what minimize() uses when options.equality_tolerance = eta > 0).
Fn relax_equalities(const Fn& constraint, double eta);

}  // namespace genmod
