// genmod mesh NAME [--param k=v ...] [--res N] -o FILE: a gallery model as a triangle mesh.
#include "arguments.hpp"
#include "commands.hpp"
#include "mesh_memory.hpp"
#include "option_values.hpp"

#include "genmod/models/gallery.hpp"
#include "genmod/models/implicit_gallery.hpp"
#include "genmod/models/procedural_models.hpp"
#include "genmod/models/region_gallery.hpp"
#include "genmod/models/trimmed_csg.hpp"
#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/validate.hpp"

#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace genmod::app {
namespace {

int run_mesh(std::span<const std::string> args) {
  for (const std::string& arg : args)
    if ((arg.size() > 3 && arg.compare(arg.size() - 3, 3, ".vm") == 0) || models::find_implicit_model(arg))
      return run_mesh_implicit(args);
  for (const std::string& arg : args)
    if (models::find_procedural_model(arg)) return run_mesh_procedural(args);
  for (const std::string& arg : args)
    if (models::is_csg_model(arg)) return run_mesh_csg(args);
  for (const std::string& arg : args)
    if (models::find_region_model(arg)) return run_mesh_regions(args);
  std::vector<std::string> rest;
  const models::ParameterValues overrides = take_param_options(args, rest);
  static constexpr std::array<const char*, 1> kFlags{"--no-check"};
  static constexpr std::array<const char*, 8> kValued{"--res", "-o", "--output", "--tolerance", "--max-leaves",
                                                      "--threads", "--max-memory", "--max-seconds"};
  const Arguments a(rest, kFlags, kValued);
  if (a.positional().size() != 1)
    throw UsageError(a.positional().empty() ? "missing model name" : "expected one model name, got " +
                                                                          std::to_string(a.positional().size()));
  const std::optional<std::string> output = a.value({"-o", "--output"});
  if (!output) throw UsageError("missing output file (-o FILE)");
  if (a.has("--res") && a.has("--tolerance"))
    throw UsageError("--res (uniform lattice) and --tolerance (adaptive) exclude each other");
  if (!mesh_format(*output))
    throw UsageError("output '" + *output + "': unknown mesh extension (use .obj, .ply, .stl or .off)");
  const double limit_mb = positive_option(a, {"--max-memory"}, static_cast<double>(default_mesh_memory_limit() >> 20), false);
  check_writable(*output);

  const models::Model* model = nullptr;
  Fn surface;
  std::size_t patches = 1;
  models::ParameterValues params;
  try {
    model = &models::find_model(a.positional()[0]);
    params = models::resolve_parameters(*model, overrides);
    surface = model->build(params);
    if (!model->solid) patches = models::model_patches(*model, surface, params).size();
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());  // unknown model, unknown or out-of-range parameter
  }
  if (a.has("--res")) {
    const int res = a.int_value({"--res"}, 64, 3, 4096);
    // Refuse before allocating: the estimate against the limit, both printed.
  const double estimate_mb =
      static_cast<double>(lattice_mesh_bytes(*model, patches, static_cast<std::size_t>(res))) / (1 << 20);
  if (estimate_mb > limit_mb) {
    char text[256];
    std::snprintf(text, sizeof text, "%s at --res %d needs about %.0f MB (%zu patch%s), above the limit of %.0f MB "
                  "(--max-memory MB; default half the physical memory or of ulimit -v)",
                  model->name.c_str(), res, estimate_mb, model->solid ? std::size_t{6} : patches,
                  (model->solid || patches > 1) ? "es" : "", limit_mb);
    throw UsageError(text);
  }
  const Mesh mesh = models::mesh_model(*model, surface, static_cast<std::size_t>(res));
  write_mesh(mesh, *output);
  std::printf("%s: %zu vertices, %zu triangles (uniform %d x %d lattice) -> %s\n", model->name.c_str(),
              mesh.vertices.size(), mesh.triangles.size(), res, res, output->c_str());
  return 0;
  }
  AdaptiveMeshOptions options;
  options.tolerance = positive_option(a, {"--tolerance"}, 0.0, true);
  if (options.tolerance == 0.0) options.tolerance = 1e-3 * models::model_extent(*model, surface, params);
  options.max_leaves = static_cast<std::size_t>(a.int_value({"--max-leaves"}, 4'000'000, 1, 1'000'000'000));
  // The memory limit as a leaf limit (about kAdaptiveBytesPerLeaf per leaf, measured).
  options.max_leaves = std::min(options.max_leaves, static_cast<std::size_t>(limit_mb * (1 << 20) / kAdaptiveBytesPerLeaf));
  options.threads = a.int_value({"--threads"}, 0, 0, 1024);
  options.max_seconds = positive_option(a, {"--max-seconds"}, 120.0, true);
  const auto start = std::chrono::steady_clock::now();
  const AdaptiveMesh m = models::mesh_model_adaptive(*model, surface, params, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_mesh(m.mesh, *output);
  std::printf("%s: %zu vertices, %zu triangles from %zu leaves in %.3f s -> %s\n", model->name.c_str(),
              m.mesh.vertices.size(), m.mesh.triangles.size(), m.leaves, seconds, output->c_str());
  std::printf("distance to the surface <= %.3g (tolerance %.3g); %zu edges glued, %zu collapsed to a point, %s\n",
              m.distance_bound, options.tolerance, m.glued_edges, m.collapsed_edges,
              m.closed() ? "closed" : (std::to_string(m.boundary_edges) + " boundary edges (open)").c_str());
  if (m.unbounded_leaves)
    std::printf("%zu leaves have no finite distance bound (the surface's interval enclosure is unbounded there)\n",
                m.unbounded_leaves);
  for (const std::string& limit : m.limits_hit) std::printf("limit reached: %s\n", limit.c_str());
  if (a.has("--no-check")) return 0;
  // The file as written is what users get: check that, not the mesh in memory.
  const MeshValidity v = validate(read_mesh(*output), {.threads = options.threads});
  std::printf("%s", describe(v).c_str());
  const bool sound = v.manifold() && v.oriented() && v.degenerate_triangles == 0 && v.self_intersections == 0;
  return (model->open ? sound : v.valid()) ? 0 : 1;
}

}  // namespace

const Command kMeshCommand{
    "mesh", "NAME [--param NAME=VALUE ...] [--tolerance E | --res N] [--max-memory MB] -o FILE | MODEL.vm --min-feature H [options] -o FILE",
    "mesh a gallery, procedural (see `genmod list`) or implicit .vm model to an OBJ/PLY/STL/OFF file",
    "  -p, --param K=V  set a model parameter (once per parameter; defaults from `genmod list`)\n"
    "  --tolerance E    largest distance between mesh and surface (adaptive kd-tree mesher, the default;\n"
    "                 default 0.001 of the model's size); the certified bound is printed\n"
    "  --max-leaves N   kd-tree leaf limit (default 4000000; reported when reached)\n"
    "  --max-seconds S  stop refining after S seconds (default 120, 0 = none; reported when reached)\n"
    "  --res N          a uniform N x N lattice instead, 3..4096 (faces not welded)\n"
    "  --max-memory MB  refuse a lattice whose estimated memory is above MB, or stop refining the adaptive\n"
    "                 mesh there (default half the physical memory)\n"
    "  -o, --output     mesh file to write; the format follows the extension (.obj .ply .stl .off)\n"
    "procedural models (see `genmod list`; the procedure's polygons, triangulated as built):\n"
    "  -p, --param K=V  a procedure parameter: a number, an integer or true/false as declared\n"
    "  --seed S         the random seed of the call (default 0)\n"
    "  --lod L          level of detail, a refinement offset (default 0 = as the parameters say; below 0\n"
    "                 coarser: the tree has levels + L levels, the human subdivisions + L, the chair's and couch's\n"
    "                 cushions 2 + L sqrt(2) rounds (at least 1), the round table subdivisions + L, the luggage's legs\n"
    "                 legSubdivisions + L; the others ignore it)\n"
    "  --camera EX,EY,EZ,TX,TY,TZ  a camera at the eye looking at the target (+z up, 640 x 480) chooses the\n"
    "                 lod from the model's bounding box on screen (-8 for a pixel .. 0 from 256 x 256 pixels);\n"
    "                 a model out of view or without bounds is an error (not with --lod)\n"
    "  --no-check       skip the validity report (exit status 1 when the mesh is not valid)\n"
    "implicit models (MODEL.vm or an implicit gallery name; the mesh bounds the solid f < 0 in the box):\n"
    "  --box x0,y0,z0,x1,y1,z1  region to mesh (default: the model's box, or -1,-1,-1,1,1,1)\n"
    "  --min-feature H  smallest cell edge (required for .vm files)\n"
    "  --tolerance E    largest vertex distance from the surface (default H)\n"
    "  --max-cell C     largest cell holding surface (default box / 8)\n"
    "  --max-cells N, --max-memory MB, --max-seconds S  limits (reported when reached; memory counts\n"
    "                 the octree and its pruned tapes, default 8192 MB)\n"
    "  --threads N      worker threads (default: all cores)\n"
    "  --no-sharp       no feature points (smooth placement only)\n"
    "  --no-check       skip the validity report (exit status 1 when the mesh is not valid)\n"
    "  --continuation H Bloomenthal's continuation polygonizer with cubes of edge H instead: only the\n"
    "                 piece of surface reached from --start x,y,z (default: a seed searched in the box),\n"
    "                 cubes outside the box not visited, --max-cells N cubes at most; --cubes uses the\n"
    "                 cube table instead of six tetrahedra per cube\n",
    run_mesh};

}  // namespace genmod::app
