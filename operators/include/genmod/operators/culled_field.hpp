// Superposition of many skeletal elements with per-box culling (Bloomenthal §1.4, §10.2).
//
// A culled field is the sum of element densities D_e(p) >= 0, as one custom operator of the
// point p. Its point value is the full sum. Its inclusion over a box X skips each element
// whose skeleton is far from X and adds a sound remainder in its place: with delta a lower
// bound of dist(X, skeleton_e) (from the skeleton's bounding box, in outward-rounded
// arithmetic),
//  * Falloff::gaussian: D_e <= weight * Gauss(delta / radius) (valid for Gaussian point
//    sources of radius `radius` and for Gaussian segment convolutions with radius = the larger
//    endpoint radius, spec §10.2), so a culled element contributes [0, that bound];
//  * Falloff::compact: D_e = 0 when delta >= radius (the support), so it contributes [0, 0].
// An element is culled when its bound is at most `cull_below` (precomputed as a distance per
// element, so the test is one box distance in double arithmetic with a rounding margin) and
// contributes [0, cull_below] (gaussian) or [0, 0] (compact); the others are bounded by their
// own (kernel) inclusion functions. The sum of all remainders keeps the result sound, so a
// field of thousands of elements prunes per box at the cost of one box distance per element
// (a linear scan: no hierarchy yet). Point evaluation skips compact elements whose support
// cannot reach the point (they are exactly 0 there). The derivative is a culled field of the
// elements' derivatives: compact ones culled as their elements, Gaussian ones never.
//
// Example:
//   Point3 a{0, 0, 0}, b{1, 0, 0};
//   double r = 0.1;
//   std::vector<FieldElement> es;
//   es.push_back({segment_convolution(a, b, r), a, b, 1.0, r, Falloff::gaussian});
//   Fn D = culled_field(es);
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/operators/skeletal.hpp"

#include <span>
#include <vector>

namespace genmod {

// gaussian and compact as above; none: never culled (any sign; e.g. a derivative).
enum class Falloff { gaussian, compact, none };

struct FieldElement {
  Fn density;       // D_e of (x(0), x(1), x(2)), >= 0
  Point3 a, b;      // the skeleton: the segment a-b (a point when a == b)
  double weight;    // gaussian: the density's peak bound factor; compact: unused (>= 0)
  double radius;    // gaussian: the Gaussian radius; compact: the support distance
  Falloff falloff;
};

struct CulledFieldOptions {
  double cull_below = 1e-6;  // cull an element whose bound over the box is at most this
};

// The culled sum of `elements` as a scalar Fn of p = (x(0), x(1), x(2)). With `p` given, of
// that point instead. std::invalid_argument for no elements, non-scalar densities, densities
// depending on other inputs, or non-finite parameters.
Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options = {});
Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options, const Fn& p);

// The bound that culling uses for one element over a box (exposed for tests): an upper bound
// of D_e over the box, +infinity when the element cannot be culled there.
double culled_element_bound(const FieldElement& element, std::span<const Interval> box);

}  // namespace genmod
