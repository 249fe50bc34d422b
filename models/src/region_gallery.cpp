#include "genmod/models/region_gallery.hpp"

#include "genmod/models/bloomenthal_models.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace genmod::models {

const std::vector<RegionModel>& region_models() {
  static const std::vector<RegionModel> models = {
      {"maple_leaf",
       "Bloomenthal's maple leaf (Sec. 7.4, reconstructed): five veins and a petiole blended into a flat blade sheet; "
       "non-manifold where blade meets vein, open at the blade's margin",
       {{"vein_radius", 0.04, "radius of the veins at their base (0 < r <= 0.1; they taper to half)"}},
       // The research notes' 0.02-0.03. No self-intersecting or degenerate triangles at
       // cubes 0.015 to 0.04 (before issue 11's fix of the post-process: 4 to 9 pairs near
       // blade/vein junctions); `genmod mesh` checks.
       0.02},
  };
  return models;
}

const RegionModel* find_region_model(const std::string& name) {
  for (const RegionModel& m : region_models())
    if (m.name == name) return &m;
  return nullptr;
}

RegionModelMesh mesh_region_model(const std::string& name, const ParameterValues& overrides, double cube_size) {
  const RegionModel* model = find_region_model(name);
  if (!model) throw std::invalid_argument("genmod: no region model named '" + name + "'");
  if (!(cube_size >= 0) || !std::isfinite(cube_size))
    throw std::invalid_argument("genmod: " + name + ": cube size must be finite and >= 0 (0: the default)");
  const ParameterValues p = resolve_parameters(name, model->parameters, overrides);
  const MapleLeaf leaf = maple_leaf(p.at("vein_radius"));
  NonmanifoldSettings s;
  s.cube_size = cube_size > 0 ? cube_size : model->cube_size;
  // The blade is the plane z = 0 and the veins reach about vein_radius off it. The z range
  // holds k + 1/2 cubes on each side, so that the plane runs through the middle of a layer of
  // cubes and no corner lies on it (a corner on the sheet is in neither half-space).
  const double k = std::ceil((0.05 + 1.5 * p.at("vein_radius")) / s.cube_size);
  const double half = (k + 0.5) * s.cube_size;
  s.bounds = {Interval(-1.0, 1.0), Interval(-0.4, 1.1), Interval(-half, half)};
  // A triangle's normal points into the higher-numbered of its two regions, so the regions
  // are renumbered vein 0, beyond the blade 1, below 2, above 3: the veins' normals point
  // out of them and the blade's up (maple_leaf() numbers them beyond, vein, above, below).
  const int renumber[4] = {1, 0, 3, 2};
  const std::vector<Fn> regions = {leaf.regions[1], leaf.regions[0], leaf.regions[3], leaf.regions[2]};
  for (const auto& [a, b] : maple_leaf_interest())
    s.interest.emplace_back(std::min(renumber[a], renumber[b]), std::max(renumber[a], renumber[b]));
  RegionModelMesh out;
  out.region_names = {"vein", "beyond the blade", "below", "above"};
  out.result = polygonize_regions(regions, s);
  return out;
}

}  // namespace genmod::models
