// Furry bear (thesis Fig 3.23, research/snyder.md 7.24): a vector field on a surface,
// V(u, v): R^2 -> R^6 = (point on the scalp, tip of the hair). The thesis gives no formulas;
// the substitute: the scalp S is a profile-product body (a circle swept by the authored
// profile curves/furry_bear_profile.crv, a belly, a neck and a head), and the hair at S is
// the straight segment
//   S -> S + hair_length normalize(N + kappa S_v),   N = S_u x S_v (outward),
// combed toward S_v (up the body): it leans from the normal toward S_v by the angle
// atan(kappa |S_v| / |N|) (N is perpendicular to S_v). The main surface is the scalp; the
// hair field is furry_bear_hair(p) (for renderers that draw segments or texels).
// For meshing, the bear is one closed surface: a grid of hairs, one per cell of the scalp's
// parameter square, each a thin closed tube that starts on the scalp at a root ring (the
// image of a small ellipse about the cell's centre), and the scalp with a hole at each root
// (the root's cell in four pieces between the ellipse and the cell's sides). The union of
// scalp and hair is a trim (Snyder's Algorithm 5.4 with the intersection curve known
// exactly): the ring is an edge of both, evaluated by the same operations at the same
// parameters, so the mesher glues them sample for sample and no surface/surface
// intersection is needed. Two caps about the poles (v < 0.2 / hair_rows and the same at the
// top) are meshed as the plain scalp; the first and last rows of cells start at their rims.
#include "genmod/models/gallery.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/sweep.hpp"
#include "genmod/operators/vector.hpp"
#include "hair_clearance.hpp"
#include "model_definitions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace genmod::models {

namespace {
Fn scalp(const ParameterValues& p) {
  const double size = detail::require_positive(p, "size");
  const Fn theta = x(0) * (2.0 * std::numbers::pi);
  const Fn profile = gallery_curve("furry_bear_profile")(x(1)) * size;
  return profile_product(cat({cos(theta), sin(theta)}), profile);
}

// The hair parameters (checked when the model is built, too).
double kappa_of(const ParameterValues& p) {
  const double kappa = detail::param(p, "kappa");
  if (!(kappa >= 0.0)) throw std::invalid_argument("parameter 'kappa' must be >= 0, got " + std::to_string(kappa));
  return kappa;
}

// hair_rows: a whole number in [1, kMaxHairRows] (2 rows^2 hairs, at most 392).
constexpr double kMaxHairRows = 14;
int hair_rows_of(const ParameterValues& p) {
  const double rows = detail::param(p, "hair_rows");
  if (!(rows >= 1.0 && rows <= kMaxHairRows && rows == std::floor(rows)))
    throw std::invalid_argument("parameter 'hair_rows' must be a whole number in [1, 14], got " + std::to_string(rows));
  return static_cast<int>(rows);
}

// The hair at the centre of each cell: its scalp point, direction and the root ellipse.
struct Hair {
  HairRoot root;
  std::array<double, 3> base, direction;
};

// Angle of the root ellipse at the start of piece 0 (the cell's lower left corner's side).
constexpr double kPhi0 = -0.75 * std::numbers::pi;

// The root ellipse at theta in [0, 1] (one turn from kPhi0) as offsets from the cell's centre
// in the scalp's parameters. The hair tube and the scalp pieces both build it from theta by
// this one function and add it to the centre last, so their shared edge is evaluated by the
// same operations at the same (dyadic) theta: bitwise equal.
std::array<Fn, 2> root_offset(const HairRoot& r, const Fn& theta) {
  const Fn phi = theta * (2.0 * std::numbers::pi) + kPhi0;
  return {r.a * cos(phi), r.b * sin(phi)};
}

Fn scalp_at(const Fn& scalp_surface, const Fn& u, const Fn& v) {
  const int uv[2] = {0, 1};
  return compose_all(scalp_surface, uv, cat({u, v}));
}

// A radius about the hair's axis that holds its whole tube. The tube's cross section at s is
// the root ring scaled by 1 - s^2 about the axis point S + s L d, so the largest distance of
// the ring from S bounds it. Sampled at 64 points: between samples the distance can grow by
// at most half the ring's arc between them (pi / 64 of its radius, 5%); 10% is added.
double tube_radius(PointEvaluator& ev, const Tape& surface, const Hair& h) {
  constexpr int kSamples = 64;
  double largest = 0.0;
  for (int k = 0; k < kSamples; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / kSamples;
    const auto e = ev.eval(surface, {h.root.u + h.root.a * std::cos(phi), h.root.v + h.root.b * std::sin(phi)});
    largest = std::max(largest, std::hypot(e[0] - h.base[0], e[1] - h.base[1], e[2] - h.base[2]));
  }
  return 1.1 * largest;
}

// Hairs combed toward a pole converge on it (the lean atan(kappa / |S_u|) grows to 90 degrees
// where the scalp's circles shrink): with many rows, a large kappa or long hairs the top
// row's tubes cross each other (hair_rows 14 at the defaults: 4,546 intersecting triangle
// pairs). Such parameters are rejected, naming the hairs: a convex hull about each hair's
// axis, tapering with the tube (hair_clearance.hpp), holds the tube and its mesh, so apart
// hulls give apart tubes.
void require_hairs_apart(const ParameterValues& p, int rows, const std::vector<Hair>& hairs,
                         const std::vector<detail::HairCapsule>& capsules) {
  const std::optional<detail::HairOverlap> overlap = detail::deepest_hair_overlap(capsules);
  if (!overlap) return;
  const HairRoot &a = hairs[overlap->a].root, &b = hairs[overlap->b].root;
  auto at = [](const HairRoot& r) { return "(" + std::to_string(r.u) + ", " + std::to_string(r.v) + ")"; };
  throw std::invalid_argument(
      "parameters 'hair_rows' (" + std::to_string(rows) + "), 'kappa' (" + std::to_string(detail::param(p, "kappa")) +
      ") and 'hair_length' (" + std::to_string(detail::param(p, "hair_length")) + "): the hairs rooted at (u, v) = " +
      at(a) + " and " + at(b) + " come " + std::to_string(overlap->distance) +
      " apart where their tubes' radii add up to " + std::to_string(overlap->radii) +
      ", so the tubes may cross; use fewer hair_rows, a smaller kappa or a shorter hair_length");
}

std::vector<Hair> hairs_of(const ParameterValues& p) {
  const int rows = hair_rows_of(p), around = 2 * rows;
  const double radius = detail::require_positive(p, "hair_radius");
  const double length = detail::require_positive(p, "hair_length");
  const Fn s = scalp(p);
  const Tape hair(furry_bear_hair(p), std::vector<int>{0, 1});
  const Tape jacobian(cat({derivative(s, 0), derivative(s, 1)}), std::vector<int>{0, 1});
  const Tape surface(s, std::vector<int>{0, 1});
  PointEvaluator ev;
  std::vector<Hair> hairs;
  std::vector<detail::HairCapsule> capsules;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double u = (i + 0.5) / around, v = (j + 0.5) / rows;
      // Copies: an evaluation's result lives in the evaluator's scratch until the next one.
      const auto hair_at = ev.eval(hair, {u, v});
      const std::vector<double> h(hair_at.begin(), hair_at.end());
      const auto jac = ev.eval(jacobian, {u, v});
      const double a = radius / std::hypot(jac[0], jac[1], jac[2]), b = radius / std::hypot(jac[3], jac[4], jac[5]);
      // The ellipse within the middle half of its cell keeps the four pieces around it
      // fan-like (each segment from the ellipse to the cell's side stays in its quarter).
      if (!(a <= 0.25 / around && b <= 0.25 / rows))
        throw std::invalid_argument("parameter 'hair_radius' (" + std::to_string(radius) +
                                    ") is too large for hair_rows " + std::to_string(rows) +
                                    ": the root of the hair at (u, v) = (" + std::to_string(u) + ", " +
                                    std::to_string(v) + ") does not fit in its cell");
      hairs.push_back({{u, v, a, b},
                       {h[0], h[1], h[2]},
                       {(h[3] - h[0]) / length, (h[4] - h[1]) / length, (h[5] - h[2]) / length}});
      capsules.push_back({{h[0], h[1], h[2]}, {h[3], h[4], h[5]}, tube_radius(ev, surface, hairs.back())});
    }
  require_hairs_apart(p, rows, hairs, capsules);
  return hairs;
}

// The tube of one hair: T(theta, s) = E + s L d + ((1 - s)(1 + s) - 1)(E - S). At s = 0 the
// added terms are exact zeros, so T is E bit for bit (the piece's r = 0 edge); at s = 1 it is
// the tip S + L d (a pole).
Fn hair_tube(const Fn& scalp_surface, const Hair& h, double length) {
  const auto [ou, ov] = root_offset(h.root, x(0));
  const Fn ring = scalp_at(scalp_surface, h.root.u + ou, h.root.v + ov);
  const Fn s = x(1), shrink = (1.0 - s) * (1.0 + s) - 1.0;
  std::vector<Fn> xyz;
  for (int k = 0; k < 3; ++k) xyz.push_back(ring[k] + s * (length * h.direction[k]) + shrink * (ring[k] - h.base[k]));
  return cat(xyz);
}

// Piece k (0 bottom, 1 right, 2 top, 3 left) of a hair's cell between its root ellipse and
// the cell's side: (t, r) -> S(c + (1 - r) e + r side), c the cell's centre, e the ellipse's
// offset at theta = (k + t) / 4 (exact in binary for the mesher's dyadic t), side the offset
// of the side from corner k to corner k + 1, counterclockwise. Blending offsets rather than
// points keeps the interval enclosures narrow (a blend of two values near u = 1 would widen
// by |u| times the width of r), and at r = 1 the corners come out as the neighbours' (exactly
// where the difference from the centre is exact).
Fn scalp_piece(const Fn& scalp_surface, const HairRoot& root, double ul, double uh, double vl, double vh, int k) {
  // Differences from the centre (exact where Sterbenz applies: within a factor 2, or 0).
  const double cu[5] = {ul - root.u, uh - root.u, uh - root.u, ul - root.u, ul - root.u};
  const double cv[5] = {vl - root.v, vl - root.v, vh - root.v, vh - root.v, vl - root.v};
  const Fn t = x(0), r = x(1);
  const auto [eu, ev] = root_offset(root, t * 0.25 + 0.25 * k);
  auto side = [&](const double c[5]) { return c[k] == c[k + 1] ? Fn(c[k]) : (1.0 - t) * c[k] + t * c[k + 1]; };
  const Fn u = root.u + ((1.0 - r) * eu + r * side(cu));
  const Fn v = root.v + ((1.0 - r) * ev + r * side(cv));
  return scalp_at(scalp_surface, u, v);
}
}  // namespace

Fn furry_bear_hair(const ParameterValues& p) {
  const double length = detail::require_positive(p, "hair_length");
  const double kappa = kappa_of(p);
  const Fn s = scalp(p);
  const Fn su = derivative(s, 0), sv = derivative(s, 1);
  const Fn direction = normalize(cross(su, sv) + kappa * sv);
  return cat({s, s + length * direction});
}

std::vector<HairRoot> furry_bear_roots(const ParameterValues& p) {
  std::vector<HairRoot> roots;
  for (const Hair& h : hairs_of(p)) roots.push_back(h.root);
  return roots;
}

std::vector<ModelPatch> furry_bear_scalp_pieces(const ParameterValues& p) {
  const Fn s = scalp(p);
  const int rows = hair_rows_of(p), around = 2 * rows;
  const std::vector<Hair> hairs = hairs_of(p);
  // The polar caps: the first and last rows of cells would reach the poles as wedges of
  // 360 / (2 rows) degrees, and with few rows (2 to 4) the triangles of such a wide wedge
  // near the flat bottom folded over each other (16 to 28 intersecting pairs at the gallery
  // test's tolerance) although within the distance bound. Near a pole the scalp is meshed
  // as the plain surface of revolution instead, out to v = cap (below every root ellipse,
  // whose lowest v is >= 0.25 / rows), and the cells start there.
  const double cap = 0.2 / rows;
  std::vector<ModelPatch> pieces;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double ul = static_cast<double>(i) / around, uh = static_cast<double>(i + 1) / around;
      const double vl = j == 0 ? cap : static_cast<double>(j) / rows;
      const double vh = j == rows - 1 ? 1.0 - cap : static_cast<double>(j + 1) / rows;
      for (int k = 0; k < 4; ++k)
        pieces.push_back({scalp_piece(s, hairs[static_cast<std::size_t>(j * around + i)].root, ul, uh, vl, vh, k)});
    }
  // One cap piece per column of cells, so that each meets its cells' sides edge to edge (one
  // periodic cap would meet them in parts at rounded grid parameters: 1.2e-9 apart).
  for (const auto& [lo, hi] : {std::pair{0.0, cap}, std::pair{1.0 - cap, 1.0}})
    for (int i = 0; i < around; ++i)
      pieces.push_back({s, Interval(static_cast<double>(i) / around, static_cast<double>(i + 1) / around), Interval(lo, hi)});
  return pieces;
}

std::vector<ModelPatch> furry_bear_hairs(const ParameterValues& p) {
  const Fn s = scalp(p);
  const double length = detail::require_positive(p, "hair_length");
  std::vector<ModelPatch> tubes;
  for (const Hair& h : hairs_of(p)) {
    ModelPatch tube{hair_tube(s, h, length)};
    tube.periodic_u = true;
    tubes.push_back(tube);
  }
  return tubes;
}

namespace detail {

Model furry_bear_model() {
  Model m;
  m.name = "furry_bear";
  m.description = "thesis Fig 3.23: a profile-product scalp carrying a combed hair field (R^2 -> R^6), meshed as one closed surface: the scalp with a hole at each hair's root ring, the hair a tube from it";
  m.parameters = {{"size", 1.0, "half the body's height (the body spans z in [-size, size])"},
                  {"hair_length", 0.08, "length of every hair"},
                  {"kappa", 1.5, "combing: the hair leans from the normal N toward S_v by atan(kappa |S_v| / |N|)"},
                  {"hair_rows", 12, "hairs output: hair_rows rows (in v) of 2 hair_rows hairs (in u), a whole number in [1, 14]; hairs combed toward the top pole converge, and combinations whose tubes may cross (14 rows at the default kappa and hair_length, long hairs) are rejected"},
                  {"hair_radius", 0.004, "radius of a hair at its root on the scalp (each hair is a thin tube from a root ring on the scalp, narrowing as 1 - s^2 to a point at its tip)"}};
  m.build = [](const ParameterValues& p) {
    require_positive(p, "hair_length");
    require_positive(p, "hair_radius");
    kappa_of(p);
    hairs_of(p);  // hair_rows, every root fits in its cell, no two tubes cross
    return scalp(p);
  };
  m.periodic_u = true;
  // The scalp's pieces first, then the tubes: the mesher glues each piece's quarter of a
  // root ring to the tube's whole ring.
  m.extra_patches = [](const ParameterValues& p) {
    std::vector<ModelPatch> patches = furry_bear_scalp_pieces(p), tubes = furry_bear_hairs(p);
    patches.insert(patches.end(), tubes.begin(), tubes.end());
    return patches;
  };
  m.surface_in_extra_patches = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
