// run_batch and batch_report_csv (batch.hpp).
#include "genmod/tessellate/batch.hpp"

#include "genmod/tessellate/mesh_io.hpp"
#include "genmod/tessellate/validate.hpp"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <charconv>
#include <chrono>
#include <exception>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>

namespace genmod {
namespace {

// The first reason a mesh is not valid, in the order a user would fix them.
std::string invalid_reason(const MeshValidity& v) {
  auto count = [](std::size_t n, const char* what) { return std::to_string(n) + " " + what; };
  if (v.triangles == 0) return "no triangles";
  if (v.invalid_indices) return count(v.invalid_indices, "invalid vertex indices");
  if (!v.closed()) return count(v.boundary_edges, "boundary edges");
  if (!v.manifold())
    return count(v.nonmanifold_edges, "non-manifold edges") + ", " +
           count(v.nonmanifold_vertices, "non-manifold vertices");
  if (!v.oriented()) return count(v.misoriented_edges, "misoriented edges");
  if (v.degenerate_triangles) return count(v.degenerate_triangles, "degenerate triangles");
  if (v.self_intersections) return count(v.self_intersections, "self-intersecting triangle pairs");
  if (!v.orientation_checked) return "orientation not determined";
  if (!v.outward) return "oriented inward";
  return "self-intersections not checked";
}

void append_message(std::string& message, const std::string& text) {
  if (text.empty()) return;
  if (!message.empty()) message += "; ";
  message += text;
}

// One job, start to finish; every failure ends up in the row.
BatchResult run_job(const BatchJob& job, const BatchOptions& options) {
  BatchResult row;
  row.name = job.name;
  row.output = job.output;
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  bool written = false;
  try {
    BatchMesh made = job.make();
    row.triangles = made.mesh.triangles.size();
    row.vertices = made.mesh.vertices.size();
    row.error_bound = made.error_bound;
    row.limits_hit = std::move(made.limits_hit);
    row.message = std::move(made.note);
    write_mesh(made.mesh, job.output);
    written = true;
    row.seconds = elapsed();
    if (options.validate) {
      // The file is what users get: validate it as read back, not the mesh in memory.
      const MeshValidity v = validate(read_mesh(job.output), {.threads = options.threads});
      row.valid = v.valid();
      if (!v.valid()) append_message(row.message, "not valid: " + invalid_reason(v));
    }
    row.status = BatchStatus::Ok;
  } catch (const std::exception& e) {
    if (!written) row.seconds = elapsed();
    row.status = BatchStatus::Error;
    row.message = e.what();
  } catch (...) {
    if (!written) row.seconds = elapsed();
    row.status = BatchStatus::Error;
    row.message = "unknown exception (not derived from std::exception)";
  }
  return row;
}

void check_jobs(const std::vector<BatchJob>& jobs, const BatchOptions& options) {
  if (options.threads < 0)
    throw std::invalid_argument("genmod: run_batch: threads must be >= 0 (0 = all cores), got " +
                                std::to_string(options.threads));
  std::set<std::filesystem::path> outputs;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const BatchJob& job = jobs[i];
    if (!job.make)
      throw std::invalid_argument("genmod: run_batch: job " + std::to_string(i) + " ('" + job.name +
                                  "') has no callable");
    if (!outputs.insert(job.output.lexically_normal()).second)
      throw std::invalid_argument("genmod: run_batch: job " + std::to_string(i) + " ('" + job.name +
                                  "') writes '" + job.output.string() + "', the output of an earlier job");
  }
}

std::string csv_field(const std::string& text) {
  const bool needs_quotes = text.find_first_of(",\"\r\n") != std::string::npos ||
                            (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!needs_quotes) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

std::string shortest(double v) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

}  // namespace

const char* to_string(BatchStatus status) noexcept { return status == BatchStatus::Ok ? "ok" : "error"; }

std::vector<BatchResult> run_batch(const std::vector<BatchJob>& jobs, const BatchOptions& options) {
  check_jobs(jobs, options);
  std::vector<BatchResult> rows(jobs.size());
  std::mutex progress_lock;
  std::size_t done = 0;
  if (options.progress) options.progress(0, jobs.size());

  // The cap holds for nested arenas too (the meshers' own), so `threads` bounds the run.
  std::unique_ptr<tbb::global_control> cap;
  if (options.threads > 0)
    cap = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                static_cast<std::size_t>(options.threads));
  tbb::task_arena arena(options.threads == 0 ? tbb::task_arena::automatic : options.threads);
  arena.execute([&] {
    // One job per task: jobs differ in cost by orders of magnitude, so no chunking.
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, jobs.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t i = range.begin(); i != range.end(); ++i) {
            if (options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed)) {
              rows[i].name = jobs[i].name;
              rows[i].output = jobs[i].output;
              rows[i].message = "cancelled before it ran";
            } else {
              rows[i] = run_job(jobs[i], options);
            }
            if (options.progress) {
              const std::lock_guard<std::mutex> hold(progress_lock);
              options.progress(++done, jobs.size());
            }
          }
        },
        tbb::simple_partitioner());
  });
  return rows;
}

std::string batch_report_csv(const std::vector<BatchResult>& rows) {
  std::string out = "name,output,status,triangles,vertices,seconds,error_bound,limits_hit,valid,message\n";
  for (const BatchResult& r : rows) {
    std::string limits;
    for (const std::string& limit : r.limits_hit) {
      if (!limits.empty()) limits += ';';
      limits += limit;
    }
    out += csv_field(r.name) + ',' + csv_field(r.output.string()) + ',' + to_string(r.status) + ',' +
           std::to_string(r.triangles) + ',' + std::to_string(r.vertices) + ',' + shortest(r.seconds) + ',' +
           (r.error_bound ? shortest(*r.error_bound) : std::string()) + ',' + csv_field(limits) + ',' +
           (r.valid ? (*r.valid ? "yes" : "no") : "") + ',' + csv_field(r.message) + '\n';
  }
  return out;
}

}  // namespace genmod
