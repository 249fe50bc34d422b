// table: Algorithm 8 of the thesis (research/morkel.md section 3.2; no listing survives). The
// box top grows from one box like the chair's seat (+x, then the -z side, the algorithm's
// "backward axis"); the round top is a flat box with segments x segments cells per side
// subdivided with the smoothing factor (the thesis's oval disc; smoothingFactor 0 keeps the
// box's shape, "an artistic coffee table"). Four legs are extruded from bottom cells.
//
// The round top is subdivided after the legs are extruded, and only the top's faces: the
// legs are chosen on the regular grid (after subdivision the bottom is a pattern of rotated
// quads that a ratio box cuts unevenly), and the subdivision keeps the vertices where a leg
// meets the top in place, so the legs stay attached. Its legs sit one cell in from the rim,
// which the smoothing pulls inwards; at 3 or 4 segments they merge into a central pedestal.
// Numbers the thesis leaves out: thickness 0.2, 8 segments, 3 levels of subdivision, legs as
// long as legLength in `segments` extrusions. smoothingFactor is limited to [0, 1], where the
// subdivided top stays inside the box (claim 24), so the legs cannot be overtaken.
//
// Level of detail (camera.hpp, furniture_tools.hpp): the round top gets subdivisions + lod
// sqrt(2) rounds (at most 6, and at least 1 unless subdivisions is 0: without a round the top
// is the flat box, no longer an oval), and below lod 0 the legs (prisms) are extruded in half
// as many steps per level; the box top has nothing curved to refine, so above lod 0 it stays as
// it is.
#include "furniture_tools.hpp"
#include "procedural_model_defs.hpp"

#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"

#include <algorithm>

namespace genmod::models::detail {
namespace {

PolyMesh build_table(bool round, double length, double width, double leg_length, double thick, int n, int levels,
                     double smoothing, int leg_steps) {
  Workpiece w;
  FaceList legs;
  if (round) {
    w.mesh = make_grid_box(Vec3(-length / 2, 0, -width / 2), Vec3(length / 2, thick, width / 2), n);
    w.name("top", all_faces(w.mesh));
    const auto lo = cell_range(1, 1, n), hi = cell_range(n - 2, n - 2, n);
    legs = merged({w.select("top", ratio_box(lo, kLow, lo)), w.select("top", ratio_box(hi, kLow, lo)),
                   w.select("top", ratio_box(hi, kLow, hi)), w.select("top", ratio_box(lo, kLow, hi))});
  } else {
    const double lu = length / n, wu = width / n;
    w.mesh = make_box(Vec3(0, 0, 0), Vec3(lu, thick, wu));
    w.name("top", all_faces(w.mesh));
    w.extrude_chain(w.select("top", ratio_box(kHigh, kAll, kAll)), Vec3(lu, 0, 0), n - 1);
    w.extrude_chain(w.select("top", ratio_box(kAll, kAll, kLow)), Vec3(0, 0, -wu), n - 1);
    const auto lo = cell_range(0, 0, n), hi = cell_range(n - 1, n - 1, n);
    legs = merged({w.select("top", ratio_box(lo, kLow, lo)), w.select("top", ratio_box(hi, kLow, lo)),
                   w.select("top", ratio_box(hi, kLow, hi)), w.select("top", ratio_box(lo, kLow, hi))});
  }
  w.extrude_chain(w.name("legs", legs), Vec3(0, -leg_length / leg_steps, 0), leg_steps);
  if (round) sqrt2_subdivide(w.mesh, w.faces("top"), levels, smoothing);
  return std::move(w.mesh);
}

// The arguments, checked (the body and the bounds both read them).
struct TableShape {
  bool round;
  double length, width, leg_length, thick;
  int n, levels;
  double smoothing;
};

TableShape table_shape(const Arguments& a) {
  TableShape t;
  t.round = a.boolean("roundTable");
  t.length = positive_real(a, "table", "length");
  t.width = positive_real(a, "table", "width");
  t.leg_length = positive_real(a, "table", "legLength");
  t.thick = positive_real(a, "table", "thickness");
  t.n = integer_in(a, "table", "segments", t.round ? 3 : 1, 64);
  t.smoothing = real_in(a, "table", "smoothingFactor", 0.0, 1.0);
  t.levels = integer_in(a, "table", "subdivisions", 0, 6);
  return t;
}

// The top and the legs below it: the box top spans [0, length] along x and [-width, 0] moved
// by one cell along z (it grows from the cell at z in [0, width / n] towards -z); the round
// top is centred, and its smoothing (<= 1) keeps it inside the flat box it starts from.
std::array<Vec3, 2> table_bounds(const Arguments& a) {
  const TableShape t = table_shape(a);
  if (t.round)
    return padded_box(Vec3(-t.length / 2, -t.leg_length, -t.width / 2), Vec3(t.length / 2, t.thick, t.width / 2));
  const double wu = t.width / t.n;
  return padded_box(Vec3(0, -t.leg_length, wu - t.width), Vec3(t.length, t.thick, wu));
}

}  // namespace

ProceduralModelDef table_definition() {
  ProcedureSpec spec;
  spec.name = "table";
  spec.mode = Mode::Out;
  spec.params = {param("roundTable", false), param("length", 3.0),   param("width", 2.0),
                 param("legLength", 1.5),    param("thickness", 0.2), param("segments", 8),
                 param("smoothingFactor", 1.0), param("subdivisions", 3)};
  spec.uses_lod = true;
  spec.bounds = table_bounds;
  spec.out_body = [](const Arguments& a, const CallContext& context) {
    const TableShape t = table_shape(a);
    const int levels = std::max(std::min(t.levels, 1), lod_levels(t.levels, context.lod(), 6));
    return build_table(t.round, t.length, t.width, t.leg_length, t.thick, t.n, levels, t.smoothing,
                       lod_steps(t.n, context.lod()));
  };
  ProceduralModel info{
      "table",
      "Morkel's table (Algorithm 8): a box top grown by extrusions, or an oval top (a subdivided flat box), on four "
      "legs",
      {{"roundTable", "oval top (subdivided flat box) instead of the box top"},
       {"length", "top length along x"},
       {"width", "top width along z"},
       {"legLength", "leg length below the top"},
       {"thickness", "top thickness"},
       {"segments", "cells per axis of the top (round: >= 3, legs one cell in from the rim)"},
       {"smoothingFactor", "round top: sqrt(2) smoothing factor, 0 (box shape) .. 1"},
       {"subdivisions", "round top: sqrt(2) levels, 0-6; the lod adds to it (at most 6, at least 1 unless 0)"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
