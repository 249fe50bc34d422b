// Kd-tree operations at mesher sizes: neighbours of every leaf (the flooding of Alg 5.4
// step 7), merge_addonly of a uniform sampling tree into a partial tree (step 6), and the
// projection of a 4-D tree onto two dimensions (step 2). Counter: leaves of the input.
#include "genmod/tessellate/kd_tree.hpp"

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace {

using namespace genmod;

// The uniform tree of 2^levels leaves over [0,1]^dims, splitting the dimensions in turn.
KdTree uniform_tree(std::size_t dims, int levels) {
  KdTree t = KdTree::full(KdBox(dims, Interval(0.0, 1.0)));
  for (int level = 0; level < levels; ++level)
    for (KdTree::Index leaf : t.leaves()) t.split(leaf, static_cast<std::size_t>(level) % dims);
  return t;
}

void BM_KdNeighboursOfAllLeaves(benchmark::State& state) {
  const KdTree t = uniform_tree(2, static_cast<int>(state.range(0)));
  const auto leaves = t.leaves();
  std::size_t total = 0;
  for (auto _ : state) {
    total = 0;
    for (KdTree::Index leaf : leaves) total += t.neighbours(leaf).size();
    benchmark::DoNotOptimize(total);
  }
  state.counters["leaves"] = static_cast<double>(leaves.size());
  state.counters["neighbours"] = static_cast<double>(total);
}
BENCHMARK(BM_KdNeighboursOfAllLeaves)->Arg(10)->Arg(14)->Unit(benchmark::kMillisecond);

void BM_KdMergeAddOnly(benchmark::State& state) {
  const KdTree sampling = uniform_tree(2, static_cast<int>(state.range(0)));
  // A partial tree: the diagonal cells of a finer grid, as an intersection curve gives.
  KdTree partial(KdBox(2, Interval(0.0, 1.0)));
  const int bits = static_cast<int>(state.range(0)) / 2 + 2;
  for (std::uint64_t k = 0; k < (std::uint64_t{1} << bits); ++k) {
    std::string b;
    for (int i = bits - 1; i >= 0; --i) b += static_cast<char>('0' + ((k >> i) & 1u));
    partial.insert_addonly(KdAddress::parse({b, b}));
  }
  for (auto _ : state) {
    KdTree t = partial;
    merge_addonly(t, sampling);
    benchmark::DoNotOptimize(t.num_nodes());
  }
  state.counters["leaves"] = static_cast<double>(sampling.leaves().size());
}
BENCHMARK(BM_KdMergeAddOnly)->Arg(10)->Arg(14)->Unit(benchmark::kMillisecond);

void BM_KdProject4To2(benchmark::State& state) {
  const KdTree t = uniform_tree(4, static_cast<int>(state.range(0)));
  const std::size_t keep[] = {0, 1};
  for (auto _ : state) {
    KdTree p = project(t, keep);
    benchmark::DoNotOptimize(p.num_nodes());
  }
  state.counters["leaves"] = static_cast<double>(t.leaves().size());
}
BENCHMARK(BM_KdProject4To2)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace
