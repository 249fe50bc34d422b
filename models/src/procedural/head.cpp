// head: the human neck and head (thesis #Head, whose listing is missing; re-authored from
// Algorithm 1 and the Loomis proportions) as an Out procedure. A neck column of two extruded
// cells on a flat root quad "headroot" at y = 0 (the human bridges it to the torso's top), and
// a head, a 3 x 3 x 3 grid box one head high, 2/3 head wide and 0.8 head deep with a nose (the
// front's middle cell extruded forward), subdivided with adaptive sqrt(2) and smoothing 1 into
// an egg; the neck's top is bridged to the middle cell of the head's underside.
//
// Numbers the thesis leaves out: neck 0.45 x 0.45 x 0.3 head set 0.1 head behind the head's
// centre, the gap under the head 0.08 head, the nose 0.12 head long.
#include "body_tools.hpp"
#include "procedural_model_defs.hpp"

#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"

namespace genmod::models::detail {
namespace {

PolyMesh build_head(const Arguments& a, const CallContext&) {
  const char* P = "head";
  const double H = positive_real(a, P, "head");
  const int levels = integer_in(a, P, "subdivisions", 0, 5);
  const double nw = 0.45 * H, nh = 0.3 * H, gap = 0.08 * H, back = -0.1 * H;
  Workpiece w;
  w.mesh = make_box(Vec3(-nw / 2, 0, back - nw / 2), Vec3(nw / 2, nh / 2, back + nw / 2));
  w.name("neck", all_faces(w.mesh));
  w.name("headroot", w.select("neck", ratio_box(kAll, kLow, kAll)));
  w.extrude_chain(w.select("neck", ratio_box(kAll, kHigh, kAll)), Vec3(0, nh / 2, 0), 1);
  w.name("necktop", w.select("neck", ratio_box(kAll, kHigh, kAll)));
  sqrt2_subdivide(w.mesh, w.faces("neck"), levels > 0 ? 1 : 0, 0.5);
  w.sets.update(w.mesh);

  Workpiece h;
  h.mesh = make_grid_box(Vec3(-H / 3, 0, -0.4 * H), Vec3(H / 3, H, 0.4 * H), 3, "head");
  h.sets.add(h.mesh, FaceSet{"head", "", all_faces(h.mesh)});
  h.name("chin", h.select("head", ratio_box(cell_range(1, 1, 3), kLow, cell_range(1, 1, 3))));
  h.extrude_chain(h.name("nose", h.select("head", ratio_box(cell_range(1, 1, 3), cell_range(1, 1, 3), kHigh))),
                  Vec3(0, 0, 0.12 * H), 1);
  sqrt2_subdivide(h.mesh, merged({h.faces("head"), h.faces("nose")}), levels, 1.0);
  h.sets.update(h.mesh);
  attach_part(h, w.mesh, "necktop", h.faces("chin"), Affine::translation(Vec3(0, -(nh + gap), 0)), "neck");
  h.mesh.garbage_collection();
  // Root at y = 0.
  apply_affine(Affine::translation(Vec3(0, nh + gap, 0)), h.mesh);
  return std::move(h.mesh);
}

}  // namespace

ProceduralModelDef head_definition() {
  ProcedureSpec spec;
  spec.name = "head";
  spec.mode = Mode::Out;
  spec.params = {param("head", 0.2286), param("subdivisions", 2)};
  spec.out_body = build_head;
  spec.cacheable = true;  // no random numbers: the arguments alone decide the mesh
  ProceduralModel info{"head",
                       "the human neck and head (a smoothed grid box with a nose); flat root 'headroot' at y = 0",
                       {{"head", "the head unit (Loomis: an eighth of the height): the head's height"},
                        {"subdivisions", "sqrt(2) levels of the head (smoothing 1), 0-5"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
