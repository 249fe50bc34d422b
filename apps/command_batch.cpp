// genmod batch JOBS -o DIR: every job of a jobs file (models/batch_jobs.hpp) meshed on all
// cores by the batch engine (tessellate/batch.hpp), one mesh per job in DIR and a CSV report.
#include "arguments.hpp"
#include "commands.hpp"
#include "option_values.hpp"
#include "progress_bar.hpp"

#include "genmod/models/batch_jobs.hpp"
#include "genmod/tessellate/batch.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace genmod::app {
namespace {

// The output directory, created when missing (UsageError when that fails or it is a file).
void make_output_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec)) {
    if (!std::filesystem::is_directory(dir, ec)) throw UsageError("-o " + dir.string() + ": not a directory");
    return;
  }
  std::filesystem::create_directories(dir, ec);
  if (ec) throw UsageError("-o " + dir.string() + ": cannot create the directory (" + ec.message() + ")");
}

void write_report(const std::string& path, const std::string& csv) {
  std::ofstream out(path, std::ios::binary);
  out << csv;
  out.close();
  if (!out) throw std::runtime_error("genmod: cannot write the report '" + path + "'");
}

int run_batch_command(std::span<const std::string> args) {
  static constexpr std::array<const char*, 1> kFlags{"--no-check"};
  static constexpr std::array<const char*, 4> kValued{"-o", "--output", "--threads", "--report"};
  const Arguments a(args, kFlags, kValued);
  if (a.positional().size() != 1)
    throw UsageError(a.positional().empty() ? "missing jobs file"
                                            : "expected one jobs file, got " + std::to_string(a.positional().size()));
  const std::string& jobs_file = a.positional()[0];
  const std::optional<std::string> dir = a.value({"-o", "--output"});
  if (!dir) throw UsageError("missing output directory (-o DIR)");
  const int threads = a.int_value({"--threads"}, 0, 0, 1024);
  std::error_code ec;
  // Not only regular files: a pipe (<(generate_jobs)) is a fine jobs file.
  if (!std::filesystem::exists(jobs_file, ec)) throw UsageError("jobs file '" + jobs_file + "' does not exist");
  if (std::filesystem::is_directory(jobs_file, ec)) throw UsageError("jobs file '" + jobs_file + "' is a directory");

  // A malformed jobs file stops everything before any work (the message names the line).
  const std::vector<models::JobDescription> descriptions = models::read_jobs_file(jobs_file);
  make_output_directory(*dir);
  const std::string report = a.value({"--report"}).value_or((std::filesystem::path(*dir) / "report.csv").string());
  check_writable(report);

  std::vector<BatchResult> rows;
  {
    ProgressBar bar("batch: " + std::to_string(descriptions.size()) + " jobs");
    BatchOptions options;
    options.threads = threads;
    options.validate = !a.has("--no-check");
    options.progress = [&bar](std::size_t done, std::size_t total) {
      bar.update(total ? static_cast<double>(done) / static_cast<double>(total) : 1.0);
    };
    rows = run_batch(models::make_batch_jobs(descriptions, *dir), options);
  }
  write_report(report, batch_report_csv(rows));

  std::size_t failed = 0, invalid = 0;
  for (const BatchResult& r : rows) {
    failed += r.status == BatchStatus::Error;
    invalid += r.valid && !*r.valid;
    // An invalid mesh's message says "not valid: why".
    std::printf("%-5s %s -> %s: %zu triangles, %.3f s%s%s%s\n", to_string(r.status), r.name.c_str(),
                r.output.string().c_str(), r.triangles, r.seconds, r.valid && *r.valid ? ", valid" : "",
                r.message.empty() ? "" : ": ", r.message.c_str());
  }
  std::printf("%zu jobs: %zu ok, %zu failed, %zu not valid; report %s\n", rows.size(), rows.size() - failed, failed,
              invalid, report.c_str());
  return failed ? 1 : 0;
}

}  // namespace

const Command kBatchCommand{
    "batch", "JOBS -o DIR [--threads N] [--report FILE.csv] [--no-check]",
    "mesh every job of a jobs file in parallel, one mesh per job in DIR, and write a CSV report",
    "  -o, --output DIR  directory of the meshes (created if missing); relative out= names are in it\n"
    "  --threads N       worker threads for the whole run (default: all cores)\n"
    "  --report FILE     the CSV report (default DIR/report.csv): name, output, status, triangles,\n"
    "                    vertices, seconds, error_bound, limits_hit, valid, message\n"
    "  --no-check        do not validate the meshes as written (the valid column stays empty)\n"
    "jobs file: one job per line, '#' starts a comment:\n"
    "  MODEL [KEY=VALUE ...] out=FILE\n"
    "  MODEL: a gallery model, an implicit gallery model (`genmod list`) or a .vm file\n"
    "  keys: model parameters; res=N (gallery models, default 64); box=x0,y0,z0,x1,y1,z1,\n"
    "  min_feature=H (required for .vm files), tolerance=E, max_cell=C, max_cells=N,\n"
    "  max_seconds=S (implicit models). A value LO:HI:COUNT is a sweep of COUNT jobs; out= must\n"
    "  then contain {KEY}, replaced by each job's value. Quote values with spaces: out=\"a b.obj\"\n"
    "  e.g.  torus res=32 major_radius=1:2:5 out=torus_{major_radius}.ply\n"
    "exit status 1 when any job failed (all jobs run); a mesh that is not valid is reported, not a failure\n",
    run_batch_command};

}  // namespace genmod::app
