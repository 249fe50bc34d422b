// genmod mesh MODEL.vm ...: an implicit model (solid where f < 0) meshed by mesh_implicit.
#include "arguments.hpp"
#include "commands.hpp"
#include "model_file.hpp"
#include "option_values.hpp"
#include "progress_bar.hpp"

#include "genmod/models/implicit_gallery.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/mesh.hpp"
#include "genmod/tessellate/validate.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace genmod::app {

int run_mesh_implicit(std::span<const std::string> args) {
  // --param may repeat: take every occurrence out before the generic scanner sees the rest.
  models::ParameterValues overrides;
  std::vector<std::string> rest;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--param" || args[i] == "-p") {
      if (i + 1 >= args.size()) throw UsageError("option " + args[i] + " needs a value");
      const std::string& text = args[++i];
      const std::size_t eq = text.find('=');
      if (eq == std::string::npos || eq == 0) throw UsageError("--param expects NAME=VALUE, got '" + text + "'");
      const std::string name = text.substr(0, eq);
      if (overrides.count(name)) throw UsageError("--param " + name + " is given twice");
      overrides[name] = parse_number("--param " + name, text.substr(eq + 1));
    } else {
      rest.push_back(args[i]);
    }
  }
  static constexpr std::array<const char*, 2> kFlags{"--no-sharp", "--no-check"};
  static constexpr std::array<const char*, 10> kValued{"--box",       "--min-feature", "--tolerance",  "--max-cell",
                                                       "--max-seconds", "--threads",   "-o",           "--output",
                                                       "--max-cells",   "--max-memory"};
  const Arguments a(rest, kFlags, kValued);
  if (a.positional().size() != 1)
    throw UsageError("expected one model, got " + std::to_string(a.positional().size()) + " arguments");
  const std::string& path = a.positional()[0];
  const models::ImplicitModel* model = models::find_implicit_model(path);
  const std::optional<std::string> output = a.value({"-o", "--output"});
  if (!output) throw UsageError("missing output file (-o FILE)");
  if (!model && !a.value({"--min-feature"})) throw UsageError("missing --min-feature H (the smallest cell edge)");
  ImplicitMeshSettings s;
  s.min_feature = positive_option(a, {"--min-feature"}, model ? model->min_feature : 0.0, false);
  s.tolerance = positive_option(a, {"--tolerance"}, 0, true);
  s.max_cell = positive_option(a, {"--max-cell"}, 0, true);
  s.max_seconds = positive_option(a, {"--max-seconds"}, 0, true);
  s.max_cells = static_cast<std::size_t>(positive_option(a, {"--max-cells"}, static_cast<double>(s.max_cells), false));
  s.max_memory = static_cast<std::size_t>(
      positive_option(a, {"--max-memory"}, static_cast<double>(s.max_memory >> 20), false) * (1 << 20));
  s.threads = a.int_value({"--threads"}, 0, 0, 1024);
  s.sharp_features = !a.has("--no-sharp");
  const std::optional<std::string> box_text = a.value({"--box"});
  const Box3 box = box_text ? parse_box(*box_text)
                 : model  ? model->box
                          : Box3{Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)};
  check_writable(*output);

  const Fn f = load_implicit_model(path, overrides);
  const auto start = std::chrono::steady_clock::now();
  ImplicitMesh result;
  try {
    ProgressBar bar("meshing " + path);
    s.progress = [&bar](double fraction) { bar.update(fraction); };
    const ImplicitSurface surface(f);
    result = mesh_implicit(surface, box, s);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_mesh(result.mesh, *output);
  const ImplicitMeshStats& st = result.stats;
  std::printf("%s: %zu vertices, %zu triangles in %.3f s -> %s\n", path.c_str(), result.mesh.vertices.size(),
              result.mesh.triangles.size(), seconds, output->c_str());
  std::printf("cells: %zu surface (%zu certified, %zu uncertified at min_feature, %zu without gradient bounds), "
              "%zu with several loops, %zu above tolerance; %d rounds; vertex error <= %.3g (%zu vertices uncertified)\n",
              st.surface_cells, st.certified_cells, st.uncertified_cells, st.unbounded_gradient_cells,
              st.multi_loop_cells, st.inaccurate_cells, st.rounds, st.max_vertex_error, st.uncertified_vertices);
  for (const std::string& limit : st.limits_hit) std::printf("limit reached: %s\n", limit.c_str());
  if (a.has("--no-check")) return 0;
  // The file as written is what users get: check that, not the mesh in memory.
  const MeshValidity v = validate(read_mesh(*output), {.threads = s.threads});
  std::printf("%s", describe(v).c_str());
  return v.valid() ? 0 : 1;
}

}  // namespace genmod::app
