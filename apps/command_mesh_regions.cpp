// genmod mesh NAME [--param K=V] [--cube-size H] [--no-check] -o FILE: a region model
// (region_gallery.hpp), whose surface is non-manifold by design (Bloomenthal's maple leaf:
// a blade sheet meeting its veins). The check reports what a user of such a mesh needs:
// no degenerate triangles and no self-intersections; edges shared by more than two
// triangles and open borders are the model's, reported, not errors.
#include "arguments.hpp"
#include "commands.hpp"
#include "file_arguments.hpp"
#include "option_values.hpp"

#include "genmod/models/region_gallery.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/validate.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace genmod::app {

int run_mesh_regions(std::span<const std::string> args) {
  std::vector<std::string> rest;
  const std::map<std::string, double> overrides = take_param_options(args, rest);
  static constexpr std::array<const char*, 1> kFlags{"--no-check"};
  static constexpr std::array<const char*, 3> kValued{"-o", "--output", "--cube-size"};
  const Arguments a(rest, kFlags, kValued);
  if (a.positional().size() != 1)
    throw UsageError("expected one model name, got " + std::to_string(a.positional().size()));
  const std::string& name = a.positional()[0];
  const std::string output = mesh_output_argument(a);
  const double cube_size = positive_option(a, {"--cube-size"}, 0.0, true);
  check_writable(output);
  const auto t0 = std::chrono::steady_clock::now();
  models::RegionModelMesh m;
  try {
    m = models::mesh_region_model(name, overrides, cube_size);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_mesh(m.result.mesh, output);
  // Triangles per pair of regions: the sheets of the model.
  std::map<std::pair<int, int>, std::size_t> sheets;
  for (const auto& pair : m.result.regions) ++sheets[pair];
  std::printf("%s (regions): %zu vertices, %zu triangles in %.3f s -> %s\n", name.c_str(),
              m.result.mesh.vertices.size(), m.result.mesh.triangles.size(), seconds, output.c_str());
  for (const auto& [pair, count] : sheets)
    std::printf("  %zu triangles between %s and %s (normals toward %s)\n", count,
                m.region_names.at(static_cast<std::size_t>(pair.first)).c_str(),
                m.region_names.at(static_cast<std::size_t>(pair.second)).c_str(),
                m.region_names.at(static_cast<std::size_t>(pair.second)).c_str());
  for (const std::string& limit : m.result.stats.limits_hit) std::printf("limit reached: %s\n", limit.c_str());
  if (a.has("--no-check")) return m.result.stats.limits_hit.empty() ? 0 : 1;
  const MeshValidity v = validate(read_mesh(output));
  std::printf("non-manifold edges: %zu (where sheets meet, by design); boundary edges: %zu (open borders)\n",
              v.nonmanifold_edges, v.boundary_edges);
  std::printf("degenerate triangles: %zu\nself-intersecting triangle pairs: %zu\n", v.degenerate_triangles,
              v.self_intersections);
  const bool clean = v.degenerate_triangles == 0 && v.self_intersections == 0 && v.invalid_indices == 0 &&
                     m.result.stats.limits_hit.empty();
  std::printf("clean: %s\n", clean ? "yes" : "no");
  return clean ? 0 : 1;
}

}  // namespace genmod::app
