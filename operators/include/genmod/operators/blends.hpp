// Blends of skeletal primitives (Bloomenthal, research/bloomenthal.md §2.4). Union and
// intersection are min / max (shapes.hpp's csg_union / csg_intersection).
//
// Two families, by the sign convention of their operands:
//  * implicit operands (f < 0 inside: distance surfaces, signed distances): average_blend,
//    range_blend (Rockwood's elliptic / super-elliptic, eqs. 5.12, 5.13, 5.18), rolling_ball_blend;
//  * density operands (P in [0, 1], larger inside): product_blend (eq. 5.16), and
//    convexity_blend (eqs. 5.15, 5.17, 5.37), which interpolates any two fields.
// All are kernel Fns except convexity_blend, a custom operator whose inclusion is the convex
// combination bound hull(B, U) (spec §10.2) without the convexity's own interval.
#pragma once

#include "genmod/kernel/fn.hpp"

#include <initializer_list>
#include <span>
#include <vector>

namespace genmod {

// The mean of the fields (Fig. 5.25's global blend): smooth, loses local detail.
Fn average_blend(std::span<const Fn> fields);
Fn average_blend(std::initializer_list<Fn> fields);

// Rockwood's range-controlled blend of implicit primitives P_i (f < 0 inside) with ranges of
// influence r_i > 0 and integer thumbweight t >= 2 (t = 2: elliptic, eq. 5.12):
// B = 1 - sum_i [1 - P_i / r_i]_+^t. Where p is beyond the range of all but primitive i the
// blend heels to 1 - (1 - P_i/r_i)^t, whose zero set is P_i = 0. B < 0 inside.
Fn range_blend(std::span<const Fn> primitives, std::span<const double> ranges, int thumbweight = 2);
Fn range_blend(std::initializer_list<Fn> primitives, std::initializer_list<double> ranges, int thumbweight = 2);

// The rolling-ball (circular) blend of two signed distances a, b with ball radius rho > 0:
// max(rho, min(a, b)) - |([rho - a]_+, [rho - b]_+)|. Equals min(a, b) wherever
// max(a, b) >= rho (the ball touches one field only); for two planes it is the exact fillet
// swept by a ball of radius rho rolling on both.
Fn rolling_ball_blend(const Fn& a, const Fn& b, double rho);

// The product ("probabilistic sum") blend of densities in [0, 1]: 1 - (1 - P1)(1 - P2).
Fn product_blend(const Fn& p1, const Fn& p2);
// The decreasing profile h(x) = 1 - Ease(x) for the product blend's primitives (§2.4.5).
Fn decay(const Fn& x);

// Convexity-interpolated blend: B + [c]_{0,1} (U - B) with c clamped to [0, 1] (eq. 5.17 with
// the clamp on both sides). Its inclusion is hull(B, U) intersected with the natural
// extension, so no interval of c is needed (its errors still propagate).
Fn convexity_blend(const Fn& blend, const Fn& union_field, const Fn& convexity);

// Grouping against unwanted blends (§6.7, Fig. 6.18): element i blends only with the elements
// of blend_with[i]. The source gives no formula; this reconstruction takes each element's
// density plus its blend set's, and the union of the results in genmod's convention:
// f = min_i (iso - (D_i + sum_{j in blend_with[i]} D_j)). With every set holding all other
// elements it is iso - sum D (plain superposition); with empty sets it is the union of the
// isolated elements. Indices must be valid and not name the element itself.
Fn grouped_blend(std::span<const Fn> densities, const std::vector<std::vector<int>>& blend_with, double iso = 0.5);

// acos(c)^2 for c in [-1, 1] (error outside), with a derivative that is defined at c = 1.
Fn acos_squared(const Fn& c);
// The combination surface's convexity (§4.4): 1 - Ease(acos(|c|) / (pi/2)) of the cosine c of
// the angle between the field's gradient and the joint-plane normal: 1 when they are parallel
// (convex: take the union), 0 when perpendicular (concave: take the blend). Built on
// acos_squared so that its gradient has no 0 * infinity where c = 1.
Fn convexity_from_cosine(const Fn& cosine);

}  // namespace genmod
