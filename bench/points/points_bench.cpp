// The C++ side of the Python overhead benchmark (bench/python/numpy_overhead.py): a model
// evaluated at N random points of its box by the batch evaluator, from structure-of-arrays
// inputs in one call, as a C++ user would. Prints the median CPU seconds per pass.
//
// Usage: genmod_points_bench MODEL.vm N REPEATS
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/kernel/vm_format.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <exception>
#include <random>
#include <string>
#include <vector>

namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) try {
  using namespace genmod;
  if (argc != 4) {
    std::fprintf(stderr, "usage: genmod_points_bench MODEL.vm N REPEATS\n");
    return 2;
  }
  const Fn f = load_vm(argv[1]);
  const std::size_t n = std::stoul(argv[2]);
  const int repeats = std::stoi(argv[3]);
  const Tape tape(f, std::vector<int>{0, 1, 2});
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> coord(-2.5, 2.5);
  std::vector<double> xs(n), ys(n), zs(n), out(n);
  for (std::size_t i = 0; i < n; ++i) xs[i] = coord(rng), ys[i] = coord(rng), zs[i] = coord(rng);
  const double* in[] = {xs.data(), ys.data(), zs.data()};
  double* o[] = {out.data()};
  BatchEvaluator ev;
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    const double start = cpu_seconds();
    ev.eval(tape, in, n, o);
    seconds.push_back(cpu_seconds() - start);
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("%.9f\n", seconds[seconds.size() / 2]);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "genmod_points_bench: %s\n", e.what());
  return 1;
}
