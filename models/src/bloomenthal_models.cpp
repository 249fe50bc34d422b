// Bloomenthal's branching demos, arm, hand and the benchmark tree (bloomenthal_models.hpp).
#include "genmod/models/bloomenthal_models.hpp"

#include "genmod/operators/convolution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace genmod::models {
namespace {

using V = std::array<double, 3>;
V add(V a, V b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V mul(double s, V a) { return {s * a[0], s * a[1], s * a[2]}; }
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
V unit(V a) { return mul(1 / std::sqrt(dot(a, a)), a); }
double rad(double deg) { return deg * std::numbers::pi / 180; }

// 3x3 rotations, row-major, applied as M v.
using M = std::array<V, 3>;
V apply(const M& m, V v) { return {dot(m[0], v), dot(m[1], v), dot(m[2], v)}; }
M mulm(const M& a, const M& b) {
  M r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  return r;
}
M rot_x(double deg) {
  const double c = std::cos(rad(deg)), s = std::sin(rad(deg));
  return {V{1, 0, 0}, V{0, c, -s}, V{0, s, c}};
}
M rot_z(double deg) {
  const double c = std::cos(rad(deg)), s = std::sin(rad(deg));
  return {V{c, -s, 0}, V{s, c, 0}, V{0, 0, 1}};
}
// Rotation by angle (radians) about the unit axis k (Rodrigues).
V rotate_about(V v, V k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return add(add(mul(c, v), mul(s, cross(k, v))), mul(dot(k, v) * (1 - c), k));
}

void check_positive(double v, const char* what) {
  if (!(v > 0) || !std::isfinite(v)) throw std::invalid_argument(std::string(what) + " must be finite and > 0");
}

}  // namespace

namespace {
Fn convolve(const ConvolutionSegment& s, Kernel kernel) {
  return kernel == Kernel::gaussian ? segment_convolution(s.a, s.b, s.r1, s.r2) : segment_convolution(s.a, s.b, s.r1, s.r2, kernel);
}
}  // namespace

std::vector<FieldElement> convolution_elements(const std::vector<ConvolutionSegment>& segments, Kernel kernel) {
  std::vector<FieldElement> es;
  es.reserve(segments.size());
  for (const ConvolutionSegment& s : segments) {
    const double r = std::max(s.r1, s.r2);
    if (kernel == Kernel::gaussian)
      es.push_back(gaussian_segment_element(s.a, s.b, s.r1, s.r2));
    else
      es.push_back({convolve(s, kernel), s.a, s.b, 1.0, std::sqrt(2.0) * kernel_support(kernel) * r, Falloff::compact});
  }
  return es;
}

Fn culled_convolution(const std::vector<ConvolutionSegment>& segments, Kernel kernel) {
  return culled_field(convolution_elements(segments, kernel));
}

Fn summed_convolution(const std::vector<ConvolutionSegment>& segments, Kernel kernel) {
  if (segments.empty()) throw std::invalid_argument("summed_convolution: no segments");
  // A balanced sum keeps the expression shallow for thousands of terms.
  std::vector<Fn> terms;
  terms.reserve(segments.size());
  for (const ConvolutionSegment& s : segments) terms.push_back(convolve(s, kernel));
  while (terms.size() > 1) {
    std::vector<Fn> next;
    next.reserve((terms.size() + 1) / 2);
    for (std::size_t i = 0; i + 1 < terms.size(); i += 2) next.push_back(terms[i] + terms[i + 1]);
    if (terms.size() % 2) next.push_back(terms.back());
    terms = std::move(next);
  }
  return terms[0];
}

// ---- §7.5 ----------------------------------------------------------------------------------

Fn rotated_pair_density(double bend_degrees, double r, double length) {
  check_positive(r, "rotated pair radius");
  check_positive(length, "rotated pair length");
  if (!(bend_degrees >= 0 && bend_degrees <= 90)) throw std::invalid_argument("rotated pair bend must be in [0, 90] degrees");
  const double a = rad(bend_degrees);
  return segment_convolution({-length, 0, 0}, {0, 0, 0}, r) +
         segment_convolution({0, 0, 0}, {length * std::cos(a), length * std::sin(a), 0}, r);
}

std::vector<SkeletonLimb> trifurcated_limbs(double r_child, double spread_degrees, double length) {
  check_positive(r_child, "ramiform child radius");
  check_positive(length, "ramiform child length");
  if (!(spread_degrees > 0 && spread_degrees < 90)) throw std::invalid_argument("ramiform spread must be in (0, 90) degrees");
  const V o = ramiform_offset;
  std::vector<SkeletonLimb> limbs;
  limbs.push_back({add(o, V{0, -1, 0}), o, std::sqrt(3.0) * r_child});
  const double s = std::sin(rad(spread_degrees)), c = std::cos(rad(spread_degrees));
  for (int i = 0; i < 3; ++i) {
    const double az = rad(120.0 * i);
    const V d{s * std::cos(az), c, s * std::sin(az)};
    limbs.push_back({o, add(o, mul(length, d)), r_child});
  }
  return limbs;
}

Fn trifurcated_density(double r_child, double spread_degrees, double length) {
  const std::vector<SkeletonLimb> limbs = trifurcated_limbs(r_child, spread_degrees, length);
  return ramiform_density(limbs[0], std::span<const SkeletonLimb>(limbs).subspan(1));
}

namespace {
V arc_point(int i, int count) {
  const double t = std::numbers::pi * i / count;
  return {std::cos(t), std::sin(t), 0};
}
void check_arc(int count, double r) {
  if (count < 1 || count > 1000) throw std::invalid_argument("arc count must be in [1, 1000]");
  check_positive(r, "arc radius");
}
}  // namespace

Fn arc_segments_density(int count, double r) {
  check_arc(count, r);
  Fn d = 0.0;
  for (int i = 0; i < count; ++i) d = d + segment_convolution(arc_point(i, count), arc_point(i + 1, count), r);
  return d;
}

Fn arc_points_density(int count, double r) {
  check_arc(count, r);
  Fn d = 0.0;
  const double chord = 2 * std::sin(std::numbers::pi / (2 * count));
  const double w = chord / (r * std::sqrt(std::numbers::pi / kGaussOmega));
  for (int i = 0; i < count; ++i)
    d = d + point_source(mul(0.5, add(arc_point(i, count), arc_point(i + 1, count))), r, w);
  return d;
}

// ---- the arm ---------------------------------------------------------------------------------

std::vector<ConvolutionSegment> arm_segments(double elbow_degrees, double bulge) {
  if (!(elbow_degrees >= 0 && elbow_degrees <= 120)) throw std::invalid_argument("arm elbow must be in [0, 120] degrees");
  check_positive(bulge, "arm bulge");
  if (bulge > 1.5) throw std::invalid_argument("arm bulge must be <= 1.5");
  std::vector<ConvolutionSegment> out;
  // A muscle from p to q, offset by `side` (a vector perpendicular to the limb): tendon1 over
  // the first t1 of the length, bulge, tendon2 over the last t2; base radius rb.
  auto muscle = [&](V p, V q, V side, double t1, double t2, double rb) {
    const V a = add(p, side), b = add(q, side);
    const V m1 = add(a, mul(t1, sub(b, a))), m2 = add(a, mul(1 - t2, sub(b, a)));
    const double rt = 0.3 * rb, rmax = bulge * rb;
    out.push_back({a, m1, rt, rmax});
    out.push_back({m1, m2, rmax, rmax});
    out.push_back({m2, b, rmax, rt});
  };
  const V shoulder{0, 0, 0}, elbow{3.0, 0, 0};
  const double e = rad(elbow_degrees);
  const V fore{std::cos(e), std::sin(e), 0};
  const V wrist = add(elbow, mul(2.7, fore));
  const V up{0, 0, 1}, fore_side = cross(up, fore);  // in-plane perpendicular of the forearm
  // The bones: humerus, and radius and ulna side by side.
  out.push_back({shoulder, elbow, 0.32, 0.28});
  out.push_back({add(elbow, mul(0.1, fore_side)), add(wrist, mul(0.12, fore_side)), 0.2, 0.17});
  out.push_back({add(elbow, mul(-0.1, fore_side)), add(wrist, mul(-0.12, fore_side)), 0.2, 0.17});
  // Upper arm: biceps in front (+z), triceps behind (-z).
  muscle(add(shoulder, V{0.25, 0, 0}), add(elbow, V{-0.1, 0, 0}), V{0, 0, 0.18}, 0.25, 0.2, 0.42);
  muscle(add(shoulder, V{0.1, 0, 0}), add(elbow, V{0.1, 0, 0}), V{0, 0, -0.2}, 0.2, 0.3, 0.4);
  // Forearm: the flexor and extensor masses near the elbow, and the brachioradialis on top.
  muscle(elbow, wrist, add(mul(0.18, fore_side), V{0, 0, -0.1}), 0.1, 0.55, 0.34);
  muscle(elbow, wrist, add(mul(-0.18, fore_side), V{0, 0, -0.1}), 0.1, 0.5, 0.33);
  muscle(add(elbow, V{-0.3, 0, 0}), wrist, V{0, 0, 0.15}, 0.15, 0.5, 0.3);
  return out;
}

// ---- the hand --------------------------------------------------------------------------------

const std::vector<Finger>& finger_table() {
  static const std::vector<Finger> t = {
      {"thumb", 30, 20, 0, 30, 0.8, 0.8, 0.45, 0.1125},   {"index", 10, 15, 30, 10, 0.75, 0.6, 0.25, 0.0875},
      {"middle", 0, 15, 30, 10, 0.9, 0.7, 0.25, 0.0875},   {"ring", -10, 15, 25, 5, 0.85, 0.6, 0.35, 0.0875},
      {"pinkie", -25, 15, 25, 5, 0.65, 0.45, 0.3, 0.08},
  };
  return t;
}

std::vector<ConvolutionSegment> hand_segments(double grip, double palm_radius) {
  if (!(grip >= 0 && grip <= 2)) throw std::invalid_argument("hand grip must be in [0, 2]");
  check_positive(palm_radius, "hand palm_radius");
  if (palm_radius > 0.3) throw std::invalid_argument("hand palm_radius must be <= 0.3");
  std::vector<ConvolutionSegment> out;
  const V wrist{0, 0, 0};
  // Knuckles (first joints): thumb base, index, middle, ring, pinkie.
  const V knuckle[5] = {{-0.75, 0.5, 0}, {-0.55, 1.7, 0}, {-0.18, 1.75, 0}, {0.18, 1.7, 0}, {0.52, 1.6, 0}};
  const V wrist_base[5] = {{-0.35, 0.1, 0}, {-0.4, 0.2, 0}, {-0.13, 0.2, 0}, {0.13, 0.2, 0}, {0.38, 0.2, 0}};
  V second[5];  // the second knuckles
  for (int f = 0; f < 5; ++f) {
    const Finger& g = finger_table()[f];
    // The thumb turns 15 degrees further than its theta about the palm normal and flexes by phi
    // toward the palm like the fingers: the reconstruction's Rz(theta + 60) Ry(-phi) sent it
    // straight out sideways (Ry leaves the bone's axis +y where it is), a stick at right angles.
    const M r1 = f == 0 ? mulm(rot_z(g.theta + 15), rot_x(-g.phi)) : mulm(rot_z(g.theta), rot_x(-g.phi));
    const M r2 = mulm(r1, rot_x(-grip * g.grip2));
    const M r3 = mulm(r2, rot_x(-grip * g.grip3));
    const V y{0, 1, 0};
    const V p0 = knuckle[f], p1 = add(p0, mul(g.length1, apply(r1, y))), p2 = add(p1, mul(g.length2, apply(r2, y))),
            p3 = add(p2, mul(g.length3 - 0.6 * g.radius, apply(r3, y)));
    second[f] = p1;
    const double r = g.radius;
    out.push_back({p0, p1, 1.1 * r, r});
    out.push_back({p1, p2, r, 0.92 * r});
    out.push_back({p2, p3, 0.92 * r, 0.8 * r});
    // The metacarpal (palm bone) of this finger.
    out.push_back({wrist_base[f], p0, (f == 0 ? 1.0 : 1.05) * palm_radius, (f == 0 ? 0.8 : 0.75) * palm_radius});
  }
  // Knuckle bar and wrist bar tie the palm together; the heel of the hand under the thumb.
  out.push_back({knuckle[1], knuckle[4], 0.7 * palm_radius, 0.7 * palm_radius});
  out.push_back({V{-0.45, 0.1, 0}, V{0.45, 0.1, 0}, 0.9 * palm_radius, 0.9 * palm_radius});
  out.push_back({V{0, -0.5, 0}, wrist, 0.35, 0.3});  // the wrist stub
  // Tendons on the back of the hand (+z), mid-palm to each second knuckle, 2 segments, half
  // buried in the back so that they raise ridges (lifted higher, they bridge over the finger
  // and the mesh gets a handle).
  for (int f = 1; f < 5; ++f) {
    const V a = add(mul(0.5, add(wrist_base[f], knuckle[f])), V{0, 0, 0.6 * palm_radius});
    const V b = add(knuckle[f], V{0, 0, 0.45 * palm_radius});
    const V c = add(second[f], V{0, 0, 0.5 * finger_table()[f].radius});
    out.push_back({a, b, 0.03, 0.03});
    out.push_back({b, c, 0.03, 0.03});
  }
  const V thumb_mid = add(mul(0.5, add(wrist_base[0], knuckle[0])), V{0, 0, 0.6 * palm_radius});
  const V thumb_second = add(second[0], V{0, 0, 0.5 * finger_table()[0].radius});
  out.push_back({thumb_mid, add(knuckle[0], V{0, 0, 0.45 * palm_radius}), 0.03, 0.03});
  out.push_back({add(knuckle[0], V{0, 0, 0.45 * palm_radius}), thumb_second, 0.03, 0.03});
  // Veins on the back: polylines of 6 and 5 segments, radius 0.02, starting inside the wrist
  // stub (started outside it, their ends poked out of the wrist as two spikes).
  const V vein1[7] = {{-0.22, -0.1, 0.18}, {-0.25, 0.05, 0.2}, {-0.32, 0.4, 0.19}, {-0.28, 0.75, 0.19},
                      {-0.38, 1.05, 0.18}, {-0.42, 1.3, 0.16}, {-0.5, 1.5, 0.14}};
  const V vein2[6] = {{0.2, -0.1, 0.18}, {0.22, 0.1, 0.2}, {0.3, 0.45, 0.19}, {0.18, 0.8, 0.19}, {0.12, 1.15, 0.18},
                      {0.08, 1.45, 0.15}};
  // The polylines are given for palm_radius 0.2 and sunk into the back with it.
  auto sunk = [&](V v) { return V{v[0], v[1], v[2] * palm_radius / 0.2 - 0.03}; };
  for (int i = 0; i < 6; ++i) out.push_back({sunk(vein1[i]), sunk(vein1[i + 1]), 0.02, 0.02});
  for (int i = 0; i < 5; ++i) out.push_back({sunk(vein2[i]), sunk(vein2[i + 1]), 0.02, 0.02});
  // The adductor pollicis: thumb base to the index metacarpal.
  out.push_back({add(knuckle[0], V{0.05, 0.05, -0.05}), V{-0.35, 1.0, -0.05}, 0.12, 0.1});
  return out;
}

// ---- the benchmark tree ---------------------------------------------------------------------

std::vector<ConvolutionSegment> tree_segments(int count, std::uint32_t seed, double length, double radius) {
  if (count < 1) throw std::invalid_argument("tree_segments: count must be >= 1");
  check_positive(length, "tree length");
  check_positive(radius, "tree radius");
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 2 * std::numbers::pi);
  struct Node {
    V a, b;
    double r;
    int generation;
  };
  std::vector<Node> nodes;
  nodes.push_back({{0, 0, 0}, {0, 0, length}, radius, 0});
  for (std::size_t parent = 0; nodes.size() < static_cast<std::size_t>(count); ++parent) {
    const Node p = nodes[parent];
    const V dir = unit(sub(p.b, p.a));
    // A perpendicular of dir, turned about dir by a random angle: the bending axis.
    const V any = std::abs(dir[0]) < 0.9 ? V{1, 0, 0} : V{0, 1, 0};
    const V perp = unit(cross(dir, any));
    const double phase = u(rng);
    for (int k = 0; k < 2 && nodes.size() < static_cast<std::size_t>(count); ++k) {
      const V axis = rotate_about(perp, dir, phase + k * std::numbers::pi);
      const V d = rotate_about(dir, axis, rad(35));
      const double s = std::pow(0.97, p.generation + 1);
      nodes.push_back({p.b, add(p.b, mul(length * s, d)), radius * s, p.generation + 1});
    }
  }
  std::vector<ConvolutionSegment> out;
  out.reserve(nodes.size());
  for (const Node& n : nodes) out.push_back({n.a, n.b, n.r, n.r});
  return out;
}

SegmentBounds segment_bounds(const std::vector<ConvolutionSegment>& segments, double margin) {
  SegmentBounds b{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
  for (const ConvolutionSegment& s : segments)
    for (int i = 0; i < 3; ++i) {
      const double r = margin * std::max(s.r1, s.r2);
      b.lo[i] = std::min({b.lo[i], s.a[i] - r, s.b[i] - r});
      b.hi[i] = std::max({b.hi[i], s.a[i] + r, s.b[i] + r});
    }
  return b;
}

}  // namespace genmod::models

namespace genmod::models {

MapleLeaf maple_leaf(double vein_radius) {
  check_positive(vein_radius, "maple leaf vein_radius");
  if (vein_radius > 0.1) throw std::invalid_argument("maple leaf vein_radius must be <= 0.1");
  MapleLeaf leaf;
  const double angles[5] = {-70, -35, 0, 35, 70}, lengths[5] = {0.7, 0.9, 1.0, 0.9, 0.7};
  const Fn X = x(0), Y = x(1), Z = x(2);
  Fn outline;
  leaf.veins.push_back({{0, -0.3, 0}, {0, 0, 0}, vein_radius, vein_radius});
  for (int i = 0; i < 5; ++i) {
    const double a = rad(angles[i]), L = lengths[i];
    const V d{std::sin(a), std::cos(a), 0};
    leaf.veins.push_back({{0, 0, 0}, mul(L, d), vein_radius, 0.5 * vein_radius});
    // The lobe: (u / (0.55 L))^2 + (v / (0.3 L))^2 - 1 about the centre 0.55 L d, u along d.
    const V c = mul(0.55 * L, d);
    const Fn u = (X - c[0]) * d[0] + (Y - c[1]) * d[1], v = (Y - c[1]) * d[0] - (X - c[0]) * d[1];
    const Fn lobe = square(u / (0.55 * L)) + square(v / (0.3 * L)) - 1.0;
    outline = i == 0 ? lobe : min(outline, lobe);
  }
  leaf.vein_density = summed_convolution(leaf.veins);
  leaf.blade_inside = -outline;
  const Fn az = abs(Z);
  // Arg max: the vein (scaled by 100 so it wins wherever r (sum D - 0.02) exceeds |z| by 1%),
  // beyond (outside the outline), above and below (inside it). The floor 0.02 (sum D below
  // it: farther than about 2.4 r from a vein) removes the film of "vein" thinner than a cube
  // that the source's rule r sum D > |z| leaves along the whole blade (there it is lost as
  // looped intersections, or caught by a sample exactly on the blade).
  leaf.regions = {-leaf.blade_inside, 100.0 * (vein_radius * (leaf.vein_density - 0.02) - az), min(Z, leaf.blade_inside),
                  min(-Z, leaf.blade_inside)};
  return leaf;
}

std::vector<std::pair<int, int>> maple_leaf_interest() { return {{1, 2}, {1, 3}, {2, 3}, {0, 1}}; }

}  // namespace genmod::models
