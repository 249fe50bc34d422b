// The implicit gallery: named implicit solids f(x, y, z) < 0 with documented parameters and
// the box to mesh them in, for `genmod list` / `genmod mesh NAME --min-feature H` and tests.
//
// Example:
//   using namespace genmod::models;
//   const ImplicitModel& m = *find_implicit_model("sphere_gyroid");   // nullptr if unknown
//   Fn f = build_implicit_model(m, {{"radius", 2.5}});
//   ImplicitMesh mesh = mesh_implicit(f, m.box, {.min_feature = 4 * m.min_feature});
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/models/gallery.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"

#include <functional>
#include <string>
#include <vector>

namespace genmod::models {

struct ImplicitModel {
  std::string name, description;
  std::vector<ModelParameter> parameters;
  // Builds f from a COMPLETE parameter map; std::invalid_argument naming a parameter whose
  // value is out of range.
  std::function<Fn(const ParameterValues&)> build;
  Box3 box;            // the region to mesh
  double min_feature;  // a default cell size that shows the model's detail
};

// All implicit models, in a fixed order: sphere_gyroid (libfive's meshing benchmark shape),
// tanglecube, drilled_block (CSG with sharp edges), blobby (four blended spheres, claim 40 of
// the thesis), gyroid_sheet, starfish (Bloomenthal's joint, starfish.hpp), tee (Bloomenthal's convolution tee),
// rotated_pair, ramiform, arc_convolution (his branching demos, §7.5), convolution_arm and hand
// (§7.2-7.3; bloomenthal_models.hpp; the arm's name leaves `arm` to the procedural human's).
const std::vector<ImplicitModel>& implicit_gallery();
// nullptr when there is no implicit model of that name.
const ImplicitModel* find_implicit_model(const std::string& name);
// The defaults with overrides applied (std::invalid_argument for an unknown parameter name
// or a non-finite value), built.
Fn build_implicit_model(const ImplicitModel& model, const ParameterValues& overrides = {});

}  // namespace genmod::models
