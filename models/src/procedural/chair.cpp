// chair: Algorithm 5 / App. C.4 of the thesis (research/morkel.md section 3.2) as a registered
// Out procedure. Parameters and defaults are the listing's, less the ones it declares but does
// not use or that genmod has no counterpart for: numLegs and type (unused), file and fileName
// (`genmod mesh` writes files). cubic = false is the disc base of Experiment 3 (the chair drawn
// onto a round seat, seating.cpp). feet calls the human `leg` procedure (leg.cpp, with its
// foot), as the listing calls the human Leg. segments is an Integer here (the thesis's 6.0 is
// used as a count). bottomArms is Algorithm 5's flag (the listing joins the posts whenever arms
// is set).
#include "furniture_tools.hpp"
#include "procedural_model_defs.hpp"
#include "seating.hpp"

namespace genmod::models::detail {
namespace {

// The arguments, checked (the body and the bounds both read them).
SeatingShape chair_shape(const Arguments& a) {
  SeatingShape s = shared_seating_shape(a, "chair");
  s.feet = a.boolean("feet");
  s.disc = !a.boolean("cubic");
  return s;
}

}  // namespace

ProceduralModelDef chair_definition() {
  ProcedureSpec spec;
  spec.name = "chair";
  spec.mode = Mode::Out;
  spec.params = {param("length", 2.0),   param("depth", 2.0),     param("legLength", 2.0),  param("backLength", 1.5),
                 param("segments", 6),   param("arms", false),    param("bottomArms", true), param("shape", false),
                 param("offSet", 2.0), param("feet", false),  param("cubic", true)};
  // The lod sets the cushions' (and feet's) sqrt(2) rounds and the legs' steps (seating.cpp).
  spec.uses_lod = true;
  // The bounds let a camera cull the chair or choose its lod (camera.hpp).
  spec.bounds = [](const Arguments& a) { return seating_bounds(chair_shape(a)); };
  spec.out_body = [](const Arguments& a, const CallContext& context) { return build_seating(chair_shape(a), context); };
  ProceduralModel info{
      "chair",
      "Morkel's chair (Algorithm 5): seat grown by extrusions, back, subdivided cushion, four legs, optional arms "
      "(bridged) and shaped back",
      {{"length", "seat width along x"},
       {"depth", "seat depth along z"},
       {"legLength", "leg length below the seat"},
       {"backLength", "back height above the seat"},
       {"segments", "cells per axis (detail; 1-3 give partial chairs: no cushion, no arms); the lod sets the cushion's "
                    "sqrt(2) rounds (2 + lod, at least 1) and, below 0, halves the legs' steps"},
       {"arms", "arm rests extruded from the back"},
       {"bottomArms", "with arms: posts from the seat bridged to the rests"},
       {"shape", "arch the top of the back"},
       {"offSet", "arch control height in back cells (apex rises half of it); -1..16"},
       {"feet", "legs are calls of the cacheable `leg` (with feet) instead of extrusions; segments >= 3"},
       {"cubic", "the square base (true) or the disc base of the base-shape experiment (false): the seat round"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
