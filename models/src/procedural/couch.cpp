// couch: Algorithm 6 of the thesis (research/morkel.md section 3.2; the thesis has no listing).
// As the spec's [decision] says, the chair's construction with the seat numCushions cushions
// long: `length` is one cushion's share, so the couch grows with the number of cushions.
// Defaults: the chair's, with arms on, three cushions and back cushions.
#include "furniture_tools.hpp"
#include "procedural_model_defs.hpp"
#include "seating.hpp"

namespace genmod::models::detail {
namespace {

// The arguments, checked (the body and the bounds both read them).
SeatingShape couch_shape(const Arguments& a) {
  SeatingShape s = shared_seating_shape(a, "couch");
  s.cushions = integer_in(a, "couch", "numCushions", 1, 16);
  s.back_cushions = a.boolean("backCushions");
  return s;
}

}  // namespace

ProceduralModelDef couch_definition() {
  ProcedureSpec spec;
  spec.name = "couch";
  spec.mode = Mode::Out;
  spec.params = {param("length", 2.0),     param("depth", 2.0),         param("legLength", 1.0),
                 param("backLength", 1.5), param("segments", 6),        param("numCushions", 3),
                 param("arms", true),      param("bottomArms", true),   param("backCushions", true),
                 param("shape", false),    param("offSet", 2.0)};
  spec.uses_lod = true;  // as the chair's (seating.cpp)
  spec.bounds = [](const Arguments& a) { return seating_bounds(couch_shape(a)); };
  spec.out_body = [](const Arguments& a, const CallContext& context) { return build_seating(couch_shape(a), context); };
  ProceduralModel info{
      "couch",
      "Morkel's couch (Algorithm 6): the chair's construction numCushions cushions long, with back cushions and arms",
      {{"length", "seat width per cushion along x"},
       {"depth", "seat depth along z"},
       {"legLength", "leg length below the seat"},
       {"backLength", "back height above the seat"},
       {"segments", "cells per cushion and axis (detail); the lod sets the cushions' sqrt(2) rounds (2 + lod, at least 1)"},
       {"numCushions", "seat cushions side by side, 1-16"},
       {"arms", "arm rests extruded from the back"},
       {"bottomArms", "with arms: posts from the seat bridged to the rests"},
       {"backCushions", "cushions extruded from the back"},
       {"shape", "arch the top of the back"},
       {"offSet", "arch control height in back cells (apex rises half of it); -1..16"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
