// Global minimization of standard test functions with known global minima and minimizers.
#include "genmod/solvers/minimizer.hpp"
#include "solvers/minimizer_problems.hpp"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

namespace genmod {

namespace minimizer_problems {
// Test names and failure messages show the problem's name (not its bytes, which hold
// addresses and would make the ctest names differ from run to run).
void PrintTo(const Problem& problem, std::ostream* os) { *os << problem.name; }
}  // namespace minimizer_problems

namespace {

bool covered(const MinimizeResult& r, std::span<const double> p, double tol) {
  for (const Box& b : r.candidates) {
    bool in = true;
    for (std::size_t i = 0; i < p.size(); ++i) in = in && b[i].lo() - tol <= p[i] && p[i] <= b[i].hi() + tol;
    if (in) return true;
  }
  return false;
}

class StandardFunction : public ::testing::TestWithParam<minimizer_problems::Problem> {};

TEST_P(StandardFunction, BracketsTheMinimumAndCoversTheMinimizers) {
  const minimizer_problems::Problem& p = GetParam();
  MinimizeOptions opt;
  opt.epsilon = p.epsilon;
  opt.delta = p.delta;
  const MinimizeResult r = minimize(p.objective, Fn(1.0), p.unknowns, p.box, opt);
  ASSERT_EQ(r.report.limit, LimitHit::None) << p.name << " hit " << limit_name(r.report.limit);
  // The bracket holds f* (known to `known_tolerance`) and is narrower than delta.
  EXPECT_LE(r.minimum.lo(), p.f_star + p.known_tolerance) << p.name << " " << r.minimum;
  EXPECT_GE(r.minimum.hi(), p.f_star - p.known_tolerance) << p.name << " " << r.minimum;
  EXPECT_LE(r.minimum.hi() - r.minimum.lo(), opt.delta) << p.name;
  EXPECT_TRUE(r.delta_reached);
  ASSERT_TRUE(r.feasible_found);
  // Every known minimizer lies in a candidate box (to the precision it is known).
  for (const std::vector<double>& m : p.minimizers) EXPECT_TRUE(covered(r, m, p.minimizer_tolerance)) << p.name;
  // The best point is within the bracket's reach of a known minimizer.
  double best = 1e300;
  for (const std::vector<double>& m : p.minimizers) {
    double d = 0.0;
    for (std::size_t i = 0; i < m.size(); ++i) d = std::max(d, std::abs(m[i] - r.best_point[i]));
    best = std::min(best, d);
  }
  EXPECT_LT(best, p.best_point_tolerance) << p.name;
}

INSTANTIATE_TEST_SUITE_P(Minimizer, StandardFunction, ::testing::ValuesIn(minimizer_problems::standard_problems()),
                         [](const ::testing::TestParamInfo<minimizer_problems::Problem>& param) {
                           return param.param.name;
                         });

}  // namespace
}  // namespace genmod
