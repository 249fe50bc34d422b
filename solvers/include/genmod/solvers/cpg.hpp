// CPG: Boolean operations on planar regions given by their boundary curves (snyder.md sections
// 7.17 and 7.19). The result is the boundary of the combined region as one closed curve, built
// from pieces of the operands (and fillet arcs), so it is an ordinary Fn of x(0) that sweeps,
// interpolation and tessellation accept like any cross section.
//
// Example:
//   const double pi = std::numbers::pi;
//   Fn a = cat({cos(2 * pi * x(0)), sin(2 * pi * x(0))});
//   Fn b = cat({1 + cos(2 * pi * x(0)), sin(2 * pi * x(0))});
//   Fn lens = region_boolean(a, b, RegionOp::Intersection);          // two arcs, two corners
//   CpgOptions smooth;
//   smooth.fillet_radius = 0.1;
//   Fn blob = region_boolean(a, b, RegionOp::Union, smooth);         // G1 everywhere
//
// Method. The boundaries meet at the hits of curve_intersections, each certified (exactly one
// crossing in its box) or, where interval Newton cannot certify a tiny hit box (polyline Curves,
// whose derivative is piecewise), with point tangents that are clearly not parallel; a tangency
// is refused either way. They split each boundary into pieces between consecutive
// hits; each piece is classified inside or outside the other region by counting the certified
// crossings of a ray from its midpoint with the other boundary (a ray that meets the boundary
// uncertifiably, e.g. tangentially, is replaced by another direction). The classification must
// alternate along each boundary (transversal crossings), which is checked. The result takes
//   Union = a_out + b_out, Intersection = a_in + b_in, Difference (a minus b) = a_out + b_in reversed,
// linked hit to hit into loops; exactly one loop is accepted. Pieces are sub-curves
// compose(a, 0, s0 + (s1 - s0) x(0)) (a piece across a curve's closing point is joined from the
// two ends with a select), concatenated with parameter shares proportional to their lengths.
//
// Fillets (fillet_radius r > 0): at each corner the offsets of the incoming and the outgoing
// piece by r toward the fillet's center (the inside of a convex corner, the outside of a
// concave one; offset_curve(), positive = left of travel) are intersected near the corner; the
// hit is the center of a circular arc of radius r tangent to both pieces, which are trimmed at
// its foot points (where their offsets pass through the center). The arc turns the same way as
// the corner. Each fillet must fit in its two adjacent pieces.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/solvers/queries.hpp"

namespace genmod {

enum class RegionOp { Union, Intersection, Difference };  // Difference = a minus b

struct CpgOptions {
  double fillet_radius = 0.0;  // 0: sharp corners
  QueryOptions query;          // tolerance and limits of the intersection and ray searches
};

// a and b: closed planar curves of x(0) alone on [0, 1] (a(0) = a(1)), counter-clockwise, meeting
// transversally. Returns the boundary of the resulting region as one closed CCW curve of x(0) on
// [0, 1]. Throws std::invalid_argument naming the problem when: a curve is not planar, not a
// function of x(0) alone, not closed or not counter-clockwise; the fillet radius is negative or
// not finite; the curves do not intersect (disjoint or nested: no single boundary results); an
// intersection or a classification is not certified (tangency); a search limit was hit; the
// result is not one closed curve (the message gives the number of loops); a fillet does not fit.
Fn region_boolean(const Fn& a, const Fn& b, RegionOp op, const CpgOptions& options = {});

}  // namespace genmod
