// luggage: Algorithm 7 / App. C.5 of the thesis (research/morkel.md section 3.2), the chest
// after Terry Pratchett's Luggage, standing on numLegs calls of the cacheable `leg` procedure.
//
// Construction: a box of one cell, extruded along -z (length) and along -x (width), then its
// top raised in `kBodyCells` extrusions (the thesis raises a rim of walls and a lid from the
// back wall; the middle of its listing is missing). The top is named "lid", extruded once and
// its top shaped onto a quadratic Bezier arch across x whose apex rises lidHeight (the lid
// curves of the listing, built from the lid's bounding box). The bottom ("base") is a grid of
// (2 columns + 1) x (2 rows + 1) layout cells, so every leg gets a cell with a free cell around
// it (the thesis subdivides the base for its legs), each layout cell split in two across x so
// that the lid's arch has twice as many facets; legs fill the grid row by row from the back.
// Each leg is `leg` called with identical arguments and the inherited seed, a copy placed a
// small gap below its cell and bridged to it, so with caching on it costs 1 miss and
// numLegs - 1 hits.
//
// Numbers the thesis does not give: the chest body is 0.4 height high in 6 cells (the listing
// uses 15 from divBy), the lid one body cell thick, legs 0.35 height long, a leg's top 0.6 of
// its layout cell, the gap (the ankle the bridge makes) a quarter of the smaller cell side, the foot
// 0.7 of a cell long (it stays within the free cell in front), three sqrt(2) levels with
// smoothing 0.5 on the leg. legColumns 0 chooses round(sqrt(numLegs * width / length)) columns
// (layout cells about square), at least 2 so that the chest stands on both sides.
//
// Level of detail (camera.hpp): the legs get legSubdivisions + lod sqrt(2) rounds (0-6); the
// chest, all flat faces but the lid's arch, is the same at every lod.
#include "furniture_tools.hpp"
#include "procedural_model_defs.hpp"

#include "genmod/procedural/affine.hpp"
#include "genmod/procedural/bezier_curve.hpp"
#include "genmod/procedural/curve_shaping.hpp"
#include "genmod/procedural/stitching.hpp"

#include <algorithm>
#include <cmath>

namespace genmod::models::detail {
namespace {

constexpr int kBodyCells = 6;

// The chest alone (the `luggage_chest` procedure): its mesh depends only on these arguments, so
// it is cached (one build per chest size and leg grid) and the luggage copies it.
PolyMesh build_chest(const Arguments& a, const CallContext&) {
  const double height = positive_real(a, "luggage_chest", "height");
  const double width = positive_real(a, "luggage_chest", "width");
  const double length = positive_real(a, "luggage_chest", "length");
  const double lid_height = real_in(a, "luggage_chest", "lidHeight", 0.0, 64.0 * height);
  const int columns = integer_in(a, "luggage_chest", "legColumns", 1, 1024);
  const int rows = integer_in(a, "luggage_chest", "legRows", 0, 1024);
  const int lx = 2 * columns + 1, nz = 2 * rows + 1, nx = 2 * lx;  // layout cells across x, cells along z, x
  const double cx = width / nx, cz = length / nz, cy = 0.4 * height / kBodyCells;

  Workpiece w;
  // The chest: one cell, grown along -z and -x, then upwards.
  w.mesh = make_box(Vec3(width - cx, 0, length - cz), Vec3(width, cy, length));
  w.name("luggage", all_faces(w.mesh));
  w.extrude_chain(w.select("luggage", ratio_box(kAll, kAll, kLow)), Vec3(0, 0, -cz), nz - 1);
  w.extrude_chain(w.select("luggage", ratio_box(kLow, kAll, kAll)), Vec3(-cx, 0, 0), nx - 1);
  w.extrude_chain(w.select("luggage", ratio_box(kAll, kHigh, kAll)), Vec3(0, cy, 0), kBodyCells - 1);
  // The lid: the top, one cell thick, its top arched across x.
  w.extrude_chain(w.name("lid", w.select("luggage", ratio_box(kAll, kHigh, kAll))), Vec3(0, cy, 0), 1);
  if (lid_height > 0) {
    const FaceList top = w.select("lid", ratio_box(kAll, kHigh, kAll));
    const auto [lo, hi] = bounds(w.mesh, top);
    const BezierCurve arch({Vec3(lo[0], hi[1], 0), Vec3(0.5 * (lo[0] + hi[0]), hi[1] + 2 * lid_height, 0),
                            Vec3(hi[0], hi[1], 0)});
    shape_to_curve(w.mesh, top, arch, Vec3(0, 1, 0), Vec3(0, 0, 1));
  }
  // The base, where the legs go: its faces are labelled "base".
  w.name("base", w.select("luggage", ratio_box(kAll, kLow, kAll)));
  return std::move(w.mesh);
}

// The chest [0, width] x [0, 0.4 height + one lid cell] x [0, length] with the lid's arch
// (its control point 2 lidHeight up, so the apex is lidHeight up) on legs reaching 0.35 height
// down; every leg and its foot's toes stay under the base (the toes end half a cell before the
// next layout row).
std::array<Vec3, 2> luggage_bounds(const Arguments& a) {
  const double height = positive_real(a, "luggage", "height");
  const double width = positive_real(a, "luggage", "width");
  const double length = positive_real(a, "luggage", "length");
  const double lid_height = real_in(a, "luggage", "lidHeight", 0.0, 64.0 * height);
  return padded_box(Vec3(0, -0.35 * height, 0), Vec3(width, 0.4 * height * (1.0 + 1.0 / kBodyCells) + lid_height, length));
}

PolyMesh build_luggage(const Arguments& a, const CallContext& context) {
  const double height = positive_real(a, "luggage", "height");
  const double width = positive_real(a, "luggage", "width");
  const double length = positive_real(a, "luggage", "length");
  const int num_legs = integer_in(a, "luggage", "numLegs", 0, 1024);
  int columns = integer_in(a, "luggage", "legColumns", 0, 1024);
  const double lid_height = real_in(a, "luggage", "lidHeight", 0.0, 64.0 * height);
  const int leg_levels = lod_levels(integer_in(a, "luggage", "legSubdivisions", 0, 6), context.lod(), 6);
  if (columns == 0)
    columns = num_legs < 2 ? 1 : std::max(2, static_cast<int>(std::lround(std::sqrt(num_legs * width / length))));
  if (num_legs > 0 && columns > num_legs)
    refuse_parameter("luggage", "legColumns", "must be at most numLegs (" + std::to_string(num_legs) + "), got " +
                                                  std::to_string(columns));
  const int rows = num_legs == 0 ? 0 : (num_legs + columns - 1) / columns;
  const int lx = 2 * columns + 1, nz = 2 * rows + 1, nx = 2 * lx;
  const double cx = width / nx, cz = length / nz;

  // The chest draws no random numbers: seed 0 for every luggage, so luggages of any seed share
  // the cached chest (as the tree's branches do).
  CallOptions fixed;
  fixed.seed = 0;
  // Built in place and returned by name (PolyMesh has no move constructor: a std::move of a
  // member would copy the whole mesh).
  PolyMesh mesh = context.call("luggage_chest",
                               {{"height", height}, {"width", width}, {"length", length}, {"lidHeight", lid_height},
                                {"legColumns", columns}, {"legRows", rows}},
                               fixed);
  // The base cells of the legs, chosen before any bridge deletes faces.
  const FaceList base = faces_labelled(mesh, "base");
  std::vector<FaceList> cells;
  for (int i = 0; i < num_legs; ++i) {
    const int r = i / columns, c = i % columns;
    cells.push_back(select_faces(mesh, base, ratio_box(cell_range(4 * c + 2, 4 * c + 3, nx), kAll,
                                                        cell_range(2 * r + 1, 2 * r + 1, nz))));
  }
  // The legs: one procedure call each, identical arguments, the caller's seed.
  const double gap = 0.25 * std::min(2 * cx, cz);
  const NamedArgs leg_args{{"height", 0.35 * height - gap}, {"width", 1.2 * cx},     {"depth", 0.6 * cz},
                           {"footLength", 0.7 * cz},     {"subdivisions", leg_levels}};
  for (int i = 0; i < num_legs; ++i) attach_leg(mesh, *context.call_shared("leg", leg_args), cells[i], gap);
  mesh.garbage_collection();
  return mesh;
}

}  // namespace

ProceduralModelDef luggage_definition() {
  ProcedureSpec spec;
  spec.name = "luggage";
  spec.mode = Mode::Out;
  // Its mesh depends only on its arguments, the seed its legs inherit and the lod (the key; it
  // does not use the transform), so a repeated luggage is one hit, as a repeated tree is
  // (claim 12: "called again: 0 new misses").
  spec.cacheable = true;
  spec.uses_lod = true;
  spec.bounds = luggage_bounds;
  spec.params = {param("height", 2.0),   param("width", 1.0),      param("length", 2.0),
                 param("numLegs", 4),    param("legColumns", 0),   param("lidHeight", 0.4),
                 param("legSubdivisions", 3)};
  spec.out_body = build_luggage;
  ProceduralModel info{
      "luggage",
      "Morkel's Luggage (Algorithm 7): a chest with an arched lid on numLegs cached calls of `leg`",
      {{"height", "the chest body is 0.4 height high, the legs 0.35 height long"},
       {"width", "chest width along x"},
       {"length", "chest length along z"},
       {"numLegs", "legs, 0-1024, in rows of legColumns under the base"},
       {"legColumns", "legs per row across x (0: about square layout cells, at least 2)"},
       {"lidHeight", "how far the lid's arch rises above the chest"},
       {"legSubdivisions", "sqrt(2) levels of each leg (passed to `leg`), 0-6; the lod adds to it (at most 6)"}}};
  return {std::move(spec), std::move(info)};
}

ProceduralModelDef luggage_chest_definition() {
  ProcedureSpec spec;
  spec.name = "luggage_chest";
  spec.mode = Mode::Out;
  spec.cacheable = true;  // no random numbers: the arguments alone decide the mesh
  spec.params = {param("height", 2.0),    param("width", 1.0),   param("length", 2.0),
                 param("lidHeight", 0.4), param("legColumns", 2), param("legRows", 2)};
  spec.out_body = build_chest;
  ProceduralModel info{
      "luggage_chest",
      "the Luggage's chest without legs, cacheable: the body grown by extrusions, the arched lid, the base "
      "(faces labelled 'base') laid out for legColumns x legRows legs",
      {{"height", "the body is 0.4 height high"},
       {"width", "chest width along x"},
       {"length", "chest length along z"},
       {"lidHeight", "how far the lid's arch rises above the chest"},
       {"legColumns", "leg columns the base is laid out for, 1-1024 (4 legColumns + 2 cells across x)"},
       {"legRows", "leg rows the base is laid out for, 0-1024 (2 legRows + 1 cells along z)"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
