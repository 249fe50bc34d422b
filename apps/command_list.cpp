// genmod list: the models of the gallery with their parameters and defaults.
#include "commands.hpp"

#include "genmod/models/gallery.hpp"
#include "genmod/models/implicit_gallery.hpp"
#include "genmod/models/procedural_models.hpp"
#include "genmod/models/region_gallery.hpp"
#include "genmod/models/trimmed_csg.hpp"

#include <cstdio>
#include <string>

namespace genmod::app {
namespace {

int run_list(std::span<const std::string> args) {
  if (!args.empty()) throw UsageError("unexpected argument '" + args[0] + "'");
  for (const models::Model& m : models::gallery()) {
    std::printf("%s\n  %s%s\n", m.name.c_str(), m.description.c_str(),
                m.open ? " (open: its mesh has a boundary)" : "");
    for (const models::ModelParameter& p : m.parameters)
      std::printf("    %-14s %-8g %s\n", p.name.c_str(), p.value, p.doc.c_str());
  }
  std::printf("\nimplicit models (solid where f < 0; genmod mesh NAME [--min-feature H] meshes them in their box)\n");
  for (const models::ImplicitModel& m : models::implicit_gallery()) {
    std::printf("%s (implicit)\n  %s\n  box [%g, %g] x [%g, %g] x [%g, %g], min_feature %g\n", m.name.c_str(),
                m.description.c_str(), m.box[0].lo(), m.box[0].hi(), m.box[1].lo(), m.box[1].hi(), m.box[2].lo(),
                m.box[2].hi(), m.min_feature);
    for (const models::ModelParameter& p : m.parameters)
      std::printf("    %-14s %-8g %s\n", p.name.c_str(), p.value, p.doc.c_str());
  }
  std::printf("\nCSG of trimmed surfaces (genmod mesh NAME [--tolerance W] -o FILE; W is the sampling box width, default 0.05)\n");
  for (const models::CsgModel& m : models::csg_models()) std::printf("%s (csg)\n  %s\n", m.name.c_str(), m.description.c_str());
  std::printf("\nregion models (several regions; their boundaries form a non-manifold surface; genmod mesh NAME "
              "[--param K=V] [--cube-size H] -o FILE)\n");
  for (const models::RegionModel& m : models::region_models()) {
    std::printf("%s (regions)\n  %s\n  cube size %g\n", m.name.c_str(), m.description.c_str(), m.cube_size);
    for (const models::ModelParameter& p : m.parameters)
      std::printf("    %-14s %-8g %s\n", p.name.c_str(), p.value, p.doc.c_str());
  }
  std::printf("\nprocedural models (Morkel's registered procedures; genmod mesh NAME [--param K=V] [--seed S] -o FILE)\n");
  const ProcedureRegistry& registry = models::procedural_registry();
  for (const models::ProceduralModel& m : models::procedural_gallery()) {
    const ProcedureSpec& spec = registry.spec(m.name);
    std::printf("%s (procedural%s)\n  %s\n", m.name.c_str(), spec.cacheable ? ", cacheable" : "", m.description.c_str());
    for (std::size_t i = 0; i < spec.params.size(); ++i) {
      const ParamValue& d = *spec.params[i].default_value;
      std::string shown;
      switch (d.type()) {
        case ParamType::Double: {
          char text[32];
          std::snprintf(text, sizeof text, "%g", d.as_double());
          shown = text;
          break;
        }
        case ParamType::Integer: shown = std::to_string(d.as_integer()); break;
        case ParamType::Boolean: shown = d.as_bool() ? "true" : "false"; break;
        case ParamType::String: shown = d.as_string(); break;
        case ParamType::Vector: shown = "vector"; break;
      }
      std::printf("    %-16s %-8s %-7s %s\n", spec.params[i].name.c_str(), shown.c_str(),
                  std::string(java_type_name(d.type())).c_str(), m.parameter_docs[i].second.c_str());
    }
  }
  return 0;
}

}  // namespace

const Command kListCommand{"list", "", "list the gallery models with their parameters and defaults", "", run_list};

}  // namespace genmod::app
