// Tables: multilinear interpolation values, the shared properties on 1-3 dimensional
// tables (boxes crossing cell edges), derivative tables, and bad input.
#include "genmod/operators/table.hpp"
#include "operators/operator_properties.hpp"

#include <gtest/gtest.h>

#include <random>

namespace genmod {
namespace {

using testing::check_operator_properties;
using testing::unit_domain;

TEST(Table, InterpolatesMultilinearly) {
  // f = 1 + 2u + 3v + uv sampled on a 3 x 2 grid, 2 outputs (f, -f); multilinear is exact.
  std::vector<double> s;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const double uu = i / 2.0, vv = j;
      const double f = 1 + 2 * uu + 3 * vv + uu * vv;
      s.push_back(f);
      s.push_back(-f);
    }
  const Fn t = table(s, std::vector<int>{2, 3, 2}, cat({x(0), x(1)}));
  ASSERT_EQ(t.dim(), 2u);
  for (double uu : {0.0, 0.3, 0.5, 0.9, 1.0})
    for (double vv : {0.0, 0.25, 1.0}) {
      const auto y = evaluate(t, std::vector<double>{uu, vv});
      EXPECT_NEAR(y[0], 1 + 2 * uu + 3 * vv + uu * vv, 1e-14);
      EXPECT_NEAR(y[1], -y[0], 0.0);
      EXPECT_NEAR(evaluate(derivative(t, 1), std::vector<double>{uu, vv})[0], 3 + uu, 1e-13);
    }
  EXPECT_TRUE(std::isnan(evaluate(t, std::vector<double>{1.5, 0.5})[0]));
}

std::vector<double> random_samples(std::mt19937_64& rng, std::size_t n) {
  std::uniform_real_distribution<double> c(-3, 3);
  std::vector<double> s(n);
  for (auto& v : s) v = c(rng);
  return s;
}

std::vector<double> grid(int n) {
  std::vector<double> g;
  for (int i = 0; i < n; ++i) g.push_back(static_cast<double>(i) / (n - 1));
  return g;
}

TEST(Table, Properties) {
  std::mt19937_64 rng(41);
  // 1D, 2D and 3D tables; derivatives are checked away from the cell edges.
  const std::vector<std::vector<int>> dimens = {{1, 7}, {2, 4, 5}, {1, 3, 4, 3}};
  for (const auto& dimen : dimens) {
    std::size_t count = static_cast<std::size_t>(dimen[0]);
    for (std::size_t k = 1; k < dimen.size(); ++k) count *= static_cast<std::size_t>(dimen[k]);
    std::vector<Fn> in;
    for (std::size_t k = 1; k < dimen.size(); ++k) in.push_back(x(static_cast<int>(k - 1)));
    const Fn t = table(random_samples(rng, count), dimen, cat(in));
    auto spec = unit_domain(dimen.size() - 1);
    for (std::size_t k = 1; k < dimen.size(); ++k) spec.breaks.push_back(grid(dimen[k]));
    check_operator_properties(t, spec, 42);
    // Second derivatives (tables of cell differences) as well.
    check_operator_properties(derivative(t, 0), spec, 43);
  }
}

TEST(Table, InclusionIsTheExactRangeOnACell) {
  // On one cell a multilinear function's range is spanned by the corners of the box.
  const std::vector<double> s = {0, 1, 2, -1};  // 2 x 2 grid: f = u + 2v - 4uv
  const Fn t = table(s, std::vector<int>{1, 2, 2}, cat({x(0), x(1)}));
  IntervalEvaluator iv;
  const Interval y = iv.eval(Tape(t), {Interval(0.25, 0.5), Interval(0.5, 1.0)})[0];
  // corners: (0.25,0.5)=0.75 (0.5,0.5)=0.5 (0.25,1)=1.25 (0.5,1)=0.5
  EXPECT_NEAR(y.lo(), 0.5, 1e-13);
  EXPECT_NEAR(y.hi(), 1.25, 1e-13);
}

TEST(Table, BadInputIsReported) {
  const std::vector<double> s = {0, 1, 2, 3};
  const Fn in = cat({x(0), x(1)});
  EXPECT_THROW(table(s, std::vector<int>{1, 2, 3}, in), std::invalid_argument);  // count
  EXPECT_THROW(table(s, std::vector<int>{1, 4, 1}, in), std::invalid_argument);  // n_k < 2
  EXPECT_THROW(table(s, std::vector<int>{1, 4}, in), std::invalid_argument);     // in dimension
  EXPECT_THROW(table(s, std::vector<int>{4}, x(0)), std::invalid_argument);
  const std::vector<double> bad = {0, 1, std::nan(""), 3};
  EXPECT_THROW(table(bad, std::vector<int>{1, 4}, x(0)), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
