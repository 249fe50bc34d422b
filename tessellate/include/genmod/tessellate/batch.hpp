// Batch tessellation: many meshing jobs in one process, on all cores (oneTBB).
//
// A job is a name, an output mesh file and a callable that produces the mesh (plus what its
// mesher reports: an error bound, the limits it hit). run_batch runs the jobs in parallel,
// writes each mesh with write_mesh, optionally validates the file as written (read back, no
// welding), and returns one result row per job, in job order.
//
// Example:
//   Fn ball = implicit_sphere(1.0);
//   std::filesystem::path out = std::filesystem::temp_directory_path() / "ball.obj";
//   std::vector<BatchJob> jobs;
//   jobs.push_back({"ball", out, [&] {
//     BatchMesh m;
//     m.mesh = mesh_implicit(ball, {Interval(-2, 2), Interval(-2, 2), Interval(-2, 2)},
//                            {.min_feature = 0.25}).mesh;
//     return m;
//   }});
//   std::vector<BatchResult> rows = run_batch(jobs, {.threads = 2});
//   std::cout << batch_report_csv(rows);
//
// Failures stay inside their row: an exception thrown by a job's callable, by the writer (a
// failed write is an error, the partial file is removed) or by validation sets the row's
// status to Error with the exception's message; the other jobs run on.
//
// Determinism: each job writes only its own file and the rows come back in job order, so the
// files and the rows (except the seconds) are bitwise the same for every thread count,
// provided each job's callable is deterministic (genmod's meshers are, for any thread count).
// Two jobs with the same output path would race for the file: run_batch refuses them.
//
// Threads: `threads` caps the whole run (tbb::global_control for its duration, and the jobs
// run in a tbb::task_arena of that many slots), so meshers that are parallel themselves
// (mesh_implicit, validate) share the same cores instead of oversubscribing the machine.
// global_control is process-wide: while a run with threads > 0 lasts, other TBB work in the
// process is capped too. threads = 0 sets no cap.
#pragma once

#include "genmod/tessellate/mesh.hpp"

#include <cstddef>
#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace genmod {

// What a job's callable returns: the mesh and what its mesher reports about it.
struct BatchMesh {
  Mesh mesh;
  // The mesher's certified distance bound to the true surface, when it gives one.
  std::optional<double> error_bound;
  // Resource limits the mesher reached (the mesh is coarser than asked), e.g. "cells".
  std::vector<std::string> limits_hit;
  // Extra facts for the row's message (e.g. "12 uncertified cells"); empty for none.
  std::string note;
};

struct BatchJob {
  std::string name;
  std::filesystem::path output;  // the format follows the extension (mesh_io.hpp)
  std::function<BatchMesh()> make;
};

enum class BatchStatus { Ok, Error };

// "ok" / "error".
const char* to_string(BatchStatus status) noexcept;

struct BatchResult {
  std::string name;
  std::filesystem::path output;
  BatchStatus status = BatchStatus::Error;
  std::size_t triangles = 0, vertices = 0;  // of the mesh produced (also when its write failed)
  double seconds = 0.0;                     // wall time of meshing and writing (not validation)
  std::optional<double> error_bound;
  std::vector<std::string> limits_hit;
  // validate() of the file as written: nothing when not checked (BatchOptions::validate off,
  // or the job failed before the file was written).
  std::optional<bool> valid;
  // The error for a failed job; otherwise the mesher's note and, for a mesh that is not
  // valid, why (e.g. "not valid: 12 boundary edges"); empty when there is nothing to say.
  std::string message;
};

struct BatchOptions {
  int threads = 0;        // 0 = all cores; std::invalid_argument when negative
  bool validate = true;   // validate each file as written (CGAL; costs about as much as meshing)
  // Called after each job with (jobs done, total), never concurrently (under a lock), from
  // whichever thread finished the job; keep it short. Also called once with (0, total).
  std::function<void(std::size_t done, std::size_t total)> progress = nullptr;
  // The caller's stop request (not owned; null = none): once it is true, jobs not yet started
  // are not run (their rows are errors saying "cancelled before it ran"); running jobs finish.
  const std::atomic<bool>* cancel = nullptr;
};

// Runs every job; the rows are in job order. std::invalid_argument (before any job runs) for
// a negative thread count, a job without a callable, or two jobs with the same output path
// (compared after lexical normalization).
std::vector<BatchResult> run_batch(const std::vector<BatchJob>& jobs, const BatchOptions& options = {});

// The rows as CSV (RFC 4180 quoting: a field with a comma, a quote, a line break or leading or
// trailing spaces is quoted, its quotes doubled; lines end in "\n"), a header line first.
// Columns: name, output,
// status, triangles, vertices, seconds, error_bound (empty when none), limits_hit (joined
// with ';'), valid (yes / no / empty when not checked), message.
std::string batch_report_csv(const std::vector<BatchResult>& rows);

}  // namespace genmod
