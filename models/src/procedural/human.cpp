// human: Morkel's Loomis-proportioned human figure (Algorithm 1, HumanFigure of App. C.1;
// research/morkel.md section 3.1) as an Out procedure assembling calls of torso, head, arm
// (twice) and the cacheable leg (left and right, each with its cacheable foot).
//
// Proportions in head units (Loomis: the figure is 8 heads; HumanFigure: head = height in
// metres / 8, the height given in feet, 6.0 by default): the torso 61.5/23 x 40/23 x 29/23
// head (height, across, front to back), the arms 3 heads long and 9/23 head thick, the legs 4
// heads from hip to sole, the head one head high on a neck. The parts are built in their own
// frames and bridged to the faces the torso names for them (neck, shoulder_r/l, hip_r/l); the
// egg figure (cubical = false, Experiment 3's Humpty-Dumpty) has no head. The figure's right is -x (the thesis's 0-1% x selections), its front +z, the soles at y = 0.
//
// Numbers the thesis leaves out (its Arm, Leg, Head listings are missing): the gaps the bridges
// span (0.08 head at the hips and neck, 0.1 head at the shoulders), the legs' top (0.7 x 0.78
// head; 0.6 x 0.78 on the egg torso, whose hips lie closer together), foot (about 1.1 head long with the heel, 0.25 head high), the arms held out level (T pose).
// tummy and butt are lengths in metres added to the torso curves' belly and buttocks control
// points, as in the listing; gender is not a parameter (the listing declares it unused).
// Every length is a multiple of the head unit, so two heights give the same mesh scaled.
//
// Level of detail (camera.hpp): the human declares uses_lod and a bounding box, and gives its
// limbs and head clamp(subdivisions + lod, 0, 4) sqrt(2) levels, so lod 0 (no camera) is the
// figure its parameters say and each lod below is one subdivision level fewer. The box, in
// head units H: x in [-5, 5] H (the arms' tips are about 4 H out), y in [-0.5, 9] H (soles at
// 0, the top of the head near 8.4 H), z in [-2, 2] H (torso, belly and feet within 1.6 H);
// tummy and butt add up to the torso's depth in z.
#include "body_tools.hpp"
#include "procedural_model_defs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace genmod::models::detail {
namespace {

// The head unit in metres (height in feet, checked).
double head_unit(const Arguments& a) {
  const double height = positive_real(a, "human", "height");
  if (!(height <= 100.0)) refuse_parameter("human", "height", "must be at most 100 (feet)");
  return height * 30.48 / 100.0 / 8.0;
}

std::array<Vec3, 2> human_bounds(const Arguments& a) {
  const double H = head_unit(a), depth = 2.0 * H + 2.0 * (29.0 / 23.0) * H;  // tummy, butt <= the torso's depth
  return {Vec3(-5.0 * H, -0.5 * H, -depth), Vec3(5.0 * H, 9.0 * H, depth)};
}

PolyMesh build_human(const Arguments& a, const CallContext& context) {
  const char* P = "human";
  const double H = head_unit(a);
  const double torso_h = (61.5 / 23.0) * H, torso_l = (40.0 / 23.0) * H, torso_w = (29.0 / 23.0) * H;
  const double tummy = real_in(a, P, "tummy", -0.1 * torso_w, torso_w);
  const double butt = real_in(a, P, "butt", -0.1 * torso_w, torso_w);
  const bool cubical = a.boolean("cubical");
  const int levels = std::clamp(integer_in(a, P, "subdivisions", 0, 4) + context.lod(), 0, 4);

  const double leg_h = 4.0 * H, hip_gap = 0.08 * H, shoulder_gap = 0.1 * H, neck_gap = 0.08 * H;
  Workpiece w;
  w.mesh = context.call("torso", {{"height", torso_h},
                                  {"length", torso_l},
                                  {"width", torso_w},
                                  {"head", H},
                                  {"tummy", tummy},
                                  {"butt", butt},
                                  {"cubical", cubical}});
  apply_affine(Affine::translation(Vec3(0, leg_h + hip_gap, 0)), w.mesh);
  // All attachment faces first: bridges delete faces (the mesh is collected at the end).
  const FaceList neck = faces_labelled(w.mesh, "neck"), shoulder_r = faces_labelled(w.mesh, "shoulder_r"),
                 shoulder_l = faces_labelled(w.mesh, "shoulder_l"), hip_r = faces_labelled(w.mesh, "hip_r"),
                 hip_l = faces_labelled(w.mesh, "hip_l");
  const auto centre = [&](const FaceList& f) {
    const auto [lo, hi] = bounds(w.mesh, f);
    return std::array<Vec3, 3>{lo, hi, 0.5 * (lo + hi)};
  };

  // Legs: left and right differ in their side (the foot's big toe inside), so two builds.
  for (const char* side : {"right", "left"}) {
    const FaceList& hip = std::string(side) == "right" ? hip_r : hip_l;
    const std::shared_ptr<const PolyMesh> leg_part = context.call_shared("leg", {{"height", leg_h},
                                             {"width", (cubical ? 0.7 : 0.6) * H},
                                             {"depth", 0.78 * H},
                                             {"segments", 4},
                                             {"footLength", 0.55 * H},
                                             {"footHeight", 0.25 * H},
                                             {"side", side},
                                             {"subdivisions", levels}});
    const PolyMesh& leg = *leg_part;  // shared: a hit is not copied
    const auto c = centre(hip);
    attach_part(w, leg, "legtop", hip, Affine::translation(Vec3(c[2][0], c[0][1] - hip_gap, c[2][2])),
                std::string("hip_") + side[0]);
  }
  // Arms, held out along +x (left) and -x (right: the left arm's half turn about y).
  const std::shared_ptr<const PolyMesh> arm_part = context.call_shared("arm", {{"length", 3.0 * H}, {"thickness", (9.0 / 23.0) * H}, {"subdivisions", levels}});
  const PolyMesh& arm = *arm_part;  // shared: a hit is not copied
  {
    const auto c = centre(shoulder_l);
    attach_part(w, arm, "armroot", shoulder_l, Affine::translation(Vec3(c[1][0] + shoulder_gap, c[2][1], c[2][2])),
                "shoulder_l");
  }
  {
    const auto c = centre(shoulder_r);
    Affine half_turn;
    half_turn.m = {{{-1, 0, 0, c[0][0] - shoulder_gap}, {0, 1, 0, c[2][1]}, {0, 0, -1, c[2][2]}}};
    attach_part(w, arm, "armroot", shoulder_r, half_turn, "shoulder_r");
  }
  // Neck and head; the egg figure has none (Experiment 3's Humpty-Dumpty: an egg with arms and
  // legs), its neck faces stay part of the egg.
  if (cubical) {
    const std::shared_ptr<const PolyMesh> head_part = context.call_shared("head", {{"head", H}, {"subdivisions", levels}});
    const PolyMesh& head = *head_part;  // shared: a hit is not copied
    const auto c = centre(neck);
    attach_part(w, head, "headroot", neck, Affine::translation(Vec3(c[2][0], c[1][1] + neck_gap, c[2][2])), "neck");
  }
  w.mesh.garbage_collection();
  return std::move(w.mesh);
}

}  // namespace

ProceduralModelDef human_definition() {
  ProcedureSpec spec;
  spec.name = "human";
  spec.mode = Mode::Out;
  spec.params = {param("height", 6.0), param("tummy", 0.0), param("butt", 0.0), param("cubical", true),
                 param("subdivisions", 2)};
  spec.uses_lod = true;
  spec.bounds = human_bounds;
  spec.out_body = build_human;
  ProceduralModel info{
      "human",
      "Morkel's Loomis-proportioned human (Algorithm 1): torso, head, two arms and two cached legs with feet, 8 "
      "heads tall",
      {{"height", "in feet (the thesis's unit; 6 ft = 1.83 m), at most 100; the soles at y = 0"},
       {"tummy", "belly forward, in metres (-0.1..1 of the torso's depth)"},
       {"butt", "buttocks back, in metres (-0.1..1 of the torso's depth)"},
       {"cubical", "the extruded torso with a head (true) or Humpty-Dumpty, the base-shape experiment's egg torso with arms and legs, no head (false)"},
       {"subdivisions", "sqrt(2) levels of the limbs and head, 0-4; the lod adds to it (camera.hpp)"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
