// Process CPU time for the driver benchmarks (the machine is shared: CPU, not wall, and the
// median of repeats).
#pragma once

#include <algorithm>
#include <ctime>
#include <vector>

namespace genmod::bench {

// CPU seconds of the whole process (all threads) since it started.
inline double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The median CPU seconds of `repeats` runs of run().
template <class F>
double median_cpu(int repeats, F&& run) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const double t0 = cpu_seconds();
    run();
    t.push_back(cpu_seconds() - t0);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace genmod::bench
