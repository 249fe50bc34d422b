// validate() and describe() (validate.hpp): the checks in order, and the report.
#include "validate_internal.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>

namespace genmod {

MeshValidity validate(const Mesh& mesh, const ValidateOptions& options) {
  if (options.face_samples < 0 || options.face_samples > 64)
    throw std::invalid_argument("genmod: validate: face_samples must be in [0, 64], got " +
                                std::to_string(options.face_samples));
  if (options.surface && (options.surface->num_outputs() != 1 || options.surface->num_inputs() != 3))
    throw std::invalid_argument("genmod: validate: the surface tape must be scalar with inputs (x, y, z), got " +
                                std::to_string(options.surface->num_outputs()) + " outputs and " +
                                std::to_string(options.surface->num_inputs()) + " inputs");
  if (!(options.search_radius >= 0.0) || !std::isfinite(options.search_radius))
    throw std::invalid_argument("genmod: validate: search_radius must be finite and >= 0");
  MeshValidity v;
  v.vertices = mesh.vertices.size();
  v.triangles = mesh.triangles.size();
  const std::vector<std::uint32_t> proper = validation::proper_triangles(mesh, v);
  validation::check_topology(mesh, proper, v);
  const std::vector<std::uint32_t> good = validation::check_degenerate(mesh, proper, v);
  if (options.check_self_intersections) {
    v.self_intersections = validation::count_self_intersections(mesh, good, options.threads);
    v.self_intersections_checked = true;
  }
  if (v.closed() && v.manifold() && v.oriented() && v.degenerate_triangles == 0 && v.self_intersections_checked &&
      v.self_intersections == 0 && v.triangles > 0)
    validation::check_outward(mesh, v);
  if (options.surface) {
    double radius = options.search_radius;
    if (radius == 0.0 && !mesh.vertices.empty()) {
      std::array<double, 3> lo = mesh.vertices[0], hi = mesh.vertices[0];
      for (const auto& p : mesh.vertices)
        for (int d = 0; d < 3; ++d) {
          lo[d] = std::min(lo[d], p[d]);
          hi[d] = std::max(hi[d], p[d]);
        }
      radius = 0.05 * std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                (hi[2] - lo[2]) * (hi[2] - lo[2]));
    }
    v.surface = validation::measure_surface_distance(mesh, *options.surface, options.face_samples, radius,
                                                     options.threads);
    v.has_surface_distance = true;
  }
  return v;
}

namespace {

__attribute__((format(printf, 2, 3))) void line(std::string& out, const char* format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  out += buffer;
  out += '\n';
}

const char* yes_no(bool b) { return b ? "yes" : "no"; }

}  // namespace

std::string describe(const MeshValidity& v) {
  std::string out;
  line(out, "vertices %zu, triangles %zu, edges %zu, components %zu, Euler characteristic %ld", v.vertices,
       v.triangles, v.edges, v.components, v.euler_characteristic);
  line(out, "closed: %s (%zu boundary edges%s)", yes_no(v.closed()), v.boundary_edges,
       v.invalid_indices ? ", invalid vertex indices" : "");
  line(out, "manifold: %s (%zu non-manifold edges, %zu non-manifold vertices)", yes_no(v.manifold()),
       v.nonmanifold_edges, v.nonmanifold_vertices);
  line(out, "consistently oriented: %s (%zu edges used twice in one direction)", yes_no(v.oriented()),
       v.misoriented_edges);
  if (v.orientation_checked) line(out, "outward: %s", yes_no(v.outward));
  else line(out, "outward: not determined (needs a closed, manifold, oriented, intersection-free mesh)");
  line(out, "degenerate triangles: %zu", v.degenerate_triangles);
  if (v.self_intersections_checked) line(out, "self-intersecting triangle pairs: %zu", v.self_intersections);
  else line(out, "self-intersections: not checked");
  if (v.unused_vertices || v.coincident_vertices)
    line(out, "unused vertices: %zu, vertices coinciding with another: %zu", v.unused_vertices,
         v.coincident_vertices);
  if (v.closed()) line(out, "volume: %.10g", v.volume);
  if (v.has_surface_distance) {
    line(out, "distance to the surface (%zu points): vertices <= %.3g (estimate %.3g), faces <= %.3g (estimate max %.3g, mean %.3g)%s",
         v.surface.points, v.surface.max_vertex_bound, v.surface.max_vertex_estimate, v.surface.max_face_bound,
         v.surface.max_face_estimate, v.surface.mean_face_estimate, v.surface.uncertified ? "" : ", all certified");
    if (v.surface.uncertified)
      line(out, "  points without a certified bound: %zu (%zu vertices)", v.surface.uncertified,
           v.surface.uncertified_vertices);
  }
  line(out, "valid: %s", yes_no(v.valid()));
  return out;
}

}  // namespace genmod
