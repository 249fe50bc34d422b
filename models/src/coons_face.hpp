// A planar (or warped) face bounded by a closed edge curve, as one Coons patch: the models'
// caps (the plate's top and bottom, the key's top and bottom). Internal to the models layer.
#pragma once

#include "genmod/kernel/fn.hpp"

#include <array>

namespace genmod::models::detail {

// The bilinearly blended Coons patch of the closed curve edge(u) (a function of x(0) alone,
// with edge(0) = edge(1)), its boundary split into four arcs at the parameters
// corners[0] < corners[1] < corners[2] < corners[3] < corners[0] + 1, counterclockwise:
//   C(s, t) = (1 - t) B(s) + t T(s) + (1 - s) L(t) + s R(t) - (bilinear of the corners),
// (s, t) = (x(0), x(1)), with B = the arc corners[0] -> corners[1], R = corners[1] ->
// corners[2], T = corners[3] -> corners[2], L = corners[0] + 1 -> corners[3] (parameters
// wrapped into [0, 1)). Its edges are points of edge(u) (to rounding), so it meets the
// surface the edge came from; for a counterclockwise planar curve C_s x C_t points along
// +z. The corners are the patch's singular points (the boundary is smooth there), so put
// them where the curve turns (the middles of rounded corners).
Fn coons_face(const Fn& edge, const std::array<double, 4>& corners);

// The same face seen from the other side: (s, t) swapped, C_s x C_t points along -z.
Fn coons_face_flipped(const Fn& edge, const std::array<double, 4>& corners);

}  // namespace genmod::models::detail
