// Bloomenthal's branching demos (research/bloomenthal.md §7.5), the arm (§7.3) and the hand
// (§7.2) as skeletons of Gaussian segment convolutions, for the implicit gallery
// (implicit_gallery.hpp) and tests/models/bloomenthal_models_test.cpp.
//
// All densities D follow convolution.hpp (positive, surface at D = 1/2) except the ramiform,
// whose distance density r^2/d^2 has its surface at 1 (eq. 5.36). The arm, the hand and the
// benchmark tree are sums of many elements built with culled_field (culled_field.hpp), so the
// mesher's interval evaluation over a box skips the elements far from it.
//
// Example:
//   using namespace genmod::models;
//   Fn f = density_to_implicit(rotated_pair_density(60.0, 0.15));
//   Fn hand = density_to_implicit(culled_convolution(hand_segments()));   // 1/2 - D < 0 inside
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/culled_field.hpp"
#include "genmod/operators/skeletal.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace genmod::models {

// A skeleton segment with end radii (Gaussian convolution, tapered when r1 != r2).
struct ConvolutionSegment {
  Point3 a, b;
  double r1, r2;
};
// One culled_field element per segment. Gaussian kernel: gaussian_segment_element (radius
// max(r1, r2), weight 1, the taper set: the values and first derivatives are culled; the
// Hessian tape the mesher uses pays every segment). B-spline or Wyvill kernel: Falloff::compact
// with the support sqrt(2) kernel_support(kernel) max(r1, r2) (convolution.hpp), so the
// derivatives are culled as the values are.
std::vector<FieldElement> convolution_elements(const std::vector<ConvolutionSegment>& segments,
                                               Kernel kernel = Kernel::gaussian);
// The culled sum of the segments' convolutions (a density).
Fn culled_convolution(const std::vector<ConvolutionSegment>& segments, Kernel kernel = Kernel::gaussian);
// The plain sum of the same convolutions (no culling; the benchmark's baseline).
Fn summed_convolution(const std::vector<ConvolutionSegment>& segments, Kernel kernel = Kernel::gaussian);

// ---- §7.5 demos ------------------------------------------------------------------------

// The rotated pair (Fig. 5.46): segments (-length, 0, 0) -> (0, 0, 0) and (0, 0, 0) ->
// length (cos a, sin a, 0), a = bend_degrees (0 = straight, 90 = a right angle), both of
// radius r. The two half-limbs add to Gauss(d/r) at the shared end, so the height above the
// joint is r at every angle (no bulge), and the field is smooth (no crease).
Fn rotated_pair_density(double bend_degrees, double r, double length = 1.0);

// The trifurcated ramiform (Fig. 5.59, eq. 5.36): a parent along +y from (0, -1, 0) to the
// junction (0, 0, 0) and three children of radius r_child and the given length, spread
// `spread_degrees` from the parent's direction (one in the xy-plane toward +x, the others at
// 120 degrees about the y axis), the parent radius sqrt(3) r_child. The skeleton is moved by
// `ramiform_offset` so that no cell corner of a gallery box lies on it (the density is
// singular there). Density r^2/d^2, surface at 1.
std::vector<SkeletonLimb> trifurcated_limbs(double r_child, double spread_degrees, double length = 0.8);
inline constexpr Point3 ramiform_offset{0.0123, 0.0071, 0.0093};
Fn trifurcated_density(double r_child, double spread_degrees, double length = 0.8);

// Segments against points (Fig. 5.57): a half circle of radius 1 (centre the origin, from
// (1, 0, 0) over +y to (-1, 0, 0)) split into `count` chords, either convolved as segments of
// radius r or as `count` Gaussian point sources at the chords' midpoints, each of weight
// chord / (r sqrt(pi / omega)) (the subtended normalized area, claim 22).
Fn arc_segments_density(int count, double r);
Fn arc_points_density(int count, double r);

// ---- the arm (§7.3) and the hand (§7.2) -----------------------------------------------

// The arm [a reconstruction: the source gives five muscle polygons, three in the forearm and
// two in the upper arm, each tendon1-bulge-tendon2; we use tapered segments for them]: the
// upper arm along +x from the shoulder (0, 0, 0) to the elbow (3, 0, 0) with the biceps and
// triceps, the forearm from the elbow to the wrist, 2.7 long, bent by `elbow_degrees` in the
// xy-plane, with three forearm muscles; each muscle is tendon (radius 0.3 bulge) -> bulge
// (radius `bulge` times the muscle's base radius) -> tendon, plus the bones (humerus, radius
// and ulna) as thin segments. Inches, like the hand.
std::vector<ConvolutionSegment> arm_segments(double elbow_degrees = 30.0, double bulge = 1.0);

// The hand: the finger table of §7.2 (angles in degrees, lengths in inches) and a
// reconstruction of the rest (§7.2's "proposed demo"): palm in the xy-plane, fingers toward
// +y, back of the hand toward +z. Fingers are three tapered phalanx segments from their
// knuckle, bent by R1 = Rz(theta) Rx(-phi), then Rx(-grip2), Rx(-grip3) (the thumb:
// Rz(theta + 15) Rx(-phi), pointing 45 degrees off the fingers and flexed toward the palm;
// the research notes' Rz(theta + 60) Ry(-phi) points it straight out sideways, as Ry leaves
// the bone axis unchanged); the palm is five metacarpal segments of radius `palm_radius`
// from the wrist to the knuckles plus a knuckle bar and a wrist bar; tendons (radius 0.03)
// lie on the back of the hand from mid-palm to the second knuckles; two veins (6 and 5
// segments, radius 0.02) on the back; the adductor pollicis is one segment (radius 0.12).
struct Finger {
  std::string name;
  double theta, phi, grip2, grip3, length1, length2, length3, radius;
};
const std::vector<Finger>& finger_table();
// grip scales every grip2 and grip3 (0 = straight fingers, 1 = the table).
std::vector<ConvolutionSegment> hand_segments(double grip = 1.0, double palm_radius = 0.2);

// The benchmark skeleton: a tree of `count` segments grown from a trunk on the z axis: each
// segment starts at the end of an earlier one (the parents are visited in order, two children
// each), length `length` times 0.97 per generation and radius `radius` times 0.97 per
// generation, directions turned from the parent's by 35 degrees about a pseudo-random axis
// (seeded). Returns the segments; `bounds` receives their box enlarged by 3 radii.
std::vector<ConvolutionSegment> tree_segments(int count, std::uint32_t seed = 1, double length = 1.0,
                                              double radius = 0.12);
struct SegmentBounds {
  Point3 lo, hi;
};
SegmentBounds segment_bounds(const std::vector<ConvolutionSegment>& segments, double margin);

}  // namespace genmod::models

namespace genmod::models {

// The maple leaf (§7.4) [a reconstruction: the specimen's 117 points are not given]: five
// primary veins in the plane z = 0 fanning from the petiole base (0, 0, 0) at -70, -35, 0, 35
// and 70 degrees from +y, lengths 0.7, 0.9, 1.0, 0.9, 0.7, Gaussian segment convolutions of
// radius `vein_radius` tapering to 0.5 of it, plus the petiole (0, -0.3, 0) -> (0, 0, 0); the
// blade is the plane z = 0 inside the union of five lobes (an ellipse about each primary
// vein, half-axes 0.55 length and 0.3 length, centred at 0.55 of the vein) -- no cupping.
// Four regions for polygonize_regions, as arg max of the returned functions:
//   0 beyond the blade, 1 inside a vein (vein_radius * (sum D - 0.02) > |z|: the source's
//   blend rule with the nearest radius taken constant and a floor that drops the thin film
//   it leaves along the whole blade), 2 above the blade, 3 below.
// maple_leaf_interest() gives the pairs {(1,2), (1,3), (2,3), (0,1)}: the blade is the (2,3)
// sheet, ending in free borders at the margin; the veins are closed against 0, 2 and 3; and
// the edges where the blade meets a vein are shared by the (1,2), (1,3) and (2,3) sheets.
struct MapleLeaf {
  std::vector<Fn> regions;              // g_0..g_3 of (x(0), x(1), x(2))
  std::vector<ConvolutionSegment> veins;
  Fn vein_density, blade_inside;        // sum D; > 0 inside the outline (in the plane)
};
MapleLeaf maple_leaf(double vein_radius = 0.04);
std::vector<std::pair<int, int>> maple_leaf_interest();

}  // namespace genmod::models
