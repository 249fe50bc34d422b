// Jobs files: lists of meshing jobs for `genmod batch` and the batch engine (tessellate/batch.hpp).
//
// One job per line; everything after a '#' (outside quotes) is a comment; blank lines are
// skipped. A line is a model followed by KEY=VALUE settings, separated by spaces or tabs:
//
//   # gallery (parametric) models: adaptive meshes within a tolerance, or lattices (res=)
//   doorknob tolerance=0.001 bulge_radius=0.9 out=knob.obj
//   torus res=32 major_radius=1:2:5 out=torus_{major_radius}.ply
//   # implicit gallery models and .vm files: mesh_implicit in a box
//   tanglecube min_feature=0.1 out=tangle_gallery.off
//   data/tanglecube.vm box=-2,-2,-2,2,2,2 min_feature=0.05 out=tangle.stl
//
// MODEL (first on the line) is a gallery model (models::gallery(), `genmod list`), an
// implicit gallery model (models::implicit_gallery()) or, when it ends in ".vm", a model file
// (read when the job runs, relative to the current directory).
//
// Keys (each at most once per line):
//   out=PATH        required. The mesh file (.obj .ply .stl .off), relative to the output
//                   directory unless absolute. {KEY} is replaced by the job's value of KEY
//                   (any numeric key on the line, printed as the shortest decimal that reads
//                   back to the same double, e.g. {major_radius} -> 1.25, {res} -> 32).
//                   Braces are for placeholders only (a lone '{' or '}' is an error).
//   tolerance=E     gallery models: the adaptive mesher's distance bound, >= 0 (absent or 0:
//                   0.001 of the model's size); implicit models: the vertex tolerance.
//   res=N           gallery models: a uniform lattice instead, samples per direction, an
//                   integer in 3..4096 (not with tolerance=).
//   box=x0,y0,z0,x1,y1,z1   implicit models: the region (default: the gallery model's box,
//                   or -1,-1,-1,1,1,1 for a .vm file); x0 < x1, y0 < y1, z0 < z1.
//   min_feature=H   implicit models: smallest cell edge, > 0 (required for a .vm file;
//                   default: the gallery model's).
//   max_cell=C      implicit models: >= 0 (0 = the mesher's default).
//   max_seconds=S   the mesher's time limit, >= 0 (0 = none); reported when reached.
//   max_cells=N     implicit models: an integer >= 1, the octree cell limit.
//   any other key   a parameter of the gallery model (`genmod list` shows them); .vm files
//                   take none. Values out of a parameter's range fail the job when it runs.
// Values are decimal numbers (finite; "1", "-0.5", "2e-3"), or for out= and the model a
// path. A value or the model may be written in double quotes ("my dir/a b.obj", with \" and
// \\ inside) to hold spaces, '#', '=' or quotes.
//
// Sweeps: a numeric value written LO:HI:COUNT (COUNT an integer >= 2) stands for COUNT
// values LO + i (HI - LO) / (COUNT - 1), i = 0 .. COUNT - 1, those between LO and HI rounded
// to 15 significant digits (0.1:0.7:4 -> 0.1, 0.3, 0.5, 0.7, not 0.30000000000000004), e.g.
// major_radius=1:2:5 -> 1, 1.25, 1.5, 1.75, 2. A line with sweeps expands to one job per
// combination, the first swept key varying slowest. Every swept key must appear as {KEY}
// in out=, so the output names differ (res sweeps must give integers).
//
// Errors (JobsFileError) name the file, the line and the problem: unknown model, unknown
// parameter or key, a key repeated on a line, a bad number or sweep, a missing out=, an
// output name without a mesh extension or with an unknown placeholder, an output name used
// by two jobs (compared after substitution and lexical normalization), too many jobs.
//
// A JobDescription is plain data (one expanded job); to_line() prints it back as one line
// that parse_job() reads to an equal description, so it can be sent to another process.
// make_batch_job() turns it into an engine job that builds the model and meshes it.
#pragma once

#include "genmod/models/gallery.hpp"
#include "genmod/tessellate/batch.hpp"

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace genmod::models {

// A malformed jobs file or line; the message names the source, the line and the problem.
class JobsFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class JobModelKind {
  Parametric,  // models::gallery()
  Implicit,    // models::implicit_gallery()
  ModelFile,   // a .vm file
};

// One job, every sweep expanded and every placeholder substituted. Unset settings take the
// defaults listed above when the job runs.
struct JobDescription {
  std::string model;
  JobModelKind kind = JobModelKind::Parametric;
  ParameterValues parameters;  // overrides of the model's defaults
  std::optional<int> res;
  std::optional<std::array<double, 6>> box;
  std::optional<double> min_feature, tolerance, max_cell, max_seconds;
  std::optional<std::size_t> max_cells;
  std::string output;  // as written (after substitution); relative = to the output directory

  bool operator==(const JobDescription&) const = default;
};

struct JobsFileLimits {
  std::size_t max_jobs = 100'000;  // jobs in one file, after sweeps are expanded
};

// Parses a jobs file's text; `source_name` names it in errors.
std::vector<JobDescription> parse_jobs(std::string_view text, const std::string& source_name,
                                       const JobsFileLimits& limits = {});
// Reads and parses a jobs file (JobsFileError naming the path when it cannot be read).
std::vector<JobDescription> read_jobs_file(const std::filesystem::path& path, const JobsFileLimits& limits = {});
// One line that must describe exactly one job (no sweeps): the inverse of to_line.
JobDescription parse_job(std::string_view line);

// The job as one line of the jobs-file syntax (no sweeps, no placeholders, no comment):
// model, parameters (by name), res, box, min_feature, tolerance, max_cell, max_cells,
// max_seconds, out; numbers in the shortest form that reads back to the same double.
std::string to_line(const JobDescription& job);
// A short name for reports: to_line without the out= setting.
std::string job_name(const JobDescription& job);

// The engine job: builds the model (a bad parameter value, a missing .vm file, ... fail the
// job, not the batch) and meshes it; a relative output is put under `output_dir`.
BatchJob make_batch_job(const JobDescription& job, const std::filesystem::path& output_dir);
std::vector<BatchJob> make_batch_jobs(const std::vector<JobDescription>& jobs, const std::filesystem::path& output_dir);

// How a gallery (parametric) job is meshed: the one place that picks the parametric mesher.
BatchMesh mesh_gallery_job(const Model& model, const Fn& surface, const JobDescription& job);

}  // namespace genmod::models
