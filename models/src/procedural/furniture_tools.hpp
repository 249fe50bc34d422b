// Shared pieces of the procedural models: parameter checks that name the procedure and the
// parameter, ratio ranges that pick whole grid cells, and a model under construction (mesh +
// named face sets) with the chained extrusion the thesis's "Repeat k times: select, extrude"
// loops amount to.
#pragma once

#include "genmod/models/procedural_models.hpp"
#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/selection.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

namespace genmod::models::detail {

[[noreturn]] void refuse_parameter(std::string_view procedure, std::string_view parameter, const std::string& problem);
// A finite value > 0.
double positive_real(const Arguments& a, std::string_view procedure, std::string_view name);
// A finite value in [lo, hi].
double real_in(const Arguments& a, std::string_view procedure, std::string_view name, double lo, double hi);
// An integer in [lo, hi].
int integer_in(const Arguments& a, std::string_view procedure, std::string_view name, int lo, int hi);

// The ratio interval that selects cells first..last (inclusive) of `cells` equal cells along
// an axis: a quarter cell of margin on both sides, so no vertex lies near a bound and the
// result does not depend on rounding.
std::pair<double, double> cell_range(int first, int last, int cells);
// Ratio intervals for the lowest and the highest layer of vertices along an axis (a flat
// margin of 1% of the extent, the thesis's 0.99..1).
inline constexpr std::pair<double, double> kLow{-0.01, 0.01};
inline constexpr std::pair<double, double> kHigh{0.99, 1.01};
inline constexpr std::pair<double, double> kAll{-0.01, 1.01};

RatioBox ratio_box(std::pair<double, double> x, std::pair<double, double> y, std::pair<double, double> z);

// Level of detail (camera.hpp: lod 0 is the model as its parameters say, each step below one
// refinement fewer, each step above one more) for the furniture:
// refinement levels (sqrt(2) rounds of a curved part): levels + lod, kept in [0, max_levels];
int lod_levels(int levels, int lod, int max_levels);
// the extrusion steps of a straight part (a leg that is a prism whatever its steps): `steps` at
// lod >= 0 (more steps would add faces but no shape), halved (rounded up) per lod below 0, at
// least 1. The part's shape is the same at every lod; only its face count changes.
int lod_steps(int steps, int lod);

// A model being built: the mesh and its named face sets (membership carried by face labels).
struct Workpiece {
  PolyMesh mesh;
  FaceSets sets;

  // Selects `box` relative to the set `parent` ("" = whole mesh).
  FaceList select(const std::string& parent, const RatioBox& box) const;
  // Registers `faces` as the set `id` (the faces leave their previous set) and returns them.
  FaceList name(const std::string& id, const FaceList& faces);
  // Extrudes `faces` by `by`, then the caps again, `times` times in all (the thesis's chained
  // extrusions), and returns the last caps (the input when times == 0). Sets are updated.
  FaceList extrude_chain(FaceList faces, const Vec3& by, int times);
  FaceList faces(const std::string& id) const { return sets.get(id).faces; }
};

// Adds a copy of `leg` (a `leg` procedure's mesh: flat top quad labelled "legtop" at y = 0)
// centred below `cell` (faces of w.mesh on the plane y = lowest of the cell's vertices) with its
// top `gap` below, and bridges the top to the cell (the new triangles labelled "ankle"). The
// mesh is not garbage-collected: handles of other faces stay valid.
void attach_leg(Workpiece& w, const PolyMesh& leg, const FaceList& cell, double gap);
// The same on a bare mesh.
void attach_leg(PolyMesh& mesh, const PolyMesh& leg, const FaceList& cell, double gap);

// The box [lo, hi] grown by `fraction` of its largest side on every side: the bounding boxes
// the furniture declares for the camera (procedure.hpp) are worked out from the construction and
// padded, since a box that is too large only costs a coarser cull.
std::array<Vec3, 2> padded_box(const Vec3& lo, const Vec3& hi, double fraction = 0.05);

// The union of face lists, in index order without repeats (selections that may overlap).
FaceList merged(std::initializer_list<FaceList> lists);

}  // namespace genmod::models::detail
