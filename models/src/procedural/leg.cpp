// leg: the cacheable Out procedure the luggage stands on. The thesis's luggage reuses the
// human model's Leg and Foot procedures (App. C.3, C.5); genmod has no human model, so this is
// a documented simple stand-in with the same role: a column grown down from a box in
// `segments` extrusions, a foot extruded forward (+z) from the front of the lowest segment in
// two steps, and every face but the top subdivided with adaptive sqrt(2) and smoothed. The top
// stays one flat quad [-width/2, width/2] x {0} x [-depth/2, depth/2] (its vertices are kept
// by the adaptive subdivision), so a caller can bridge it to the body it carries; the sole is
// at y = -height.
//
// It is cacheable: equal arguments and seed return copies of one built mesh. It uses neither
// the seed, the level of detail nor the transform (the caller places the copy).
#include "furniture_tools.hpp"
#include "procedural_model_defs.hpp"

#include "genmod/procedural/sqrt2_subdivision.hpp"

namespace genmod::models::detail {

ProceduralModelDef leg_definition() {
  ProcedureSpec spec;
  spec.name = "leg";
  spec.mode = Mode::Out;
  spec.cacheable = true;
  spec.params = {param("height", 1.0),     param("width", 0.25),     param("depth", 0.25),
                 param("segments", 4),     param("footLength", 0.2), param("subdivisions", 2),
                 param("smoothing", 0.5)};
  spec.out_body = [](const Arguments& a, const CallContext&) {
    const double h = positive_real(a, "leg", "height"), wd = positive_real(a, "leg", "width"),
                 dp = positive_real(a, "leg", "depth"), foot = positive_real(a, "leg", "footLength");
    const int n = integer_in(a, "leg", "segments", 1, 64);
    const int levels = integer_in(a, "leg", "subdivisions", 0, 6);
    const double smoothing = real_in(a, "leg", "smoothing", 0.0, 1.0);
    const double unit = h / n;
    Workpiece w;
    w.mesh = make_box(Vec3(-wd / 2, -unit, -dp / 2), Vec3(wd / 2, 0, dp / 2));
    w.name("leg", all_faces(w.mesh));
    w.name("legtop", w.select("leg", ratio_box(kAll, kHigh, kAll)));
    w.extrude_chain(w.select("leg", ratio_box(kAll, kLow, kAll)), Vec3(0, -unit, 0), n - 1);
    w.extrude_chain(w.select("leg", ratio_box(kAll, cell_range(0, 0, n), kHigh)), Vec3(0, 0, foot / 2), 2);
    sqrt2_subdivide(w.mesh, w.faces("leg"), levels, smoothing);
    return std::move(w.mesh);
  };
  ProceduralModel info{
      "leg",
      "a cacheable leg with a foot (the luggage's legs; stands in for the thesis's human Leg/Foot): flat top at y = 0",
      {{"height", "from the top (y = 0) to the sole"},
       {"width", "top width along x"},
       {"depth", "top depth along z"},
       {"segments", "extrusions of the column"},
       {"footLength", "how far the foot reaches forward (+z)"},
       {"subdivisions", "sqrt(2) levels on everything but the top, 0-6"},
       {"smoothing", "sqrt(2) smoothing factor, 0..1"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
