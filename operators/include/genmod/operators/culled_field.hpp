// Superposition of many skeletal elements with per-box culling (Bloomenthal §1.4, §10.2).
//
// A culled field is the sum of element densities D_e(p) >= 0, as one custom operator of the
// point p. Its point value is the full sum. Its inclusion over a box X skips each element
// whose skeleton is far from X and adds a sound remainder in its place: with delta a lower
// bound of dist(X, skeleton_e) (from the skeleton's bounding box, with a rounding margin),
//  * Falloff::gaussian: D_e <= weight * Gauss(delta / radius) (valid for Gaussian point
//    sources of radius `radius` and for Gaussian segment convolutions with radius = the larger
//    endpoint radius, spec §10.2), so a culled element contributes [0, that bound];
//  * Falloff::compact: D_e = 0 when delta >= radius (the support), so it contributes [0, 0].
// An element is culled when its bound is at most `cull_below` (precomputed as a distance per
// element, so the test is one box distance in double arithmetic with a rounding margin).
//
// The elements sit in a bounding-volume hierarchy of their skeleton boxes, built once: a
// subtree whose box is beyond the largest cull distance of its elements is culled with one
// test, as a CSG tree prunes a branch, and contributes [0, n * b] for its n Gaussian elements,
// b = min(cull_below, Gauss bound at the subtree's distance with its largest weight and
// radius) (compact ones [0, 0]); the elements that are not culled are bounded by their own
// (kernel) inclusion functions. A box thus visits only the part of the hierarchy near it:
// fields of thousands of elements prune per box.
//
// Point value. With cull_below > 0 the value at p is the sum, in index order, of the elements
// a walk of the same hierarchy visits at p, and it lies within
//   2^-60 max(M, cull_below)  (plus the rounding of the elements and of the sum)
// of the exact sum of all elements, M the sum of |D_e(p)| over the visited elements. The walk
// at a threshold t skips a subtree whose bound at p's distance (the box bound above, with the
// subtree's largest weight, radius and taper) is at most t, and a compact element beyond its
// support (exactly 0 there); the skipped bounds add up to R. If R <= 2^-60 max(M, cull_below),
// that sum is the value; otherwise the walk is repeated at t = 2^-61 max(M, cull_below) / n
// (n the Gaussian elements in the hierarchy), which meets it (M only grows), and, should
// rounding defeat that, at t = 0 (every element). The first walk guesses M = w, the largest
// weight: t = 2^-61 max(w, cull_below) / n (2^-71 to 2^-74 for 1,000 to 10,000 unit-weight
// elements), so a point visits the elements within about 8.5 radii and rarely walks twice.
// The value is a function of p alone (deterministic). With cull_below = 0 it is the full sum
// (compact elements beyond their support, exactly 0 there, skipped). So that the inclusion
// holds these values, it is widened by 2^-59 max(M_X, cull_below), M_X >= M over the box
// (downward only for the densities: every skipped element is >= 0).
//
// The derivative is a culled field of the elements' partial derivatives: compact elements are
// culled as their densities are (remainder 0); a Gaussian element that declares itself a
// Gaussian convolution (taper >= 0, as the factories below do) is culled by the rigorous bound
//   |dD_e/dx_k| <= weight exp(-omega s^2) [(c0 + c1 s) + taper (c2 + c1 s^2)] / radius,
//   s = delta / radius >= 1.5, c0 = sqrt(omega/pi), c1 = 2 omega, c2 = 2/sqrt(2 pi e)
// (derived in culled_field_bounds.cpp), contributing [-b, b]. The second derivatives (the
// derivative's derivative, as an implicit mesher's Hessian) of a constant-radius Gaussian
// element (taper == 0: segments with r1 == r2 and point sources) are culled by
//   |d^2 D_e / dx_j dx_k| <= weight c1 exp(-omega s^2) [(1 + c2) + 3 c0 s + c1 s^2] / radius^2,
//   s = delta / radius >= 2
// (derived there too), contributing [-b, b]. Other Gaussian elements' derivatives (taper < 0;
// second derivatives of tapered segments) and all third and higher derivatives of Gaussian
// elements are never culled. A derivative's point value follows the point rule above with the
// derivative's bound (a skipped subtree counts [-b, b]): it is within 2^-60 max(M, cull_below)
// of the exact partial sum.
//
// Example:
//   Point3 a{0, 0, 0}, b{1, 0, 0};
//   double r = 0.1;
//   std::vector<FieldElement> es;
//   es.push_back({segment_convolution(a, b, r), a, b, 1.0, r, Falloff::gaussian});
//   es.push_back(gaussian_segment_element(b, {1, 1, 0}, r, 2 * r));  // derivatives culled too
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
  // gaussian only. >= 0: the density is `weight` times a Gaussian point source of this radius
  // (point_source) or a Gaussian segment convolution of a-b whose larger end radius is
  // `radius` (segment_convolution), and taper >= |r2 - r1| / |b - a| (0 for a constant radius
  // or a point): its first derivatives are then culled by the bound above, and with taper
  // exactly 0 its second derivatives too. Negative (the default, for densities of another
  // form): its derivatives are never culled.
  double taper = -1;
};

// The elements of the usual Gaussian densities, with every culling parameter set:
// segment_convolution(a, b, r1, r2) and point_source(c, r, weight).
FieldElement gaussian_segment_element(const Point3& a, const Point3& b, double r1, double r2);
FieldElement gaussian_point_element(const Point3& c, double r, double weight = 1.0);

struct CulledFieldOptions {
  // Cull an element whose bound over the box is at most this. Also the point value's floor:
  // its tolerance is 2^-60 max(M, cull_below) (above); 0 makes points sum every element.
  double cull_below = 1e-6;
  // Visit the elements through the hierarchy (true) or test every element against every box
  // (false: a linear scan, the baseline the hierarchy is measured and tested against). Both
  // give sound bounds; the hierarchy's remainders are at least as tight.
  bool hierarchy = true;
  // Cull the second derivatives of constant-radius Gaussian elements (above). false: they are
  // evaluated on every box, as before issue 11's Hessian culling (the benchmarks' baseline).
  bool cull_second_derivatives = true;
};

// The culled sum of `elements` as a scalar Fn of p = (x(0), x(1), x(2)). With `p` given, of
// that point instead. std::invalid_argument for no elements, non-scalar densities, densities
// depending on other inputs, or non-finite parameters.
Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options = {});
Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options, const Fn& p);

// The bound that culling uses for one element over a box (exposed for tests): an upper bound
// of D_e over the box, +infinity when the element cannot be culled there.
double culled_element_bound(const FieldElement& element, std::span<const Interval> box);
// The same for the element's partial derivatives of order 1 or 2: an upper bound of |dD_e/dx_k|
// (order 1) or |d^2 D_e / dx_j dx_k| (order 2) over the box for every j, k; +infinity where no
// bound is claimed (Falloff::none, a Gaussian element with taper < 0 (order 1) or != 0 (order
// 2), a box nearer than 1.5 (order 1) or 2 (order 2) radii to a Gaussian skeleton, or within a
// compact element's support). std::invalid_argument for another order.
double culled_derivative_bound(const FieldElement& element, std::span<const Interval> box, int order = 1);

}  // namespace genmod
