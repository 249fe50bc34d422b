// arm: the human arm (thesis #Arm, whose listing is missing: re-authored from Algorithm 1 and
// the HumanFigure constants) as an Out procedure. Held out sideways (the box-modelling
// tutorial's T pose) along +x from a flat root quad "armroot" at x = 0 (the human bridges it to
// the shoulder): a column extruded in `segments` pieces, its top/bottom and front/back shaped
// onto profile curves (upper arm, elbow, forearm, wrist, a flat and wider hand over the last
// sixth), then everything but the root subdivided with adaptive sqrt(2) and smoothed.
//
// Numbers the thesis leaves out: the profiles (fractions of the thickness at the shoulder:
// 0.62 at the elbow, 0.45 at the wrist, the hand 0.35 thick and 0.85 wide).
#include "body_tools.hpp"
#include "procedural_model_defs.hpp"

#include "genmod/procedural/sqrt2_subdivision.hpp"

namespace genmod::models::detail {
namespace {

PolyMesh build_arm(const Arguments& a, const CallContext&) {
  const char* P = "arm";
  const double length = positive_real(a, P, "length"), t = positive_real(a, P, "thickness");
  const int n = integer_in(a, P, "segments", 1, 64);
  const int levels = integer_in(a, P, "subdivisions", 0, 6);
  const double smoothing = real_in(a, P, "smoothing", 0.0, 1.0);
  const double unit = length / n;
  Workpiece w;
  w.mesh = make_box(Vec3(0, -t / 2, -t / 2), Vec3(unit, t / 2, t / 2));
  w.name("arm", all_faces(w.mesh));
  w.name("armroot", w.select("arm", ratio_box(kLow, kAll, kAll)));
  w.extrude_chain(w.select("arm", ratio_box(kHigh, kAll, kAll)), Vec3(unit, 0, 0), n - 1);
  // Profiles from the shoulder (t = 0) to the finger tips (t = 1).
  const std::vector<double> thick{1.0, 0.95, 0.8, 0.66, 0.62, 0.58, 0.5, 0.45, 0.36, 0.35, 0.3};
  const std::vector<double> wide{1.0, 0.95, 0.82, 0.7, 0.66, 0.64, 0.56, 0.5, 0.85, 0.85, 0.7};
  const FaceList py = w.select("arm", ratio_box(kAll, kHigh, kAll)), ny = w.select("arm", ratio_box(kAll, kLow, kAll));
  const FaceList pz = w.select("arm", ratio_box(kAll, kAll, kHigh)), nz = w.select("arm", ratio_box(kAll, kAll, kLow));
  shape_profile(w.mesh, py, 0, 0.0, length, 1, 0.0, 1.0, t / 2, thick);
  shape_profile(w.mesh, ny, 0, 0.0, length, 1, 0.0, -1.0, t / 2, thick);
  shape_profile(w.mesh, pz, 0, 0.0, length, 2, 0.0, 1.0, t / 2, wide);
  shape_profile(w.mesh, nz, 0, 0.0, length, 2, 0.0, -1.0, t / 2, wide);
  sqrt2_subdivide(w.mesh, w.faces("arm"), levels, smoothing);
  return std::move(w.mesh);
}

}  // namespace

ProceduralModelDef arm_definition() {
  ProcedureSpec spec;
  spec.name = "arm";
  spec.mode = Mode::Out;
  spec.params = {param("length", 0.6858), param("thickness", 0.0894521739130435), param("segments", 6),
                 param("subdivisions", 2), param("smoothing", 0.5)};
  spec.out_body = build_arm;
  spec.cacheable = true;  // no random numbers: the arguments alone decide the mesh
  ProceduralModel info{
      "arm",
      "the human arm held out along +x (shoulder, elbow, wrist, flat hand); flat root 'armroot' at x = 0",
      {{"length", "shoulder to finger tips (the thesis: 3 heads)"},
       {"thickness", "at the shoulder (the thesis's armLength, 9/23 head)"},
       {"segments", "extrusions along the arm (the thesis: divBy / 2 = 6)"},
       {"subdivisions", "sqrt(2) levels on everything but the root, 0-6"},
       {"smoothing", "sqrt(2) smoothing factor, 0..1"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
