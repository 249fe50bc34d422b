// Several threads building shapes in the shared DAG store and evaluating them at once.
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "kernel/random_functions.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace genmod {
namespace {

TEST(Concurrency, ThreadsBuildAndEvaluateTheSameShapes) {
  constexpr int kThreads = 4, kShapes = 150;
  // Each thread builds the same sequence of random functions (same seed), keeps them, and
  // records the node ids and values; hash-consing must give every thread identical ids (while
  // the functions live: a reclaimed id may be reused).
  std::vector<std::vector<NodeId>> ids(kThreads);
  std::vector<std::vector<double>> values(kThreads);
  std::vector<std::vector<double>> lows(kThreads);
  std::vector<std::vector<Fn>> kept(kThreads);  // alive until every thread is done
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([t, &ids, &values, &lows, &kept] {
      testing::RandomFunctions rnd(77);
      PointEvaluator pv;
      IntervalEvaluator iv;
      const std::vector<int> xyz = {0, 1, 2};
      for (int s = 0; s < kShapes; ++s) {
        const Fn f = rnd.function(6) + derivative(rnd.function(4), 1);
        kept[t].push_back(f);
        ids[t].push_back(f.node(0));
        const Tape tape(f, xyz);
        values[t].push_back(pv.eval(tape, {0.25, -0.5, 1.5})[0]);
        lows[t].push_back(iv.eval(tape, std::vector<Interval>{Interval(0, 1), Interval(-1, 0), Interval(1, 2)})[0].lo());
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 1; t < kThreads; ++t) {
    EXPECT_EQ(ids[t], ids[0]);
    for (int s = 0; s < kShapes; ++s) {
      EXPECT_TRUE(values[t][s] == values[0][s] || (std::isnan(values[t][s]) && std::isnan(values[0][s])));
      EXPECT_TRUE(lows[t][s] == lows[0][s] || (std::isnan(lows[t][s]) && std::isnan(lows[0][s])));
    }
  }
}

TEST(Concurrency, OneTapeSharedByManyEvaluators) {
  const Fn f = sqrt(square(x(0)) + square(x(1))) - 0.5;
  const Tape tape(f);
  std::vector<std::thread> threads;
  std::vector<int> mismatches(4, 0);
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      BatchEvaluator batch;
      PointEvaluator pv;
      std::vector<double> xs(1000), ys(1000), out(1000);
      for (int i = 0; i < 1000; ++i) {
        xs[i] = -1 + 0.002 * i + 0.0001 * t;
        ys[i] = 0.5 - 0.001 * i;
      }
      const double* in[2] = {xs.data(), ys.data()};
      double* o[1] = {out.data()};
      batch.eval(tape, in, 1000, o);
      for (int i = 0; i < 1000; ++i) mismatches[t] += out[i] != pv.eval(tape, {xs[i], ys[i]})[0];
    });
  }
  for (auto& th : threads) th.join();
  for (int m : mismatches) EXPECT_EQ(m, 0);
}

}  // namespace
}  // namespace genmod
