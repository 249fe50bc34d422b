// Jobs files (batch_jobs.hpp): a job description as an engine job that builds and meshes it.
#include "genmod/kernel/vm_format.hpp"
#include "genmod/models/batch_jobs.hpp"
#include "genmod/models/implicit_gallery.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"

#include <stdexcept>
#include <string>

namespace genmod::models {
namespace {

BatchMesh mesh_implicit_job(const Fn& f, const Box3& box, double default_min_feature, const JobDescription& job) {
  ImplicitMeshSettings s;
  s.min_feature = job.min_feature.value_or(default_min_feature);
  s.tolerance = job.tolerance.value_or(0.0);
  s.max_cell = job.max_cell.value_or(0.0);
  s.max_seconds = job.max_seconds.value_or(0.0);
  if (job.max_cells) s.max_cells = *job.max_cells;
  // threads = 0: the mesher uses the cores the batch engine allows (its global cap).
  ImplicitMesh m = mesh_implicit(f, box, s);
  BatchMesh out{std::move(m.mesh), m.stats.max_vertex_error, std::move(m.stats.limits_hit), {}};
  if (m.stats.uncertified_cells)
    out.note = std::to_string(m.stats.uncertified_cells) + " surface cells with uncertified topology";
  if (m.stats.uncertified_vertices) {
    if (!out.note.empty()) out.note += "; ";
    out.note += std::to_string(m.stats.uncertified_vertices) + " vertices without a certified distance bound";
  }
  return out;
}

Box3 box_of(const std::array<double, 6>& b) {
  return {Interval(b[0], b[3]), Interval(b[1], b[4]), Interval(b[2], b[5])};
}

BatchMesh run_description(const JobDescription& job) {
  switch (job.kind) {
    case JobModelKind::Parametric: {
      const Model& model = find_model(job.model);
      return mesh_gallery_job(model, build_model(model, job.parameters), job);
    }
    case JobModelKind::Implicit: {
      const ImplicitModel* model = find_implicit_model(job.model);
      if (!model) throw std::invalid_argument("genmod: unknown implicit model '" + job.model + "'");
      const Fn f = build_implicit_model(*model, job.parameters);
      return mesh_implicit_job(f, job.box ? box_of(*job.box) : model->box, model->min_feature, job);
    }
    case JobModelKind::ModelFile: {
      if (!job.parameters.empty()) throw std::invalid_argument("genmod: a .vm model takes no parameters");
      if (!job.min_feature) throw std::invalid_argument("genmod: a .vm model needs min_feature");
      const Fn f = load_vm(job.model);
      const Box3 unit{Interval(-1, 1), Interval(-1, 1), Interval(-1, 1)};
      return mesh_implicit_job(f, job.box ? box_of(*job.box) : unit, 0.0, job);
    }
  }
  throw std::logic_error("genmod: job of an unknown kind");
}

}  // namespace

BatchMesh mesh_gallery_job(const Model& model, const Fn& surface, const JobDescription& job) {
  if (job.res && job.tolerance)
    throw std::invalid_argument("genmod: res= (uniform lattice) and tolerance= (adaptive) exclude each other");
  if (job.res) return {mesh_model(model, surface, static_cast<std::size_t>(*job.res)), std::nullopt, {}, {}};
  const ParameterValues params = resolve_parameters(model, job.parameters);
  // As `genmod mesh`: adaptive, by default within 0.001 of the model's size.
  AdaptiveMeshOptions options;
  options.tolerance = job.tolerance.value_or(0.0) > 0.0 ? *job.tolerance : 1e-3 * model_extent(model, surface, params);
  options.max_seconds = job.max_seconds.value_or(0.0);
  AdaptiveMesh m = mesh_model_adaptive(model, surface, params, options);
  const bool closed = m.closed();  // before the mesh moves out
  BatchMesh out{std::move(m.mesh), m.distance_bound, std::move(m.limits_hit), {}};
  if (!closed) out.note = std::to_string(m.boundary_edges) + " boundary edges (open surface)";
  return out;
}

BatchJob make_batch_job(const JobDescription& job, const std::filesystem::path& output_dir) {
  const std::filesystem::path output(job.output);
  return {job_name(job), output.is_absolute() ? output : output_dir / output, [job] { return run_description(job); }};
}

std::vector<BatchJob> make_batch_jobs(const std::vector<JobDescription>& jobs, const std::filesystem::path& output_dir) {
  std::vector<BatchJob> out;
  out.reserve(jobs.size());
  for (const JobDescription& job : jobs) out.push_back(make_batch_job(job, output_dir));
  return out;
}

}  // namespace genmod::models
