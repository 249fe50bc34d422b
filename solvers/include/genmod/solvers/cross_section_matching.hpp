// Matching the parameterizations of two cross sections before interpolating between them
// (snyder.md section 7.12). Linear interpolation pairs c1(u) with c2(u); when the curves start
// at different places the interpolated surface collapses (claim 29: circles of radius 1 and 2
// with a phase offset of pi give a cone with its apex at v = 1/3). Both remedies here return c1
// reparameterized (the same point set, a different speed), as an Fn with point values,
// inclusions and derivatives, ready for interp_cross_sections().
//
// Example:
//   const double pi = std::numbers::pi;
//   Fn u = x(0), v = x(1);
//   Fn c = cat({cos(2 * pi * u), sin(2 * pi * u)});
//   Fn d = -2.0 * c;                                              // radius 2, starting at angle pi
//   Fn s = interp_cross_sections(v, match_polar_angle(c, d, 0), d);   // |s(u, v)| = 1 + v
#pragma once

#include "genmod/kernel/fn.hpp"

namespace genmod {

// Remedy 2: c1 reparameterized so that its polar angle equals c2's at every parameter value:
// c1(s(u)) with angle(c1(s(u))) = angle(c2(u)) (mod 2 pi). Both curves are planar, closed,
// counter-clockwise and star-shaped around the origin, functions of x(parm) on [0, 1] (other
// coordinates stay free). The angles are unwrapped as theta_k(u) = atan2(c_k(0)) + integral_0^u
// of (x y' - y x') / (x^2 + y^2), which is continuous and increasing (star-shaped), normalized
// by its total so that it covers exactly one turn; the target angle is reduced modulo one turn
// (a floor), so s(u) jumps from 1 to 0 once where c1 closes, and c1(s(u)) stays continuous.
// Throws std::invalid_argument for curves that are not planar or do not depend on x(parm), or
// a parm out of range. Star shape, closedness and orientation are the caller's promise: where
// they fail the angle is not monotone and point values are NaN or one of several matches.
Fn match_polar_angle(const Fn& c1, const Fn& c2, int parm);

// Remedy 3 (minimum distance): inner reparameterized so that each point is the point of inner
// closest to outer(u): inner(s*(u)), s*(u) = argmin over s in [0, 1] of |inner(s) - outer(u)|,
// by the minimize operator (its point value is a verified global minimizer within about
// epsilon; a tie between two closest points picks one of them). The curves are functions of
// x(parm) of equal dimension; the search uses a coordinate neither curve depends on. Good when
// the curves are similar (each point of outer has one clear nearest point on inner); where the
// nearest point jumps, so does the result. Throws std::invalid_argument for unequal dimensions,
// curves not depending on x(parm), a parm out of range or an epsilon that is not finite and > 0.
Fn reparameterize_to_closest(const Fn& inner, const Fn& outer, int parm, double epsilon = 1e-7);

}  // namespace genmod
