// model_patches: the one list of surfaces a mesher needs for a gallery model.
#include "genmod/models/gallery.hpp"

#include <stdexcept>

namespace genmod::models {

std::vector<ModelPatch> model_patches(const Model& model, const Fn& surface, const ParameterValues& p) {
  if (model.solid)
    throw std::invalid_argument("model_patches: model '" + model.name +
                                "' is a solid (mesh its six boundary faces with mesh_model)");
  std::vector<ModelPatch> patches{{surface, model.u, model.v, model.periodic_u, model.periodic_v}};
  if (model.extra_patches) {
    std::vector<ModelPatch> extra = model.extra_patches(p);
    patches.insert(patches.end(), extra.begin(), extra.end());
  }
  return patches;
}

}  // namespace genmod::models
