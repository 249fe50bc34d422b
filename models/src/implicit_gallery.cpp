// The implicit gallery (implicit_gallery.hpp).
#include "genmod/models/implicit_gallery.hpp"

#include "genmod/models/bloomenthal_models.hpp"
#include "genmod/models/starfish.hpp"
#include "genmod/operators/convolution.hpp"
#include "genmod/operators/polygon_convolution.hpp"
#include "genmod/operators/shapes.hpp"

#include <cmath>
#include <stdexcept>

namespace genmod::models {
namespace {

const Fn X = x(0), Y = x(1), Z = x(2);

double positive(const ParameterValues& p, const char* name) {
  const double v = p.at(name);
  if (!(v > 0)) throw std::invalid_argument(std::string("parameter '") + name + "' must be > 0, got " + std::to_string(v));
  return v;
}

Box3 cube(double h) { return {Interval(-h, h), Interval(-h, h), Interval(-h, h)}; }

// libfive's benchmark: s = max(|p| - radius, gyroid(frequency)), thickened to
// min(s, 2 sqrt|s| - shell) (the solid s < shell^2 / 4), as data/sphere_gyroid.vm writes it.
Fn sphere_gyroid(const ParameterValues& p) {
  const double k = positive(p, "frequency"), shell = positive(p, "shell");
  const Fn g = sin(k * X) * cos(k * Y) + sin(k * Y) * cos(k * Z) + sin(k * Z) * cos(k * X);
  const Fn s = max(sqrt(square(X) + square(Y) + square(Z)) - positive(p, "radius"), g);
  return min(s, 2.0 * sqrt(abs(s)) - shell);
}

Fn tanglecube(const ParameterValues& p) {
  const double a = p.at("a"), c = p.at("c");
  auto term = [&](const Fn& t) { return square(square(t)) - a * square(t); };
  return term(X) + term(Y) + term(Z) + c;
}

Fn drilled_block(const ParameterValues& p) {
  const double h = positive(p, "half_side"), r = positive(p, "hole_radius");
  if (r >= h) throw std::invalid_argument("parameter 'hole_radius' must be below 'half_side'");
  return csg_difference(implicit_box(cat({h, h, h})), implicit_cylinder(r, 2 * h));
}

// f = threshold - sum exp(-sharpness |p - q_i|), negative near the four centers.
Fn blobby(const ParameterValues& p) {
  const double d = positive(p, "spacing"), b = positive(p, "sharpness"), t = positive(p, "threshold");
  const double centers[4][3] = {{-d, -d, 0}, {d, -d, 0.2 * d}, {-d, d, -0.2 * d}, {d, d, 0}};
  Fn sum = 0.0;
  for (const auto& q : centers) sum = sum + exp(-b * sqrt(square(X - q[0]) + square(Y - q[1]) + square(Z - q[2])));
  return t - sum;
}

Fn gyroid_sheet(const ParameterValues& p) {
  return implicit_gyroid(positive(p, "frequency"), positive(p, "thickness"));
}

// Bloomenthal's starfish joint (starfish.hpp): variant 0 = combination surface, 1 =
// convolution (bulges at the joint), 2 = union of capsules (creases in the webbing).
Fn starfish(const ParameterValues& p) {
  const double v = p.at("variant");
  if (!(v == 0 || v == 1 || v == 2))
    throw std::invalid_argument("parameter 'variant' must be 0 (combination), 1 (convolution) or 2 (union), got " + std::to_string(v));
  return starfish_implicit(static_cast<StarfishVariant>(static_cast<int>(v)));
}

// Bloomenthal's tee (Figs 5.62-5.67): Gaussian convolution of a crossbar (0,-1,0)-(0,1,0) and
// a stem along +x to (1.5,0,0), both of radius r; the stem starts at the origin (bulge at the
// junction: D(0,0,r) = 3/4) or, with shorten = 1, at (r,0,0) (D(r,0,r) = 1/2: "a small bulge
// and a small dip").
Fn tee(const ParameterValues& p) {
  const double r = positive(p, "radius"), shorten = p.at("shorten");
  if (!(shorten == 0 || shorten == 1)) throw std::invalid_argument("parameter 'shorten' must be 0 or 1, got " + std::to_string(shorten));
  if (!(r < 0.5)) throw std::invalid_argument("parameter 'radius' must be < 0.5, got " + std::to_string(r));
  const Fn d = segment_convolution({0, -1, 0}, {0, 1, 0}, r) + segment_convolution({shorten * r, 0, 0}, {1.5, 0, 0}, r);
  return density_to_implicit(d);
}

// Bloomenthal's rotated pair (Fig. 5.46, bloomenthal_models.hpp): two segments sharing an end.
Fn rotated_pair(const ParameterValues& p) {
  return density_to_implicit(rotated_pair_density(p.at("bend"), positive(p, "radius")));
}

// The trifurcated ramiform (Fig. 5.59): max(parent, sum of three children), iso 1.
Fn ramiform(const ParameterValues& p) {
  const double r = positive(p, "radius");
  if (r > 0.2) throw std::invalid_argument("parameter 'radius' must be <= 0.2, got " + std::to_string(r));
  return density_to_implicit(trifurcated_density(r, p.at("spread")), 1.0);
}

// Segments against points (Fig. 5.57): a half circle by `count` segments or point sources.
Fn arc_convolution(const ParameterValues& p) {
  const double n = p.at("count"), points = p.at("points"), r = positive(p, "radius");
  if (!(n >= 1 && n <= 100 && n == std::floor(n))) throw std::invalid_argument("parameter 'count' must be an integer in [1, 100]");
  if (!(points == 0 || points == 1)) throw std::invalid_argument("parameter 'points' must be 0 or 1");
  if (r > 0.4) throw std::invalid_argument("parameter 'radius' must be <= 0.4");
  const int count = static_cast<int>(n);
  return density_to_implicit(points == 1 ? arc_points_density(count, r) : arc_segments_density(count, r));
}

Fn arm(const ParameterValues& p) { return density_to_implicit(culled_convolution(arm_segments(p.at("elbow"), p.at("bulge")))); }

Fn hand(const ParameterValues& p) {
  return density_to_implicit(culled_convolution(hand_segments(p.at("grip"), p.at("palm_radius"))));
}

// Bloomenthal's polygonal skeletal elements (§6.1-6.3, polygon_convolution.hpp) in the plane
// z = 0: a unit square (a slab with rounded rim), an L, or a plus of five abutting unit/3
// squares (coplanar contiguous polygons: no seam, no bulge at the junction).
Fn polygon_slab(const ParameterValues& p) {
  const double shape = p.at("shape"), r = positive(p, "radius"), res = p.at("resolution");
  if (!(shape == 0 || shape == 1 || shape == 2)) throw std::invalid_argument("parameter 'shape' must be 0 (square), 1 (L) or 2 (plus)");
  if (r > 0.2) throw std::invalid_argument("parameter 'radius' must be <= 0.2, got " + std::to_string(r));
  if (!(res >= 2 && res <= 1000 && res == std::floor(res))) throw std::invalid_argument("parameter 'resolution' must be an integer in [2, 1000]");
  auto rect = [](double x0, double y0, double x1, double y1) {
    return SkeletalPolygon{{{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}}, {}};
  };
  std::vector<SkeletalPolygon> polys;
  if (shape == 0) polys = {rect(-0.5, -0.5, 0.5, 0.5)};
  if (shape == 1) polys = {{{{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, -0.1, 0}, {-0.1, -0.1, 0}, {-0.1, 0.5, 0}, {-0.5, 0.5, 0}}, {}}};
  if (shape == 2) {
    const double a = 0.5 / 3;
    polys = {rect(-a, -a, a, a), rect(a, -a, 3 * a, a), rect(-3 * a, -a, -a, a), rect(-a, a, a, 3 * a), rect(-a, -3 * a, a, -a)};
  }
  return polygon_convolution_surface(polys, r, {.resolution = static_cast<int>(res)});
}

}  // namespace

const std::vector<ImplicitModel>& implicit_gallery() {
  static const std::vector<ImplicitModel> models = {
      {"sphere_gyroid",
       "libfive's meshing benchmark: a gyroid inside a sphere, thickened (data/sphere_gyroid.vm)",
       {{"radius", 3.0, "sphere radius"},
        {"frequency", 2.0, "gyroid frequency k in sin(k x) cos(k y) + ..."},
        {"shell", 0.5, "thickening: the solid is s < shell^2 / 4"}},
       sphere_gyroid, cube(5.0), 0.05},
      {"tanglecube", "the tanglecube quartic x^4 - a x^2 + y^4 - a y^2 + z^4 - a z^2 + c < 0 (genus 5)",
       {{"a", 5.0, "quadratic coefficient"}, {"c", 10.0, "constant"}}, tanglecube, cube(2.5), 0.05},
      {"drilled_block", "a cube with a round hole through it: sharp edges and a genus-1 solid",
       {{"half_side", 1.0, "half the cube's side"}, {"hole_radius", 0.5, "radius of the hole along z"}},
       drilled_block, cube(1.5), 0.02},
      {"blobby", "four blended spheres, the blobby surface of the thesis's Fig 5.29",
       {{"spacing", 1.0, "centers at (+-spacing, +-spacing)"},
        {"sharpness", 4.0, "decay of each term exp(-sharpness r)"},
        {"threshold", 0.5, "the surface is sum = threshold"}},
       blobby, cube(2.0), 0.02},
      {"gyroid_sheet", "a gyroid sheet |g| < thickness clipped by the box",
       {{"frequency", 3.0, "gyroid frequency"}, {"thickness", 0.3, "half thickness in g"}}, gyroid_sheet,
       cube(1.0), 0.02},
      {"starfish",
       "Bloomenthal's starfish joint (Figs 5.71-5.73): five limbs of radius 0.1, combination of convolution and union",
       {{"variant", 0.0, "0 = combination surface (JointValue), 1 = convolution, 2 = union of capsules"}},
       starfish, {Interval(-0.65, 0.85), Interval(-0.55, 0.75), Interval(-0.3, 0.3)}, 0.025},
      {"tee", "Bloomenthal's convolution tee (Figs 5.62-5.67): crossbar and stem of radius r; bulge, or shortened stem",
       {{"radius", 0.2, "radius of both segments (< 0.5)"},
        {"shorten", 0.0, "1: the stem starts at (r, 0, 0) instead of the junction (removes most of the bulge)"}},
       tee, {Interval(-0.7, 1.9), Interval(-1.4, 1.4), Interval(-0.7, 0.7)}, 0.05},
      {"rotated_pair",
       "Bloomenthal's rotated pair (Fig. 5.46): two convolved segments of length 1 sharing an end, bent by an angle; no bulge, no crease",
       {{"bend", 60.0, "angle between the second segment and the first's direction, degrees in [0, 90]"},
        {"radius", 0.15, "radius of both segments"}},
       rotated_pair, {Interval(-1.5, 1.5), Interval(-0.6, 1.5), Interval(-0.6, 0.6)}, 0.025},
      {"ramiform",
       "Bloomenthal's trifurcated ramiform (Fig. 5.59, eq. 5.36): max(parent, sum of three children), parent radius sqrt(3) r",
       {{"radius", 0.08, "child radius r (<= 0.2); the parent's is sqrt(3) r"},
        {"spread", 40.0, "angle of each child from the parent's direction, degrees in (0, 90)"}},
       ramiform, {Interval(-0.9, 0.9), Interval(-1.3, 1.1), Interval(-0.9, 0.9)}, 0.02},
      {"arc_convolution",
       "Bloomenthal's segments against points (Fig. 5.57): a half circle by count Gaussian segments or weighted point sources",
       {{"count", 7.0, "number of chords (segments) or of point sources at their midpoints, integer in [1, 100]"},
        {"points", 0.0, "1: point sources of weight chord / (r sqrt(pi / ln 2)) instead of segments"},
        {"radius", 0.15, "radius r (<= 0.4)"}},
       arc_convolution, {Interval(-1.6, 1.6), Interval(-0.65, 1.65), Interval(-0.6, 0.6)}, 0.02},
      {"convolution_arm",
       "Bloomenthal's arm (Sec. 6.4), reconstructed: five tendon-bulge-tendon muscles and three bones as tapered convolution segments, culled sum",
       {{"elbow", 30.0, "elbow bend, degrees in [0, 120]"},
        {"bulge", 1.0, "muscle bulge radius as a fraction of its base, (0, 1.5]"}},
       arm, {Interval(-0.8, 6.4), Interval(-0.8, 2.6), Interval(-0.9, 0.9)}, 0.04},
      {"hand",
       "Bloomenthal's hand (Sec. 6.5, Fig. 6.14): the finger table of the thesis and a reconstructed palm, tendons, veins and thumb muscle; culled sum of 45 convolution segments",
       {{"grip", 1.0, "scale of every finger's grip angles (0 = straight, 1 = the thesis's table), [0, 2]"},
        {"palm_radius", 0.2, "radius of the metacarpal segments, inches, (0, 0.3]"}},
       hand, {Interval(-3.0, 1.2), Interval(-0.9, 3.8), Interval(-0.9, 0.7)}, 0.02},
      {"polygon_slab",
       "Bloomenthal's polygonal skeletal elements (Ch. 6): B-spline convolution images of planar polygons times the distance filter",
       {{"shape", 0.0, "0 = unit square (a slab), 1 = L, 2 = plus of five abutting squares (seamless junction)"},
        {"radius", 0.1, "radius r (<= 0.2): the slab's half thickness"},
        {"resolution", 80.0, "image pixels across the longer side, integer in [2, 1000]"}},
       polygon_slab, {Interval(-0.8, 0.8), Interval(-0.8, 0.8), Interval(-0.3, 0.3)}, 0.025},
  };
  return models;
}

const ImplicitModel* find_implicit_model(const std::string& name) {
  for (const ImplicitModel& m : implicit_gallery())
    if (m.name == name) return &m;
  return nullptr;
}

Fn build_implicit_model(const ImplicitModel& model, const ParameterValues& overrides) {
  return model.build(resolve_parameters(model.name, model.parameters, overrides));
}

}  // namespace genmod::models
