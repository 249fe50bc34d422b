// The summary of a genmod_bench run: a console reporter that also keeps the results, and the
// table of the figures, with ratios computed against the baselines of the same run.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace genmod::bench {

class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  // Plain tabular output: colour codes would end up in logs and CI output.
  SummaryReporter() : ConsoleReporter(OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override;

  // The table; a figure whose benchmark was filtered out or failed shows as "-".
  void print_table(std::FILE* out) const;

 private:
  const Run* find(const std::string& name) const;
  double counter(const std::string& name, const std::string& counter_name) const;  // NaN if absent
  double seconds(const std::string& name) const;                                   // per iteration; NaN if absent
  double cpu_seconds(const std::string& name) const;                               // process CPU per iteration

  // By benchmark name without the time-type suffix ("BM_RenderProspero/threads:2"); with
  // repetitions, the fastest run, the least disturbed by other load on the machine.
  std::map<std::string, Run> best_;
};

}  // namespace genmod::bench
