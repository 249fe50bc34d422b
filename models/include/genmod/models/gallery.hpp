// The model gallery: named parametric surfaces with documented parameters.
//
// The 23 examples of the thesis's Chapter 3 and Appendix B (research/snyder.md section 7),
// built the way the thesis builds them from genmod's operators (sweeps, offsets, warps, the
// CPG path builder, region Booleans, matched schedules, integrate / inverse / minimize), with
// authored substitute curves (the original .crv files are lost; ours are models/curves/*.crv
// or built in code where a parameter shapes them), in thesis order: doorknob (7.2), patio_tile,
// lamp_stand, tennis_racket (7.5), briefcase_handle, banana, turbine_blade, gear,
// sphere_cylinder_fillet (7.11), cross_section_matching, offsets, offset_plate, spoon, key,
// cpg (7.17), screwdriver_regular, screwdriver_phillips, cpg_fillet, bottle (7.20),
// circular_beam, time_varying_curve, wing, furry_bear (7.24). Then standard shapes: sphere,
// torus. `genmod list` prints them with their parameters.
// A model is either a 3-D surface of (u, v) = (x(0), x(1)) over its domain, or (with
// `solid`) a generative solid of (u, v, w) = (x(0), x(1), x(2)): a deformed brick, meshed by
// its six boundary faces. Time-dependent models and families (the fillet's bulge, the wing's
// time) take the extra coordinate as a model parameter and are surfaces. An object made of
// several surfaces (the plate's walls and faces, the key's sides and caps, the bear's scalp
// and hairs) has the further ones in Model::extra_patches; model_patches() lists them all.
//
// Example:
//   using namespace genmod::models;
//   const Model& m = find_model("doorknob");
//   Fn s = build_model(m, {{"bulge_radius", 0.9}});   // unspecified parameters keep defaults
//   Mesh mesh = mesh_model(m, s, 64);
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/operators/curve.hpp"
#include "genmod/tessellate/mesh.hpp"
#include "genmod/tessellate/parametric_mesher.hpp"

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace genmod::models {

struct ModelParameter {
  std::string name;
  double value;  // the default
  std::string doc;
};

using ParameterValues = std::map<std::string, double>;

// One parametric surface of (u, v) = (x(0), x(1)) over u x v; a periodic axis closes the
// surface across its ends (the adaptive mesher's patch type, parametric_mesher.hpp).
using ModelPatch = SurfacePatch;

struct Model {
  std::string name, description;
  std::vector<ModelParameter> parameters;
  // Builds the surface from a COMPLETE parameter map (every parameter present); use
  // build_model() to start from overrides. Throws std::invalid_argument for values out of
  // the parameter's range (the message names the parameter).
  std::function<Fn(const ParameterValues&)> build;
  Interval u = Interval(0.0, 1.0), v = Interval(0.0, 1.0);
  bool periodic_u = false, periodic_v = false;
  // A solid S(u, v, w) with w in `w` (three inputs) instead of a surface.
  bool solid = false;
  Interval w = Interval(0.0, 1.0);
  // Open by nature (a sheet, a fillet piece, a tube without caps): its mesh has a boundary.
  // Every other model's adaptive mesh is closed.
  bool open = false;
  // Further surfaces of the same object (an empty function or an empty list: none), from the
  // same complete parameter map: the plate's top and bottom faces, the bear's hairs. Where
  // the object is closed, each edge of a patch coincides geometrically with an edge of the
  // main surface or of another patch (a mesher glues them). Throws like `build`.
  std::function<std::vector<ModelPatch>(const ParameterValues&)> extra_patches;
  // The extra patches tile the main surface themselves, changed (the bear's scalp in pieces
  // with a hole at each hair root, where the hair's tube starts): model_patches leaves the
  // main surface out, since meshing it too would overlap those pieces.
  bool surface_in_extra_patches = false;
};

// All models, in a fixed order.
const std::vector<Model>& gallery();
// The model of that name; std::invalid_argument naming it and listing the known models.
const Model& find_model(const std::string& name);

// The defaults with `overrides` applied; std::invalid_argument for a parameter name the model
// does not have (the message names it, the model and the model's parameters) or a non-finite
// value.
ParameterValues resolve_parameters(const Model& model, const ParameterValues& overrides = {});
// The same for any named parameter list (the implicit gallery's models too).
ParameterValues resolve_parameters(const std::string& model_name, const std::vector<ModelParameter>& parameters,
                                   const ParameterValues& overrides);
// model.build(resolve_parameters(model, overrides)).
Fn build_model(const Model& model, const ParameterValues& overrides = {});
// Every surface of the object, for meshers: the main surface (`surface`, built from `p` by
// model.build, with the model's domain and periodic flags) first unless the extra patches tile
// it (Model::surface_in_extra_patches), then model.extra_patches(p);
// for a solid, its six boundary faces (each a function of x(0), x(1); a pair of opposite
// faces that coincide, as in a solid swept all the way around, is left out).
// `p` is a complete parameter map (resolve_parameters).
std::vector<ModelPatch> model_patches(const Model& model, const Fn& surface, const ParameterValues& p);

// The surface meshed with mesh_parametric on an n x n lattice over the model's domain, with
// the model's periodic axes closed (n >= 3). A solid is meshed as its six boundary faces
// (u, v or w at either end of its domain), each an n x n lattice patch, oriented outward
// where the solid's Jacobian determinant is positive; the patches are not welded.
Mesh mesh_model(const Model& model, const Fn& surface, std::size_t n);
// The diagonal of the bounding box of the model's patches at 17 x 17 samples each (the scale
// of the default tolerance).
double model_extent(const Model& model, const Fn& surface, const ParameterValues& p);
// The model's patches meshed adaptively (parametric_mesher.hpp): closed models give closed,
// outward meshes within options.tolerance of the surface.
AdaptiveMesh mesh_model_adaptive(const Model& model, const Fn& surface, const ParameterValues& p,
                                 const AdaptiveMeshOptions& options);

// The curve files of models/curves (compiled into the library): the curve in
// models/curves/<name>.crv, parsed (CurveFileError naming the file and line), or
// std::invalid_argument naming a curve that does not exist.
Curve gallery_curve(std::string_view name);
std::vector<std::string> gallery_curve_names();

// The authored curves of the thesis models (from a complete parameter map), for tests and
// for reuse. Profiles are (radius, height) curves, cross sections closed curves in the plane.
Curve doorknob_profile(const ParameterValues& p);
Curve patio_tile_cross(const ParameterValues& p);
Curve patio_tile_profile(const ParameterValues& p);
Curve lamp_stand_cross(const ParameterValues& p);
Curve lamp_stand_profile(const ParameterValues& p);

// Sweep models of thesis 7.5-7.11 and 7.22-7.24: their authored curves (as functions of
// x(0), already scaled by the model's parameters) and extra fields, for tests and reuse.
// The closed rounded-rectangle cross section (frame_width x frame_depth) and the head oval.
Fn tennis_racket_cross(const ParameterValues& p);
Fn tennis_racket_wire(const ParameterValues& p);
// The grip cross section (x in [-1, 1], y = z scaled by depth / 2) and the two arch rails.
Fn briefcase_handle_cross(const ParameterValues& p);
Fn briefcase_handle_rail1(const ParameterValues& p);
Fn briefcase_handle_rail2(const ParameterValues& p);
// The banana's largest |bend| at that thickness: min(pi, L / thickness), L = 2 / (max banscale
// max |cross_x|) (about 6.70): beyond, its surface intersects itself (banana.cpp says why).
double banana_max_bend(double thickness);
// The closed gear curve (teeth, outer_radius, tooth_depth) the gear interpolates from.
Fn gear_cross(const ParameterValues& p);
// The App. B.1 fillet as the thesis writes it: a function of (u, v, w) = (x(0), x(1), x(2)),
// the bulge w as the third input (the model fixes w = bulge); the cylinder and sphere
// surfaces are cyl(u, v) = (interp(v, -1, 1), cylinder_radius circle(2 pi u)) and the sphere.
Fn sphere_cylinder_fillet_family(const ParameterValues& p);
// Time-varying curve (7.23): c(u, t) = (u, amplitude u^2 sin(2 pi (t - phase_lag u))) as a
// function of (u, t) = (x(0), x(1)), and u_t(t), the parameter where its arclength from 0
// reaches `arclength`, a function of t = x(1) (integrate + inverse operators).
Fn time_varying_curve_c(const ParameterValues& p);
Fn time_varying_curve_end(const ParameterValues& p);
// The wing's wire (the time-varying curve at the model's `time`, a 2-D function of x(1)) and
// its cross section (a function of (u, s) = (x(0), x(1))).
Fn wing_wire(const ParameterValues& p);
Fn wing_cross(const ParameterValues& p);
// The furry bear's hair field V(u, v) = (S, S + hair_length normalize(N + kappa S_v)) in R^6,
// S the scalp (the model surface), N = S_u x S_v.
Fn furry_bear_hair(const ParameterValues& p);
// The bear's hair roots, one per cell [i, i + 1] / (2 R) x [j, j + 1] / R of the scalp's
// parameter square (R = hair_rows, i < 2 R, j < R, row-major in j): the root circle is the
// image of the ellipse (u + a cos phi, v + b sin phi) about the cell's centre (u, v), with
// a = hair_radius / |S_u|, b = hair_radius / |S_v| at (u, v) (a circle of radius hair_radius
// to first order: S_u is perpendicular to S_v on the profile product). Throws
// std::invalid_argument naming hair_radius when an ellipse does not fit in a quarter of its cell,
// and naming hair_rows, kappa and hair_length when two hairs' tubes may cross (hairs combed
// toward the top pole converge on it; checked on tapered hulls about the hair segments).
struct HairRoot {
  double u, v, a, b;
};
std::vector<HairRoot> furry_bear_roots(const ParameterValues& p);
// The scalp with a hole at each hair root, as the model meshes it (the extra patches, with
// Model::surface_in_extra_patches): per root, the four pieces of its cell between the root
// ellipse and the cell's sides (bottom, right, top, left), piece k of (t, r) being
// S((1 - r) e(phi_k(t)) + r side_k(t)), e the root ellipse at phi_k(t) = 2 pi (k + t) / 4
// - 3 pi / 4 and side_k(t) the cell's side from corner to corner, counterclockwise. The piece's
// r = 0 edge is the quarter of the root ring that its hair's tube starts from, sample for sample.
// The cells of the first and last rows start at v = 0.2 / R and end at 1 - 0.2 / R: the
// list ends with the polar caps, the scalp over v in [0, 0.2 / R] and then [1 - 0.2 / R, 1],
// one piece per column of cells (u in [i, i + 1] / (2 R)).
std::vector<ModelPatch> furry_bear_scalp_pieces(const ParameterValues& p);
// The bear's hairs as surfaces: one closed tube per root (furry_bear_roots order) of
// (theta, s) = (x(0), x(1)), periodic in theta, from the root ring on the scalp (s = 0) to the
// tip of furry_bear_hair at the cell's centre (s = 1, a pole):
//   T(theta, s) = E(theta) + s hair_length d + ((1 - s)(1 + s) - 1) (E(theta) - S),
// E(theta) = S(root ellipse at 2 pi theta - 3 pi / 4), S and d the hair's scalp point and
// direction: the tube's cross section is the root ring scaled by 1 - s^2 about the axis.
std::vector<ModelPatch> furry_bear_hairs(const ParameterValues& p);

// Offset models of thesis 7.13-7.18 (offsets, offset_plate, spoon, key, screwdriver tips).
// The offsets surface of any closed planar curve of x(0): (offset_curve(c, r)(u), r) with
// r = interp(v, -r_max, r_max) (operators/offset.hpp: positive r is inward on a CCW curve).
Fn offsets_surface(const Fn& curve, double r_max);
// The offsets model's closed curve (models/curves/offsets_curve.crv).
Curve offsets_curve(const ParameterValues& p);
// The plate's closed cross section and its (inward offset d1, height d2) edge profile.
Curve offset_plate_cross(const ParameterValues& p);
Curve offset_plate_profile(const ParameterValues& p);
// The plate's top (z = thickness / 2, normal +z) and bottom (normal -z) faces: fans from the
// centre to the sides' top and bottom edges, periodic in the sides' u, which they share (the
// model's extra patches).
std::vector<ModelPatch> offset_plate_faces(const ParameterValues& p);
// The spoon's mid-surface (shape_x(v), arc(u, v) + (0, bend_y(v))) before thickening, and
// its half thickness thick_y(v) (functions of (u, v) = (x(0), x(1))); the flat faces
// closing its end sections (the model's extra patches): the handle's end (v = 0, normal -x)
// and the tip (v = 1, normal +x), each bounded by the four quarters of its section.
Fn spoon_mid_surface(const ParameterValues& p);
Fn spoon_half_thickness(const ParameterValues& p);
std::vector<ModelPatch> spoon_caps(const ParameterValues& p);
// The keyboard key's curves (from its parameters): the rounded-square cross section in
// [-1, 1]^2 (counterclockwise from (1, 0)), the front (yz_left) and back (yz_right) outlines
// in the yz plane and the side outline in the xz plane (x = half width), curves of v from
// the bottom (v = 0) to the top (v = 1); the sides before the warp (the thesis's _sides);
// the caps closing the sides (the model's extra patches): the dished top and the flat bottom.
Curve key_cross(const ParameterValues& p);
Curve key_yz_left(const ParameterValues& p);
Curve key_yz_right(const ParameterValues& p);
Curve key_xz(const ParameterValues& p);
Fn key_unwarped(const ParameterValues& p);
std::vector<ModelPatch> key_caps(const ParameterValues& p);
// The screwdriver tips' planar cross sections as functions of (u, v) (the model is
// (section, z(v))), and the Phillips tip's circle radius and wedge-vertex distance D of v.
Fn screwdriver_regular_section(const ParameterValues& p);
Fn screwdriver_phillips_section(const ParameterValues& p);
Fn screwdriver_phillips_radius(const ParameterValues& p);
Fn screwdriver_phillips_depth(const ParameterValues& p);

// Models on the solver layer's operators (thesis 7.12, 7.17-7.20). The bottle's cross section
// (a function of (u, v): the rounding varies along the bottle) and its thesis half; the CPG
// regions and the result's boundary (curves of x(0); `fillet_radius` present = filleted,
// `operation` absent = union); the matched inner curve of the cross-section matching model.
Fn bottle_half_cross(const ParameterValues& p);
// The bottle's largest tangent_length (exclusive): 3 sqrt 2 min over v of min(q, 1 - q), q
// the rounding schedule; beyond, its sections intersect themselves (bottle.cpp says why).
double bottle_max_tangent_length();
Fn bottle_cross(const ParameterValues& p);
Fn cpg_circle(const ParameterValues& p);
Fn cpg_bean(const ParameterValues& p);
Fn cpg_boundary(const ParameterValues& p);
Fn matching_inner(const ParameterValues& p);

}  // namespace genmod::models
