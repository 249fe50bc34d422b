// The region gallery: models made of several regions whose shared boundaries form a
// non-manifold surface (Bloomenthal §5.7), meshed by polygonize_regions. `genmod list` shows
// them as "(regions)"; `genmod mesh NAME -o FILE` writes the mesh. Today: the maple leaf
// (bloomenthal_models.hpp), a blade sheet with veins, non-manifold where blade meets vein.
//
// Example:
//   using namespace genmod::models;
//   // a coarse lattice (cube edge 0.1) for a quick look; 0 takes the model's default
//   RegionModelMesh m = mesh_region_model("maple_leaf", {{"vein_radius", 0.05}}, 0.1);
//   // m.result.mesh: triangles; m.result.regions: the two regions each one separates
#pragma once

#include "genmod/models/gallery.hpp"
#include "genmod/tessellate/nonmanifold_polygonizer.hpp"

#include <string>
#include <vector>

namespace genmod::models {

struct RegionModel {
  std::string name, description;
  std::vector<ModelParameter> parameters;
  double cube_size;  // the default lattice cube edge
};

const std::vector<RegionModel>& region_models();
// nullptr when there is no region model of that name.
const RegionModel* find_region_model(const std::string& name);

struct RegionModelMesh {
  RegionMesh result;  // a triangle's normal points into the second of its two regions
  std::vector<std::string> region_names;  // by region index
};

// Meshes a region model with its defaults overridden by `overrides` and the lattice cube edge
// `cube_size` (0: the model's default). std::invalid_argument names an unknown model, an
// unknown or out-of-range parameter, or a bad cube size; a lattice limit that is hit is
// reported in result.stats.limits_hit.
RegionModelMesh mesh_region_model(const std::string& name, const ParameterValues& overrides = {},
                                  double cube_size = 0.0);

}  // namespace genmod::models
