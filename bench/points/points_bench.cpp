// The C++ side of the Python overhead benchmark (bench/python/numpy_overhead.py): a model
// evaluated at N random points of its box by the batch evaluator in one call, as a C++ user
// would, from three separate coordinate arrays and from one row-major (N, 3) array read with
// strides. Prints the median CPU seconds per pass of each, on one line.
//
// Usage: genmod_points_bench MODEL.vm N REPEATS
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/kernel/vm_format.hpp"
#include "../cpu_time.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <exception>
#include <random>
#include <string>
#include <vector>

int main(int argc, char** argv) try {
  using namespace genmod;
  using bench::cpu_seconds;
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
  std::vector<double> xs(n), ys(n), zs(n), rows(3 * n), out(n);
  for (std::size_t i = 0; i < n; ++i) {
    xs[i] = rows[3 * i] = coord(rng);
    ys[i] = rows[3 * i + 1] = coord(rng);
    zs[i] = rows[3 * i + 2] = coord(rng);
  }
  const double* columns[] = {xs.data(), ys.data(), zs.data()};
  const double* row_major[] = {rows.data(), rows.data() + 1, rows.data() + 2};
  double* o[] = {out.data()};
  BatchEvaluator ev;
  std::vector<double> by_columns, by_rows;
  for (int r = 0; r < repeats; ++r) {
    double start = cpu_seconds();
    ev.eval(tape, columns, n, o);
    by_columns.push_back(cpu_seconds() - start);
    start = cpu_seconds();
    ev.eval(tape, row_major, n, o, 3, 1);
    by_rows.push_back(cpu_seconds() - start);
  }
  const auto median = [](std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  std::printf("%.9f %.9f\n", median(by_columns), median(by_rows));
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "genmod_points_bench: %s\n", e.what());
  return 1;
}
