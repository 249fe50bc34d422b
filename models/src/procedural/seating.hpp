// The construction the chair and the couch share (Algorithms 5 and 6): the couch is the chair
// widened to several cushions, as research/morkel.md's [decision] for the couch says.
#pragma once

#include "genmod/procedural/procedure.hpp"

#include <array>
#include <string>
#include <string_view>

namespace genmod::models::detail {

struct SeatingShape {
  double length = 2.0;       // x extent of one cushion's share of the seat
  double depth = 2.0;        // z extent of the seat
  double leg_length = 2.0;   // legs, down from the seat's bottom
  double back_length = 1.5;  // the back, up from the seat's top
  int segments = 6;          // cells per cushion along x, along z, in the back (and the legs' steps at lod 0)
  int cushions = 1;          // seat cushions side by side along x
  bool arms = false, bottom_arms = true, shape = false, back_cushions = false;
  bool feet = false;  // `leg` procedure calls instead of extruded legs (needs segments >= 3)
  bool disc = false;  // the chair's round base (the listing's cubic = false): see seating.cpp
  double offset = 2.0;  // the shaped back top rises offset * backLength / segments / 2 in the middle
};

// The arguments the chair and the couch share (length, depth, legLength, backLength, segments,
// arms, bottomArms, shape, offSet), checked; errors name `procedure`.
SeatingShape shared_seating_shape(const Arguments& a, std::string_view procedure);

// Checked by the callers; builds the seat in [0, cushions * length] x [-leg_length, ...] x
// [0, depth], the back at the low z side, facing +z.
// With feet, the legs are calls of `leg` through `context` (same arguments: one build, three
// copies when caching is on).
PolyMesh build_seating(const SeatingShape& s, const CallContext& context);
// A box holding build_seating(s, ...) at every lod (the chair's and the couch's bounds).
std::array<Vec3, 2> seating_bounds(const SeatingShape& s);

}  // namespace genmod::models::detail
