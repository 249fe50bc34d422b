// genmod mesh MODEL.vm ...: an implicit model (solid where f < 0) meshed by mesh_implicit, or
// with --continuation H by Bloomenthal's continuation polygonizer (the classic baseline).
#include "arguments.hpp"
#include "commands.hpp"
#include "model_file.hpp"
#include "option_values.hpp"
#include "progress_bar.hpp"

#include "genmod/models/implicit_gallery.hpp"
#include "genmod/tessellate/continuation_polygonizer.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "genmod/tessellate/mesh.hpp"
#include "genmod/tessellate/validate.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace genmod::app {

namespace {

// "x,y,z": three finite numbers.
std::array<double, 3> parse_point(const std::string& option, const std::string& text) {
  std::vector<double> v;
  for (std::size_t begin = 0; begin <= text.size();) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    v.push_back(parse_number(option, text.substr(begin, end - begin)));
    begin = end + 1;
  }
  if (v.size() != 3) throw UsageError(option + " expects x,y,z (3 numbers), got '" + text + "'");
  return {v[0], v[1], v[2]};
}

// The --continuation path: the piece of surface reached from the start point (or from a seed
// found in the box), cubes of edge H, cubes whose centre is outside the box not visited.
int run_continuation(const Arguments& a, const std::string& path, const Fn& f, const Box3& box,
                     const std::string& output) {
  ContinuationSettings s;
  s.cube_size = positive_option(a, {"--continuation"}, 0.0, false);
  if (const auto start = a.value({"--start"})) s.starts.push_back(parse_point("--start", *start));
  s.bounds = box;
  s.decomposition = a.has("--cubes") ? CellDecomposition::cubes : CellDecomposition::tetrahedra;
  s.max_cubes = static_cast<std::size_t>(positive_option(a, {"--max-cells"}, static_cast<double>(s.max_cubes), false));
  const auto t0 = std::chrono::steady_clock::now();
  ContinuationMesh result;
  try {
    result = polygonize_continuation(f, s);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_mesh(result.mesh, output);
  const ContinuationStats& st = result.stats;
  std::printf("%s: %zu vertices, %zu triangles in %.3f s -> %s\n", path.c_str(), result.mesh.vertices.size(),
              result.mesh.triangles.size(), seconds, output.c_str());
  std::printf("continuation (%s): %zu cubes, %zu evaluations of f (%zu corners, %zu bisections, %zu normals, %zu search); "
              "vertex error <= %.3g\n",
              s.decomposition == CellDecomposition::cubes ? "cube table" : "tetrahedra", st.cubes, st.evaluations(),
              st.corner_evaluations, st.bisection_evaluations, st.normal_evaluations, st.search_evaluations,
              0.5 * st.max_bracket);
  for (const std::string& limit : st.limits_hit) std::printf("limit reached: %s\n", limit.c_str());
  if (a.has("--no-check")) return 0;
  const MeshValidity v = validate(read_mesh(output));
  std::printf("%s", describe(v).c_str());
  return v.valid() ? 0 : 1;
}

}  // namespace

int run_mesh_implicit(std::span<const std::string> args) {
  std::vector<std::string> rest;
  const models::ParameterValues overrides = take_param_options(args, rest);
  static constexpr std::array<const char*, 3> kFlags{"--no-sharp", "--no-check", "--cubes"};
  static constexpr std::array<const char*, 12> kValued{"--box",       "--min-feature", "--tolerance",  "--max-cell",
                                                       "--max-seconds", "--threads",   "-o",           "--output",
                                                       "--max-cells",   "--max-memory", "--continuation", "--start"};
  const Arguments a(rest, kFlags, kValued);
  if (a.positional().size() != 1)
    throw UsageError("expected one model, got " + std::to_string(a.positional().size()) + " arguments");
  const std::string& path = a.positional()[0];
  const models::ImplicitModel* model = models::find_implicit_model(path);
  const std::optional<std::string> output = a.value({"-o", "--output"});
  if (!output) throw UsageError("missing output file (-o FILE)");
  const bool continuation = a.value({"--continuation"}).has_value();
  if (!continuation && (a.value({"--start"}) || a.has("--cubes")))
    throw UsageError("--start and --cubes belong to --continuation H");
  if (!model && !continuation && !a.value({"--min-feature"}))
    throw UsageError("missing --min-feature H (the smallest cell edge)");
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
  if (continuation) return run_continuation(a, path, f, box, *output);
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
