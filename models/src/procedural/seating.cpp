// The chair / couch construction of Algorithms 5 and 6 (research/morkel.md section 3.2, App.
// C.4), step by step with the procedural tools. Where the thesis's ratio boxes would pick a
// different number of cells at other `segments`, the boxes here are computed from cell indices
// (cell_range), so every segments value gives the same parts; the cell choices are written at
// each step.
#include "seating.hpp"

#include "furniture_tools.hpp"
#include "genmod/procedural/bezier_curve.hpp"
#include "genmod/procedural/curve_shaping.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"
#include "genmod/procedural/stitching.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace genmod::models::detail {
namespace {

// The disc base (the chair's cubic = false, Experiment 3's "chair from a disc"): the finished
// seating is drawn onto a round seat by a radial map in x and z about the seat's middle, in
// coordinates where the seat rectangle is [-1, 1]^2: p -> p max(|u|, |v|) / |p|. It takes the
// rectangle's outline to the inscribed ellipse and every ray from the middle to itself, scaled
// by a factor in [1/sqrt 2, 1] that depends only on the ray's direction, so it is one-to-one
// everywhere and moves no point away from the middle (the bounds still hold). y is untouched,
// so walls stay vertical and horizontal faces horizontal: every face stays planar, and the
// construction's cells, parts and counts are those of the square chair.
// The thesis makes its Disc by smoothing subdivision of a box instead; a subdivided grid would
// no longer have the cells the selections here are made of.
void round_the_base(PolyMesh& mesh, double length, double depth) {
  const double cx = 0.5 * length, cz = 0.5 * depth;
  for (auto v : mesh.vertices()) {
    Vec3 p = mesh.point(v);
    const double u = (p[0] - cx) / cx, w = (p[2] - cz) / cz, r = std::hypot(u, w);
    if (r == 0) continue;  // the middle stays
    const double scale = std::max(std::abs(u), std::abs(w)) / r;
    p[0] = cx + cx * u * scale;
    p[2] = cz + cz * w * scale;
    mesh.set_point(v, p);
  }
}

// The cushions' (and the feet's legs') sqrt(2) rounds at most: each round doubles a cushion's
// faces, so lod +4 has 16 times the cushion faces of lod 0.
constexpr int kMaxSmoothLevels = 6;
}  // namespace

std::array<Vec3, 2> seating_bounds(const SeatingShape& s) {
  const int n = s.segments;
  const double lu = s.length / n, du = s.depth / n, hu = s.back_length / n, thick = std::min(lu, du);
  // Down to the legs' (or feet's soles') y = -leg_length; up to the back's top raised by the
  // arch's control point (the apex rises half of it) or the cushions (0.75 du on the seat),
  // whichever is higher; along z from the back (0) to the seat's front, where a front foot's
  // toes reach half a depth unit further (0.3 du from its cell's middle to the leg's front,
  // 0.7 du of foot).
  const double top = thick + std::max(s.back_length + std::max(s.offset, 0.0) * hu, 0.75 * du);
  return padded_box(Vec3(0, -s.leg_length, 0), Vec3(s.cushions * s.length, top, s.depth + (s.feet ? 0.5 * du : 0.0)));
}

SeatingShape shared_seating_shape(const Arguments& a, std::string_view procedure) {
  SeatingShape s;
  s.length = positive_real(a, procedure, "length");
  s.depth = positive_real(a, procedure, "depth");
  s.leg_length = positive_real(a, procedure, "legLength");
  s.back_length = positive_real(a, procedure, "backLength");
  s.segments = integer_in(a, procedure, "segments", 1, 64);
  s.arms = a.boolean("arms");
  s.bottom_arms = a.boolean("bottomArms");
  s.shape = a.boolean("shape");
  // Down to -1: the top row (one height unit) keeps half its height at the dip.
  s.offset = real_in(a, procedure, "offSet", -1.0, 16.0);
  return s;
}

PolyMesh build_seating(const SeatingShape& s, const CallContext& context) {
  const int n = s.segments;
  const int nx = n * s.cushions;  // seat cells along x
  const double lu = s.length / n, du = s.depth / n, hu = s.back_length / n;
  // The thesis starts from a cube of the unit; with length != depth the units differ, and the
  // seat is as thick as the smaller one.
  const double thick = std::min(lu, du);
  // Level of detail (furniture_tools.hpp): the cushions' and the feet's legs' sqrt(2) rounds
  // (2 at lod 0) and the legs' extrusion steps follow the context's lod; everything else (the
  // cells that decide which parts exist) does not, so every lod has the same parts. A cushion
  // keeps at least one round: unrounded, its box would touch an arm post along an edge (the
  // post stands on the cell diagonal to the cushion's front corner), which is no longer a
  // 2-manifold surface; one round pulls its corners in.
  const int leg_levels = lod_levels(2, context.lod(), kMaxSmoothLevels);
  const int cushion_levels = std::max(1, leg_levels);
  const int leg_steps = lod_steps(n, context.lod());

  Workpiece w;
  // 1. The seat: one box, its +x face extruded nx - 1 times by a length unit, then the whole
  //    +z side nx cells wide extruded n - 1 times by a depth unit: nx x n cells, one thick.
  w.mesh = make_box(Vec3(0, 0, 0), Vec3(lu, thick, du));
  w.name("seat", all_faces(w.mesh));
  w.extrude_chain(w.select("seat", ratio_box(kHigh, kAll, kAll)), Vec3(lu, 0, 0), nx - 1);
  w.extrude_chain(w.select("seat", ratio_box(kAll, kAll, kHigh)), Vec3(0, 0, du), n - 1);

  // 2. The back: the top faces of the rear row (z cell 0), extruded n times by a height unit.
  //    Naming them first lets the extruded walls inherit the name (the thesis names the back
  //    afterwards with a second selection).
  w.extrude_chain(w.name("back", w.select("seat", ratio_box(kAll, kHigh, cell_range(0, 0, n)))), Vec3(0, hu, 0), n);

  // 3. Cushions (thesis ranges x 0.1-0.9, z 0.2-0.9): per cushion the x cells between its
  //    first and last (one cell of seat left free on either side) and the z cells 2..n-2 (two
  //    free rows before the back, so the cushion does not lean on it, one at the front).
  //    Extruded once by 0.75 depth units, then two adaptive sqrt(2) levels with smoothing 1.
  //    Too few cells (segments < 4) give no cushion: the thesis's partial chairs at low detail.
  for (int k = 0; k < s.cushions; ++k) {
    const int x0 = k * n + 1, x1 = (k + 1) * n - 2, z0 = 2, z1 = n - 2;
    if (x1 < x0 || z1 < z0) break;
    const std::string id = "cushion" + std::to_string(k + 1);
    w.extrude_chain(w.name(id, w.select("seat", ratio_box(cell_range(x0, x1, nx), kHigh, cell_range(z0, z1, n)))),
                    Vec3(0, 0.75 * du, 0), 1);
    sqrt2_subdivide(w.mesh, w.faces(id), cushion_levels, 1.0);
    w.sets.update(w.mesh);
  }

  // 3b. Back cushions (couch): per cushion the same x cells of the back's front, rows 1..n-2,
  //    extruded forward by half a depth unit and subdivided like the seat cushions. With arms
  //    the outermost cushions keep one more cell free beside the arm rests (whose walls would
  //    otherwise lie in the plane of the cushion's walls, overlapping them).
  const bool arm_rests = s.arms && n >= 3;
  if (s.back_cushions)
    for (int k = 0; k < s.cushions; ++k) {
      const int x0 = k * n + 1 + (arm_rests && k == 0), x1 = (k + 1) * n - 2 - (arm_rests && k == s.cushions - 1);
      const int y0 = 1, y1 = n - 2;
      if (x1 < x0 || y1 < y0) break;
      const std::string id = "backcushion" + std::to_string(k + 1);
      w.extrude_chain(w.name(id, w.select("back", ratio_box(cell_range(x0, x1, nx), cell_range(y0, y1, n), kHigh))),
                      Vec3(0, 0, 0.5 * du), 1);
      sqrt2_subdivide(w.mesh, w.faces(id), cushion_levels, 1.0);
      w.sets.update(w.mesh);
    }

  // 4. Legs: the bottom faces of the four corner cells (thesis: the corner quarters of the
  //    base, one cell at 6 segments), extruded together n times by a leg unit downwards. With
  //    one or two cells per axis the corners meet and the legs merge into one block. With feet
  //    (and at least 3 cells per axis, so the corners are apart) the corners are named here and
  //    get `leg` calls at the end (step 7).
  const bool feet = s.feet && n >= 3;
  {
    const auto xl = cell_range(0, 0, nx), xr = cell_range(nx - 1, nx - 1, nx);
    const auto zb = cell_range(0, 0, n), zf = cell_range(n - 1, n - 1, n);
    const RatioBox corners[4] = {ratio_box(xl, kLow, zb), ratio_box(xr, kLow, zb), ratio_box(xr, kLow, zf),
                                 ratio_box(xl, kLow, zf)};
    if (feet) {
      for (int i = 0; i < 4; ++i) w.name("foot" + std::to_string(i + 1), w.select("seat", corners[i]));
    } else {
      const FaceList legs = merged({w.select("seat", corners[0]), w.select("seat", corners[1]),
                                    w.select("seat", corners[2]), w.select("seat", corners[3])});
      w.extrude_chain(w.name("legs", legs), Vec3(0, -s.leg_length / leg_steps, 0), leg_steps);
    }
  }

  // 5. Arms (segments >= 3): an arm rest from the back's front in the outer x cells at back row
  //    j = segments / 2, extruded n - 1 times by a depth unit to the front edge; with
  //    bottom_arms a post from the seat's outer front cells, extruded j - 1 times by a height
  //    unit, so one height unit of air stays between post and rest (the thesis's rows leave
  //    the two touching, which a bridge cannot join); the rest's underside at the front and
  //    the post's top are bridged below, after the back is shaped.
  struct ArmJoin {
    std::string rest, post;
  };
  std::vector<ArmJoin> joins;
  if (arm_rests) {
    const int j = n / 2;
    const auto yj = cell_range(j, j, n);
    const std::pair<double, double> sides[2] = {cell_range(0, 0, nx), cell_range(nx - 1, nx - 1, nx)};
    const char* side_names[2] = {"r", "l"};
    FaceList rests;
    for (int i = 0; i < 2; ++i)
      rests = merged({rests, w.name(std::string("armrest_") + side_names[i], w.select("back", ratio_box(sides[i], yj, kHigh)))});
    w.extrude_chain(rests, Vec3(0, 0, du), n - 1);
    if (s.bottom_arms) {
      FaceList posts;
      for (int i = 0; i < 2; ++i)
        posts = merged({posts, w.name(std::string("armpost_") + side_names[i],
                                      w.select("seat", ratio_box(sides[i], kHigh, cell_range(n - 1, n - 1, n))))});
      w.extrude_chain(posts, Vec3(0, hu, 0), j - 1);
      for (const char* side : side_names)
        joins.push_back({std::string("armrest_") + side, std::string("armpost_") + side});
    }
  }

  // 6. Shape (Algorithm 5's last step): the top of the back onto a quadratic Bezier arch over
  //    its width whose middle control point is `offset` height units above the top (the apex
  //    rises half that), moving vertices along y, seen along z.
  if (s.shape) {
    const FaceList top = w.select("back", ratio_box(kAll, kHigh, kAll));
    const auto [lo, hi] = bounds(w.mesh, top);
    const BezierCurve arch({Vec3(lo[0], hi[1], 0), Vec3(0.5 * (lo[0] + hi[0]), hi[1] + s.offset * hu, 0),
                            Vec3(hi[0], hi[1], 0)});
    shape_to_curve(w.mesh, top, arch, Vec3(0, 1, 0), Vec3(0, 0, 1));
  }

  // 5b. The arm joins: the underside of the rest's front cell bridged to the post's top. All
  //    faces to join are selected first: a bridge deletes faces, which the named sets still
  //    list until the garbage collection at the end.
  std::vector<std::pair<FaceList, FaceList>> bridges;
  for (const ArmJoin& a : joins) {
    const int rest_cells = n - 1;  // the rest's z cells, from the back's front to the seat's front
    bridges.emplace_back(w.select(a.rest, ratio_box(kAll, kLow, cell_range(rest_cells - 1, rest_cells - 1, rest_cells))),
                         w.select(a.post, ratio_box(kAll, kHigh, kAll)));
  }
  std::vector<FaceList> foot_cells;
  if (feet)
    for (int i = 0; i < 4; ++i) foot_cells.push_back(w.faces("foot" + std::to_string(i + 1)));
  for (std::size_t i = 0; i < joins.size(); ++i) bridge(w.mesh, bridges[i].first, bridges[i].second, joins[i].rest);

  // 7. Feet (the listing's `feet`: #Leg per corner): one `leg` call with the same arguments for
  //    each corner, its top a quarter of the smaller unit below the corner cell and bridged to
  //    it, its foot pointing forward. The leg's top is 0.6 of the cell, the foot 0.7 of a depth
  //    unit long (numbers the listing takes from its human Leg).
  if (feet) {
    const double gap = 0.25 * std::min(lu, du);
    // The leg's own default of 2 sqrt(2) rounds at lod 0 (passed explicitly: the same resolved
    // arguments, so the same cache entry, as leaving it out).
    const NamedArgs leg_args{{"height", s.leg_length - gap}, {"width", 0.6 * lu}, {"depth", 0.6 * du},
                             {"footLength", 0.7 * du}, {"subdivisions", leg_levels}};
    for (const FaceList& cell : foot_cells) attach_leg(w, *context.call_shared("leg", leg_args), cell, gap);
  }
  w.mesh.garbage_collection();
  if (s.disc) round_the_base(w.mesh, s.cushions * s.length, s.depth);
  return std::move(w.mesh);
}

}  // namespace genmod::models::detail
