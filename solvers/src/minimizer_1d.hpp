// The minimize operator's common case, one unknown and no constraint (the closest point of a
// curve, reparameterize_to_closest): a point value polished to the root of df/dx, and an
// inclusion over a box of the free coordinates without a global search per box. Internal to
// the solvers layer (minimize_operator.cpp).
#pragma once

#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/tape.hpp"

#include <optional>
#include <span>

namespace genmod::detail {

// The tapes of f(x, p), df/dx and d2f/dx2, all with inputs (x, free coordinates...).
struct Objective1d {
  const Tape& f;
  const Tape& fx;
  const Tape& fxx;
  Interval domain;  // of x
};

// The local minimizer of f(., p) that descends from q (the first sign change of df/dx from
// - to + found by doubling steps from q toward the descent, then bisection to adjacent
// doubles): f decreases from q to it, so it is in q's level set. q itself when df/dx does not
// change sign between q and the domain's end in the descent direction (a minimum at the end:
// f decreases from q to the end), or is NaN there.
double polish_minimizer(const Objective1d& obj, double q, std::span<const double> p);

// The global minimizer of f(., p) without a search: the candidates of steps 1-2 below at
// P = [p, p] refined until every run is convex, each run descended from its middle by
// polish_minimizer (its ends too where they are the domain's), the least f of these. nullopt
// when a run is not convex or an evaluation may fail (the caller searches then).
std::optional<double> minimizer_1d(const Objective1d& obj, std::span<const double> p, double delta);

struct Enclosure1d {
  Interval minimizer;  // every point value (minimizer_1d, or a search polished as above) for p
                       // in the box, given f(q, p) <= f*(p) + delta
  Interval minimum;    // f*(p) for every p in the box (without delta)
  // One convex candidate run off the domain's ends: for every p in the box the minimizer is
  // unique, minimizer_1d finds it (never fails) and it is continuous in p.
  bool unique = false;
};

// The enclosure over the box P of the free coordinates, for point values q with
// f(q, p) <= f*(p) + delta polished by polish_minimizer:
//  1. U = the least f(m, P).hi() over midpoints m of a grid on the domain: f*(p) <= U on P;
//  2. candidate cells: f(cell, P).lo() <= U + delta (every point value lies in one), bisected
//     level by level while they are few;
//  3. in each run of adjacent candidates where d2f/dx2 > 0 on the run x P, a point value off the
//     domain's ends is the one root of df/dx(., p) there, bracketed by interval evaluations
//     of df/dx at single x down to `tolerance` (a run that touches an end keeps it).
// nullopt when an evaluation may fail (the caller's general method decides then).
std::optional<Enclosure1d> enclose_minimizer_1d(const Objective1d& obj, std::span<const Interval> P, double delta,
                                                double tolerance);

}  // namespace genmod::detail
