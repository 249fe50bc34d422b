// Bloomenthal's starfish joint (research/bloomenthal.md §4, §7.1; the thesis's Figs.
// 5.71-5.73 and its appendix A.2): one parent limb and four children meeting at the origin,
// all of radius 0.1, in the plane z = 0.
//
// Three densities (positive inside, surface at 1/2) over the same skeleton:
//  * convolution: the sum of Gaussian segment convolutions (ConvolveValue; bulges at the joint);
//  * union: max over limbs of Gauss(dist(p, union segment)/r), the capsule union around the
//    union segments, whose free ends are moved in by r so the caps reach the original ends;
//  * combination (JointValue): convolution + convexity (union - convolution), convexity =
//    1 - Ease(angle(grad convolution, joint-plane normal) / (pi/2)): the union above and
//    below the flat joint (no bulge), the convolution in the webbing (a fillet).
// The gradient in the convexity is the symbolic gradient of the convolution density (the
// source uses forward differences with delta = 0.00025; both give the same angle to ~1e-3).
// `starfish_implicit` wraps a density to genmod's convention: f = 1/2 - D < 0 inside.
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/operators/skeletal.hpp"

#include <vector>

namespace genmod::models {

struct StarfishLimb {
  Point3 e1, e2;                // the limb
  Point3 union1, union2;        // the union segment (free ends moved in by the radius)
  Point3 n1, n2;                // joint-plane normals at the ends
  double r1, r2;                // radii at the ends
  int parent;                   // index of the parent limb, -1 for the root
};

// The skeleton of MakeJoint after SetLimb (pre-order: the root first).
std::vector<StarfishLimb> starfish_limbs();

struct StarfishFields {
  Fn convolution, union_density, convexity, combination;  // densities of (x(0), x(1), x(2))
};
StarfishFields starfish_fields(const std::vector<StarfishLimb>& limbs = starfish_limbs());

enum class StarfishVariant { combination = 0, convolution = 1, union_of_capsules = 2 };
// f = 1/2 - D for the chosen density.
Fn starfish_implicit(StarfishVariant variant = StarfishVariant::combination);

}  // namespace genmod::models
