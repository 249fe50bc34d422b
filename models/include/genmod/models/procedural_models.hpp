// Morkel's furniture models (research/morkel.md section 3.2, thesis App. C.4-C.5) as registered
// procedures of the procedural layer, built with its tools only: ratio-box selections of named
// face sets, chained extrusions, adaptive sqrt(2) subdivision of cushions, curve shaping of a
// chair back or a lid, and bridges (the stitching tool on one mesh) for arms and legs.
//
//   leg      the human leg with its foot (the thesis's #Leg + Foot), cacheable: a column in
//            four pieces shaped onto thigh/knee/calf/ankle profile curves and subdivided, and a
//            `foot` call bridged under the ankle. As in the thesis the Luggage (and the chair's
//            feet) reuse it; its flat top "legtop" is what a caller bridges to.
//   chair    Algorithm 5: a seat grown from one box by extrusions along x and z, a back grown
//            up from the rear row, a subdivided cushion, four legs (extruded, or with `feet`
//            four calls of `leg` bridged under the corners), optional arms (arm rests extruded
//            forward from the back, posts up from the seat, bridged) and an optional shaped
//            back top.
//   couch    Algorithm 6: the chair's construction widened to numCushions cushions, with back
//            cushions.
//   table    Algorithm 8: a box top grown by extrusions, or an oval top (a flat box
//            subdivided with the smoothing factor), on four legs.
//   luggage  Algorithm 7, cacheable: a chest grown by extrusions with an arched lid (curve
//            shaping), on numLegs legs, each a call of `leg` with the same arguments and the
//            inherited seed, so with caching on the leg costs one miss and numLegs - 1 hits
//            (claim 12), and a repeated luggage is one luggage hit (no sub-call). The chest is
//            a call of `luggage_chest` (seed 0), appended to by shared (uncopied) leg hits.
//   luggage_chest  the luggage without legs, cacheable: the body, the arched lid and the base
//            (labelled "base") laid out for legColumns x legRows legs.
//   foot     Algorithm 4, cacheable: a grid of toe and gap columns, the toes extruded forward
//            (the big toe the longest), mirrored for the right foot; flat top "foottop".
//   arm      an arm held out along +x (upper arm, elbow, forearm, wrist, flat hand) on a flat
//            root quad "armroot".
//   torso    Algorithm 2 and the TorsoCurves of App. C.2: a 7 x 12 x 6 block of cells shaped
//            by the side, front and back Bezier curves (tummy and butt move the belly's and
//            buttocks' control points), or the smoothed egg (cubical = false); the faces the
//            limbs attach to are labelled neck, shoulder_r/l, hip_r/l.
//   head     the neck and the head (a smoothed grid box with a nose) on a flat root quad.
//   human    Algorithm 1: torso, head, two arms and two legs (left and right: two foot
//            builds) bridged together in Loomis's proportions, 8 heads tall; height (feet),
//            tummy, butt, cubical. Every length is a multiple of the head unit, so heights
//            give scaled copies of one mesh.
//   branch   a cacheable meshed cylinder (frustum): the tree's branches.
//   tree     an L-system tree (A -> F/[+A][-A], levels rewrites, seeded jitter of the angles),
//            cacheable, its 2^levels - 1 branches `branch` calls with one argument tuple per
//            order (levels misses per tree). Branches are separate closed components a small
//            gap apart (no overlaps).
//
// Level of detail (camera.hpp): the tree (levels + lod levels), the human (subdivisions + lod
// sqrt(2) levels), the chair and the couch (2 + lod sqrt(2) levels of the feet's legs and of the
// cushions, at least 1 for a cushion), the round table (subdivisions + lod) and the luggage (legSubdivisions + lod
// levels of its legs) read the context's lod and declare it for the cache key; below lod 0 the
// chair's, couch's and table's straight legs are also extruded in fewer steps (same shape,
// fewer faces). All six declare bounding boxes, so a call with a camera builds them coarser when
// they are small on screen and not at all when out of view. Without a camera (lod 0) every
// model is as its parameters say.
//
// Every model's mesh is closed, 2-manifold, oriented outward and free of self-intersections
// (tests/models/procedural_models_test.cpp checks this with the CGAL validator), and the same
// arguments and seed give the same bytes. Bad values are refused with std::invalid_argument
// naming the procedure and the parameter ("call 'chair': parameter 'length' ...").
//
// Example:
//   using namespace genmod;
//   const ProcedureRegistry& registry = models::procedural_registry();
//   PolyMesh chair = registry.call("chair", {{"backLength", 2.0}, {"arms", true}});
//   Mesh triangles = models::mesh_procedural_model("chair");   // `genmod mesh chair -o chair.ply`, z up
//   if (chair.n_faces() == 0 || triangles.triangles.empty()) throw std::runtime_error("no chair");
#pragma once

#include "genmod/procedural/procedure.hpp"
#include "genmod/tessellate/mesh.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace genmod::models {

// A procedural model as `genmod list` shows it: the name of its registered procedure, a line
// of description and one line of documentation per parameter (in declaration order; types and
// defaults come from the procedure's spec).
struct ProceduralModel {
  std::string name, description;
  std::vector<std::pair<std::string, std::string>> parameter_docs;
};

// leg, chair, couch, table, luggage, luggage_chest, foot, arm, torso, head, human, branch, tree, in
// that order.
const std::vector<ProceduralModel>& procedural_gallery();
// nullptr when no procedural model has that name.
const ProceduralModel* find_procedural_model(const std::string& name);

// Adds the procedures to `registry` (std::invalid_argument if one of the names is taken).
// `adjust`, when given, may change each spec before it is added (benchmarks switch the
// cacheable flag of single procedures, e.g. the human with only its feet cached).
void register_procedural_models(ProcedureRegistry& registry, const std::function<void(ProcedureSpec&)>& adjust = {});
// A process-wide registry holding exactly these procedures, registered on first use (thread
// safe). Its caching switch and cache counters are shared by all users of this registry; tests
// and benchmarks that count cache hits use a registry of their own.
ProcedureRegistry& procedural_registry();

// The triangulated mesh of procedural_registry().call(name, args, {seed, lod}), turned from the
// procedures' frame (y up, the front facing +z, as in the thesis's Java3D) to genmod's z up
// (x, y, z) -> (x, -z, y): the front faces -y, towards `genmod preview`'s viewpoint. The lod is
// a refinement offset (camera.hpp): 0 as the parameters say, below 0 coarser for the models that
// use it (tree, human, chair, couch, table, luggage), ignored by the others.
Mesh mesh_procedural_model(const std::string& name, const NamedArgs& args = {}, std::int64_t seed = 0, int lod = 0);

// A camera at `eye` looking at `target`, +z up, in genmod's z-up frame, with camera.hpp's
// defaults for the rest (640 x 480 pixels, lod -8..0): what `genmod mesh --camera` and Python's
// procedural.mesh(camera=...) build. Throws std::invalid_argument for a non-finite point, an eye
// at the target ("same point") or a vertical view ("vertical": the up would be the view).
Camera camera_looking_at(const Vec3& eye, const Vec3& target);

// A camera given in genmod's z-up frame (the frame of mesh_procedural_model's meshes and of
// `genmod mesh --camera`) turned into the procedures' y-up frame, where the registry places
// bounds: position, direction and up go through (x, y, z) -> (x, z, -y), the inverse of the
// turn above; the other fields are kept.
Camera procedure_frame_camera(const Camera& z_up);

// How `camera` (z-up frame) sees the model's declared bounding box: the visibility and the lod
// a call with that camera gets (view_of_box). nullopt when the model declares no bounds (the
// camera then neither culls it nor sets its lod). Throws std::invalid_argument for a bad camera
// (check_camera) or bad arguments.
std::optional<BoxView> procedural_model_view(const std::string& name, const NamedArgs& args, const Camera& camera);

// The model built with `camera` (z-up frame) in its context: at the lod the camera chooses for
// its bounds, an empty mesh when the camera does not see them (procedure.hpp).
Mesh mesh_procedural_model(const std::string& name, const NamedArgs& args, std::int64_t seed, const Camera& camera);

}  // namespace genmod::models
