#include "summary_table.hpp"

#include "prospero.hpp"

#include <cmath>
#include <limits>

namespace genmod::bench {
namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

std::string key(const benchmark::BenchmarkReporter::Run& run) {
  const auto& n = run.run_name;
  return n.args.empty() ? n.function_name : n.function_name + "/" + n.args;
}

// One line: label, value to three significant digits followed by `unit` (or "-" when
// missing), target.
void row(std::FILE* out, const char* label, double value, const char* unit, const char* target = "") {
  char text[64] = "-";
  if (!std::isnan(value)) std::snprintf(text, sizeof text, "%.3g%s", value, unit);
  std::fprintf(out, "%-46s %-28s %s\n", label, text, target);
}

}  // namespace

void SummaryReporter::ReportRuns(const std::vector<Run>& runs) {
  ConsoleReporter::ReportRuns(runs);
  for (const Run& run : runs) {
    if (run.run_type != Run::RT_Iteration || run.error_occurred) continue;
    const auto [it, inserted] = best_.try_emplace(key(run), run);
    if (!inserted && run.real_accumulated_time / static_cast<double>(run.iterations) <
                         it->second.real_accumulated_time / static_cast<double>(it->second.iterations))
      it->second = run;
  }
}

const benchmark::BenchmarkReporter::Run* SummaryReporter::find(const std::string& name) const {
  const auto it = best_.find(name);
  return it == best_.end() ? nullptr : &it->second;
}

double SummaryReporter::counter(const std::string& name, const std::string& counter_name) const {
  const Run* run = find(name);
  if (!run) return kMissing;
  const auto it = run->counters.find(counter_name);
  return it == run->counters.end() ? kMissing : it->second.value;
}

double SummaryReporter::seconds(const std::string& name) const {
  const Run* run = find(name);
  return run ? run->real_accumulated_time / static_cast<double>(run->iterations) : kMissing;
}

double SummaryReporter::cpu_seconds(const std::string& name) const {
  const Run* run = find(name);
  return run ? run->cpu_accumulated_time / static_cast<double>(run->iterations) : kMissing;
}

void SummaryReporter::print_table(std::FILE* out) const {
  const double batch = counter("BM_BatchProspero", "clause_evals/s");
  const double genmod = counter("BM_IntervalGenmod", "time/clause") * 1e9;
  const double pair = counter("BM_IntervalPairBaseline", "time/clause") * 1e9;
  const double boost = counter("BM_IntervalBoostProtected", "time/clause") * 1e9;
  const double prune = counter("BM_SimplifyGenmod", "time/clause") * 1e9;
  const double render1 = seconds("BM_RenderProspero/threads:1") * 1e3;
  const double render2 = seconds("BM_RenderProspero/threads:2") * 1e3;

  std::fprintf(out, "\ngenmod benchmark summary (Prospero tape: %zu clauses; ratios from this run)\n",
               prospero_tape().size());
  std::fprintf(out, "%-46s %-28s %s\n", "figure", "measured", "target");
  row(out, "batch point evaluation, 1 core", batch, " clause evals/s", ">= 1e9");
  row(out, "interval evaluation: genmod", genmod, " ns/clause");
  row(out, "interval evaluation: pair of doubles baseline", pair, " ns/clause");
  row(out, "interval evaluation: Boost, protected per op", boost, " ns/clause");
  row(out, "  ratio genmod / pair of doubles", genmod / pair, "x", "<= 1.5x");
  row(out, "  ratio Boost protected / genmod", boost / genmod, "x", "about 10x");
  row(out, "tape pruning (simplify), same tape and boxes", prune, " ns/clause");
  row(out, "  ratio pruning / interval evaluation", prune / genmod, "x", "a small fraction");
  row(out, "render 1024x1024, 1 thread", render1, " ms");
  row(out, "render 1024x1024, 2 threads", render2, " ms", "< 50 ms");
  row(out, "  speed-up, wall time 1 thread / 2 threads", render1 / render2, "x", ">= 1.8x");
  // Process CPU time: above 1 when the threads do extra work (contention), whatever else
  // runs on the machine; a low speed-up at a ratio near 1 means the cores were not free.
  row(out, "  CPU time 2 threads / 1 thread", cpu_seconds("BM_RenderProspero/threads:2") /
      cpu_seconds("BM_RenderProspero/threads:1"), "x", "about 1x");
  row(out, "  tape left in the deepest interval tiles", counter("BM_RenderProspero/threads:2", "deepest_tile_tape") * 100,
      "% of the clauses");
  row(out, "  tape left for per-pixel evaluation", counter("BM_RenderProspero/threads:2", "pixel_tape") * 100,
      "% of the clauses");
}

}  // namespace genmod::bench
