// leg: the human leg with its foot (thesis App. C.1-C.3: #Leg builds a leg from the thigh in
// head-length pieces, thigh, knee, shin and ankle, and calls Foot) as a cacheable Out
// procedure. It is what the human stands on, and, as in the thesis ("the Luggage reuses the
// human leg and foot procedures"), what the luggage and the chair's feet stand on.
//
// Construction (y up, front +z): a column grown down from a box in `segments` extrusions
// (default 4, the thesis's pieces), its four sides shaped onto profile curves (thigh, knee,
// calf, ankle; the calf bulges at the back, the knee at the front), everything but the flat top
// and the ankle subdivided with adaptive sqrt(2) and smoothed; then a `foot` call (cacheable
// too), placed a small gap below the ankle with its toe tips footLength in front of the leg's
// front (z = depth / 2 + footLength) and its sole at y = -height, and bridged to the ankle (the
// triangles labelled "ankle"). The top stays one flat quad [-width/2, width/2] x {0} x
// [-depth/2, depth/2] labelled "legtop", which a caller bridges to the body it carries.
//
// Numbers the thesis leaves out (its Leg listing is missing): the profiles (half-widths as
// fractions of the top's along the column: 1 at the hip, 0.6 at the knee, 0.4 at the ankle),
// the foot's size (width 0.8 of the leg's, its heel cell 0.4 depth long under the ankle,
// toes 0.3 of its length), the ankle gap (0.2 footHeight). It uses neither the seed nor the transform.
#include "body_tools.hpp"
#include "procedural_model_defs.hpp"

#include "genmod/procedural/sqrt2_subdivision.hpp"

#include <algorithm>

namespace genmod::models::detail {
namespace {

PolyMesh build_leg(const Arguments& a, const CallContext& context) {
  const char* P = "leg";
  const double h = positive_real(a, P, "height"), wd = positive_real(a, P, "width"), dp = positive_real(a, P, "depth"),
               foot_length = positive_real(a, P, "footLength"), foot_height = positive_real(a, P, "footHeight");
  const int n = integer_in(a, P, "segments", 1, 64);
  const int levels = integer_in(a, P, "subdivisions", 0, 6);
  const double smoothing = real_in(a, P, "smoothing", 0.0, 1.0);
  const int toes = integer_in(a, P, "numToes", 1, 10);
  const std::string& side = a.string("side");
  if (side != "left" && side != "right") refuse_parameter(P, "side", "must be \"left\" or \"right\", got \"" + side + "\"");
  const double gap = 0.2 * foot_height;
  if (!(foot_height + gap < h)) refuse_parameter(P, "footHeight", "must leave room for the leg (1.2 footHeight < height)");
  const double column = h - foot_height - gap, unit = column / n;

  Workpiece w;
  w.mesh = make_box(Vec3(-wd / 2, -unit, -dp / 2), Vec3(wd / 2, 0, dp / 2));
  w.name("leg", all_faces(w.mesh));
  w.name("legtop", w.select("leg", ratio_box(kAll, kHigh, kAll)));
  w.extrude_chain(w.select("leg", ratio_box(kAll, kLow, kAll)), Vec3(0, -unit, 0), n - 1);
  w.name("legbottom", w.select("leg", ratio_box(kAll, kLow, kAll)));
  // Profiles from the hip (t = 0, y = 0) to the ankle (t = 1, y = -column).
  const std::vector<double> sides{1.0, 0.95, 0.8, 0.62, 0.58, 0.64, 0.55, 0.42, 0.4};
  const std::vector<double> front{1.0, 0.95, 0.82, 0.7, 0.68, 0.58, 0.5, 0.42, 0.4};
  const std::vector<double> back{1.0, 1.0, 0.85, 0.62, 0.8, 0.78, 0.55, 0.42, 0.4};
  const FaceList px = w.select("leg", ratio_box(kHigh, kAll, kAll)), nx = w.select("leg", ratio_box(kLow, kAll, kAll));
  const FaceList pz = w.select("leg", ratio_box(kAll, kAll, kHigh)), nz = w.select("leg", ratio_box(kAll, kAll, kLow));
  shape_profile(w.mesh, px, 1, 0.0, -column, 0, 0.0, 1.0, wd / 2, sides);
  shape_profile(w.mesh, nx, 1, 0.0, -column, 0, 0.0, -1.0, wd / 2, sides);
  shape_profile(w.mesh, pz, 1, 0.0, -column, 2, 0.0, 1.0, dp / 2, front);
  shape_profile(w.mesh, nz, 1, 0.0, -column, 2, 0.0, -1.0, dp / 2, back);
  sqrt2_subdivide(w.mesh, w.faces("leg"), levels, smoothing);
  w.sets.update(w.mesh);

  // The foot: its heel cell (as deep as the ankle, 0.4 depth) under the ankle, toe tips at
  // z = depth / 2 + footLength.
  const double heel = 0.4 * dp, length = 0.5 * dp + foot_length + 0.5 * heel;
  // Shared: a hit is not copied (the foot is only read, then appended).
  const std::shared_ptr<const PolyMesh> foot_part = context.call_shared("foot", {{"length", length},
                                              {"width", 0.8 * wd},
                                              {"height", foot_height},
                                              {"numToes", toes},
                                              {"heel", heel},
                                              {"side", side},
                                              {"subdivisions", std::min(levels, 3)},
                                              {"smoothing", smoothing}});
  const PolyMesh& foot = *foot_part;
  // Centre the foot's top under the ankle across x.
  const auto [tlo, thi] = bounds(foot, faces_labelled(foot, "foottop"));
  const Affine place = Affine::translation(Vec3(-0.5 * (tlo[0] + thi[0]), -(h - foot_height), dp / 2 + foot_length - length));
  attach_part(w, foot, "foottop", w.faces("legbottom"), place, "ankle");
  w.mesh.garbage_collection();
  return std::move(w.mesh);
}

}  // namespace

ProceduralModelDef leg_definition() {
  ProcedureSpec spec;
  spec.name = "leg";
  spec.mode = Mode::Out;
  spec.cacheable = true;
  spec.params = {param("height", 1.0),     param("width", 0.25),      param("depth", 0.25),
                 param("segments", 4),     param("footLength", 0.2),  param("subdivisions", 2),
                 param("smoothing", 0.5),  param("footHeight", 0.08), param("numToes", 5),
                 param("side", "left")};
  spec.out_body = build_leg;
  ProceduralModel info{
      "leg",
      "the human leg with its foot (thesis #Leg + Foot), cacheable; the human's, the luggage's and the chair's legs: "
      "flat top 'legtop' at y = 0",
      {{"height", "from the top (y = 0) to the sole"},
       {"width", "top width along x"},
       {"depth", "top depth along z"},
       {"segments", "extrusions of the column (the thesis's thigh, knee, shin, ankle: 4)"},
       {"footLength", "how far the toes reach in front of the leg (+z)"},
       {"subdivisions", "sqrt(2) levels on everything but the top, 0-6 (the foot gets at most 3)"},
       {"smoothing", "sqrt(2) smoothing factor, 0..1"},
       {"footHeight", "the foot's height (sole to instep)"},
       {"numToes", "toes of the foot, 1-10"},
       {"side", "\"left\" or \"right\" (the foot's big toe on the inside)"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
