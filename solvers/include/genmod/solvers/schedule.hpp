// Parameter schedules (snyder.md sections 7.20 and 7.21): functions of a sweep parameter built by
// matching one curve against another with the inverse operator. Each result is an ordinary Fn
// (point value, inclusion, derivative through inverse() and compose()), so it nests in sweeps.
//
// Example:
//   using namespace genmod;
//   Fn v = x(1);
//   Fn radius = cat({v * v, 0.5 + 0.5 * v});         // (z, r): r as a curve over z, parameter v
//   Fn r_at_z = match_schedule(radius, v, 1);        // r where radius_x = v: 0.5 + 0.5 sqrt(v)
//
// Monotonicity of the inverted component in x(parm) over `domain` is the caller's promise (see
// inverse_operator.hpp): without it a point value is one of the roots and NaN where the value
// to match is not bracketed (outside the curve's range).
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"

namespace genmod {

// GENMOD's m_resample_y_by_curve generalized: c1 reparameterized in x(parm) so that its
// component `component` equals c2's at the same parameter value:
//   compose(c1, parm, inverse(c1[component], c2[component], parm, domain)).
// c2 is evaluated at the outer point (it may depend on x(parm) itself, as in the bottle).
// Throws std::invalid_argument naming the problem for: a component missing from c1 or c2, a parm
// out of range, c1[component] not depending on x(parm), or a bad domain (see inverse()).
Fn resample_by_curve(const Fn& c1, const Fn& c2, int parm, int component = 1, Interval domain = Interval(0, 1));

// Matching schedule (7.21): curve[1] at the parameter where curve[0] equals x1,
// i.e. curve[1](curve[0]^-1(x1)). curve is a planar curve of x(parm) (dimension >= 2; only the
// first two components are used) whose x component is monotone; x1 any scalar Fn (e.g. the z
// translation schedule of v). Throws std::invalid_argument for a curve of dimension < 2, a
// non-scalar x1, or the conditions of resample_by_curve.
Fn match_schedule(const Fn& curve, const Fn& x1, int parm, Interval domain = Interval(0, 1));

// GENMOD's m_warp of App. B.3: (m, w[1](w[0]^-1(|m|))): m (any dimension) gains a last
// coordinate, a function of its Euclidean length given by the planar curve w of x(parm) (w's x
// component monotone, spanning the lengths |m| takes). m may depend on x(parm) too: its length
// is the value matched, evaluated at the outer point. Throws std::invalid_argument for a w of
// dimension < 2 or the conditions of resample_by_curve.
Fn warp_by_length(const Fn& m, const Fn& w, int parm, Interval domain = Interval(0, 1));

}  // namespace genmod
