// Sweeps of GENMOD (thesis section 3.1, research/snyder.md sections 7.1-7.11): profile, wire
// and rail products, quasi-linear transformations, and linear / Hermite interpolation of cross
// sections. Every operator is a plain composition of kernel Fns (scalarized, no custom
// operators), so point evaluation, inclusion functions and derivatives come from the kernel.
//
// Two calling styles:
//  * GENMOD style: the arguments are already functions of their parameters, e.g. a cross
//    section of u = x(0) and a profile of v = x(1):
//      Fn knob = profile_product(circle_of_u, profile_of_v);
//  * curve style (`*_surface`): every curve is given as a function of x(0) alone; the sweep
//    feeds the cross section u = x(0) and the profile / wire / rails v = x(1) by compose():
//      Fn knob = profile_surface(Curve::bezier(...)(x(0)), Curve::bspline(...)(x(0)));
//
// All products return a 3D function. Wrong dimensions throw std::invalid_argument naming the
// operator and the sizes.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/operators/matrix.hpp"

namespace genmod {

// `curve` (a function of x(0) only) with x(0) replaced by x(parm). Throws if the curve
// depends on any coordinate other than x(0).
Fn curve_in(const Fn& curve, int parm);

// Profile product (section 7.1): S = (g1 d1, g2 d1, d2) for a cross section g (dimension 2)
// and a profile d (dimension 2). A circular cross section gives a surface of revolution with
// radius d1(v) at height d2(v).
Fn profile_product(const Fn& cross, const Fn& profile);

// Wire product (section 7.5): t = d'/|d'| (derivative with respect to x(wire_parm)),
// n = (-t2, t1), S = (n1 g1 + d1, n2 g1 + d2, g2). The cross section's x axis goes to n, its
// y axis to world z, its origin to the wire point. The wire (dimension 2) must depend on
// x(wire_parm); the tangent is an error where the wire's speed vanishes.
Fn wire_product(const Fn& cross, const Fn& wire, int wire_parm = 1);

// Rail product (section 7.6): t = r2 - r1, m = (r1 + r2)/2, S = (t1 g1/2 + m1, t2 g1/2 + m2, g2).
// Cross-section points with g1 = -1 land on rail1 and those with g1 = +1 on rail2 (in xy).
// Cross section and rails have dimension 2.
Fn rail_product(const Fn& cross, const Fn& rail1, const Fn& rail2);

// Quasi-linear transformation (section 7.7): S = M g + T with a 3x3 matrix M and a 3D offset
// T (both may be functions of the sweep parameter). A 2D cross section is taken as z = 0.
Fn quasi_linear(const Fn& cross, const Matrix& m, const Fn& t);
// The homogeneous 4x4 [M T; 0 0 0 1] of a 3x3 M and a 3D T, for composing with the
// transforms of transform.hpp (matrices premultiply: the factor written last applies first).
Matrix homogeneous(const Matrix& m, const Fn& t);

// Linear interpolation of cross sections (section 7.10): c1 + alpha (c2 - c1); alpha scalar,
// c1 and c2 of equal dimension. The parameterizations of c1 and c2 define which points
// correspond (a phase mismatch collapses the surface, claim 29).
Fn interp_cross_sections(const Fn& alpha, const Fn& c1, const Fn& c2);
// Hermite interpolation of cross sections (section 7.11): H(0) = p1, H(1) = p2, H'(0) = t1,
// H'(1) = t2; alpha scalar, the others of equal dimension.
Fn hermite_cross_sections(const Fn& alpha, const Fn& p1, const Fn& p2, const Fn& t1, const Fn& t2);

// Curve-style sweeps: every argument is a curve of x(0); the result is a surface in
// (u, v) = (x(0), x(1)).
Fn profile_surface(const Fn& cross, const Fn& profile);
Fn wire_surface(const Fn& cross, const Fn& wire);
Fn rail_surface(const Fn& cross, const Fn& rail1, const Fn& rail2);
// (interp(v, c1(u), c2(u)), height(v)) for 2D cross sections c1, c2 and a scalar height:
// linear interpolation of cross sections with alpha = v.
Fn interp_surface(const Fn& c1, const Fn& c2, const Fn& height);

}  // namespace genmod
