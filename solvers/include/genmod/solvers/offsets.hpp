// Offsets of parametric shapes by nested interval search (snyder.md section 5.1).
//
// For a parametric shape S: D -> R^n (a curve or surface given as an Fn of its parameters)
// and a radius r, with d(z) = min over x in D of |z - S(x)|:
//  * the s-offset S↑r = { z : d(z) <= r } (Rossignac-Requicha), a region;
//  * the b-offset S∂r = { z : d(z) = r }, which contains the boundary of S↑r and needs no
//    classification of the shape's singular points.
// Both are computed by an outer branch-and-prune over boxes Z of space, where each box gets a
// guaranteed bracket of d over Z from an inner global minimization (Algorithm 5.2 nested in
// Algorithm 5.1):
//   lower: the minimum of |z - S(x)|^2 over x in D and z in Z jointly (minimize_value);
//   upper: max over z in Z of |z - S(x*)|^2 for the best parameter x* found (any fixed x*
//          bounds min_x from above for every z at once).
// A box is dropped only when its bracket proves it misses the set, so no part of the offset
// is lost; boxes narrower than epsilon that remain undecided are returned as Boundary.
//
// Example:
//   Fn segment = cat({2 * x(0) - 1, Fn(0.0)});            // [(-1, 0), (1, 0)]
//   Box region = {Interval(-2, 2), Interval(-2, 2)};
//   OffsetResult stadium = b_offset(segment, 0.25, region);
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/solvers/box.hpp"
#include "genmod/solvers/limits.hpp"

#include <span>
#include <vector>

namespace genmod {

struct OffsetOptions {
  double epsilon = 1e-2;    // boxes of space narrower than this are accepted
  SearchLimits limits;      // of the outer search (boxes of space)
  SearchLimits inner_limits{20'000, 200, 0.0};  // of each inner minimization
};

enum class OffsetBoxStatus { Inside, Boundary };

struct OffsetBox {
  Box box;                 // a box of space
  OffsetBoxStatus status;  // Inside: every point has d <= r (s-offset only)
};

struct OffsetResult {
  std::vector<OffsetBox> boxes;
  SearchReport report;  // of the outer search; unexplored boxes are returned as Boundary
};

// The b-offset {z in region : d(z) = r}: Boundary boxes covering it.
OffsetResult b_offset(const Fn& shape, double r, std::span<const Interval> region, std::span<const Interval> domain = {},
                      const OffsetOptions& options = {});

// The s-offset {z in region : d(z) <= r}: Inside boxes and Boundary boxes covering it.
OffsetResult s_offset(const Fn& shape, double r, std::span<const Interval> region, std::span<const Interval> domain = {},
                      const OffsetOptions& options = {});

}  // namespace genmod
