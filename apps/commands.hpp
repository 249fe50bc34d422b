// The subcommands of the genmod program and how they report problems.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace genmod::app {

// A problem with the command line (exit code 2); other exceptions are failures (exit code 1).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Command {
  std::string_view name;
  std::string_view usage;    // arguments after the command name
  std::string_view summary;  // one line for `genmod --help`
  std::string_view details;  // option descriptions for `genmod COMMAND --help`
  // Runs the command on the arguments after its name; returns the exit code.
  int (*run)(std::span<const std::string> args);
};

extern const Command kRenderCommand;
extern const Command kInfoCommand;
extern const Command kListCommand;
extern const Command kMeshCommand;
extern const Command kPreviewCommand;
extern const Command kCheckCommand;
extern const Command kBatchCommand;

// genmod mesh MODEL.vm ...: the implicit path of the mesh command.
int run_mesh_implicit(std::span<const std::string> args);
// genmod mesh NAME ...: the procedural path of the mesh command (procedural_models.hpp).
int run_mesh_procedural(std::span<const std::string> args);
// genmod mesh NAME ...: the CSG models of trimmed surfaces (trimmed_csg.hpp).
int run_mesh_csg(std::span<const std::string> args);
// genmod mesh NAME ...: the region models, non-manifold meshes (region_gallery.hpp).
int run_mesh_regions(std::span<const std::string> args);
// genmod render MODEL --3d ...: the shaded 3-D path of the render command.
int run_render_shaded(std::span<const std::string> args);

}  // namespace genmod::app
