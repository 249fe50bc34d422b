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
#include "furniture_tools.hpp"
#include "procedural_model_defs.hpp"

#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"

namespace genmod::models::detail {
namespace {

PolyMesh build_table(bool round, double length, double width, double leg_length, double thick, int n, int levels,
                     double smoothing) {
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
  w.extrude_chain(w.name("legs", legs), Vec3(0, -leg_length / n, 0), n);
  if (round) sqrt2_subdivide(w.mesh, w.faces("top"), levels, smoothing);
  return std::move(w.mesh);
}

}  // namespace

ProceduralModelDef table_definition() {
  ProcedureSpec spec;
  spec.name = "table";
  spec.mode = Mode::Out;
  spec.params = {param("roundTable", false), param("length", 3.0),   param("width", 2.0),
                 param("legLength", 1.5),    param("thickness", 0.2), param("segments", 8),
                 param("smoothingFactor", 1.0), param("subdivisions", 3)};
  spec.out_body = [](const Arguments& a, const CallContext&) {
    const bool round = a.boolean("roundTable");
    const double length = positive_real(a, "table", "length");
    const double width = positive_real(a, "table", "width");
    const double leg_length = positive_real(a, "table", "legLength");
    const double thick = positive_real(a, "table", "thickness");
    const int n = integer_in(a, "table", "segments", round ? 3 : 1, 64);
    const double smoothing = real_in(a, "table", "smoothingFactor", 0.0, 1.0);
    const int levels = integer_in(a, "table", "subdivisions", 0, 6);
    return build_table(round, length, width, leg_length, thick, n, levels, smoothing);
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
       {"subdivisions", "round top: sqrt(2) levels, 0-6"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
