// Lattice evaluation: equal to point evaluation bit for bit, and claim 12's operation counts.
#include "genmod/tessellate/lattice.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "kernel/random_functions.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdint>

namespace genmod {
namespace {

// Bitwise equality; NaN (the error value) matches any NaN.
bool same_bits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Checks both lattice methods against the point evaluator at every lattice point.
void expect_lattice_equals_points(const Fn& f, const Lattice& lat) {
  const std::vector<double> plain = evaluate_lattice(f, lat, LatticeMethod::Plain);
  const std::vector<double> tables = evaluate_lattice(f, lat, LatticeMethod::Tables);
  const Tape tape(f);
  PointEvaluator ev;
  const std::size_t m = f.dim();
  ASSERT_EQ(plain.size(), lat.num_points() * m);
  ASSERT_EQ(tables.size(), lat.num_points() * m);
  for (std::size_t p = 0; p < lat.num_points(); ++p) {
    const std::vector<double> x = lat.point(p);
    std::vector<double> in;
    for (int c : tape.inputs()) in.push_back(x[static_cast<std::size_t>(c)]);
    const auto y = ev.eval(tape, in);
    for (std::size_t j = 0; j < m; ++j) {
      ASSERT_TRUE(same_bits(plain[p * m + j], y[j])) << "plain, point " << p << " component " << j;
      ASSERT_TRUE(same_bits(tables[p * m + j], y[j]))
          << "tables, point " << p << " component " << j << ": " << tables[p * m + j] << " vs " << y[j];
    }
  }
}

TEST(Lattice, CoordinateFormula) {
  const LatticeAxis a{0, -1.0, 2.0, 7};
  for (std::size_t k = 0; k < 7; ++k)
    EXPECT_TRUE(same_bits(lattice_coordinate(a, k), -1.0 + (static_cast<double>(k) * 3.0) / 6.0));
  EXPECT_EQ(lattice_coordinate(LatticeAxis{0, 0.5, 1.0, 1}, 0), 0.5);
  const Lattice lat({{2, 0.0, 1.0, 3}, {0, 10.0, 20.0, 2}});
  EXPECT_EQ(lat.num_points(), 6u);
  const std::vector<double> x = lat.point(4);  // k0 = 1, k1 = 1: first axis fastest
  EXPECT_EQ(x[2], 0.5);
  EXPECT_EQ(x[0], 20.0);
}

TEST(Lattice, MatchesPointEvaluationForRandomFunctions) {
  testing::RandomFunctions gen(1234, 3);
  const Lattice lat({{0, -2.0, 1.5, 5}, {1, -1.0, 3.0, 4}, {2, 0.25, 2.0, 3}});
  std::size_t multi_table = 0, fallbacks = 0;
  for (int i = 0; i < 300; ++i) {
    const Fn f = gen.function(5);
    SCOPED_TRACE(i);
    expect_lattice_equals_points(f, lat);
    if (::testing::Test::HasFatalFailure()) return;
    LatticeStats stats;
    (void)evaluate_lattice(f, lat, LatticeMethod::Tables, &stats);
    multi_table += stats.tables > 1;
    fallbacks += stats.fallback_stages;
  }
  // The table path is really exercised (not just one full-lattice stage per function).
  EXPECT_GT(multi_table, 100u);
  RecordProperty("fallback_stages", static_cast<int>(fallbacks));
  std::printf("random functions: %zu of 300 used several tables, %zu fallback stages\n", multi_table, fallbacks);
}

TEST(Lattice, MatchesPointEvaluationForVectorFunctionsAndOddAxisOrder) {
  testing::RandomFunctions gen(99, 3);
  // Axes listed out of coordinate order, one of a single sample, an extra unused axis.
  const Lattice lat({{2, 0.0, 1.0, 4}, {0, -1.0, 1.0, 5}, {5, 0.0, 1.0, 2}, {1, 3.0, 3.0, 1}});
  for (int i = 0; i < 100; ++i) {
    const Fn f = cat({gen.function(4), gen.function(4), gen.function(3)});
    SCOPED_TRACE(i);
    expect_lattice_equals_points(f, lat);
    if (::testing::Test::HasFatalFailure()) return;
  }
  expect_lattice_equals_points(cat({Fn(2.5), x(0), sin(Fn(1.0)) * x(2)}), lat);
}

TEST(Lattice, Claim12TableLookupCounts) {
  const Fn x1 = x(0), x2 = x(1), x3 = x(2);
  const Fn f = (x1 * x2 + x2 * x3) * exp(x2);
  const Lattice lat({{0, 0.0, 1.0, 10}, {1, 0.0, 1.0, 10}, {2, 0.0, 1.0, 10}});
  LatticeStats plain, tables;
  const auto a = evaluate_lattice(f, lat, LatticeMethod::Plain, &plain);
  const auto b = evaluate_lattice(f, lat, LatticeMethod::Tables, &tables);
  EXPECT_EQ(plain.multiplies(), 3000u);
  EXPECT_EQ(plain.adds(), 1000u);
  EXPECT_EQ(plain.exps(), 1000u);
  EXPECT_EQ(plain.total(), 5000u);
  EXPECT_EQ(tables.multiplies(), 1200u);  // 1000 + 100 + 100
  EXPECT_EQ(tables.adds(), 1000u);
  EXPECT_EQ(tables.exps(), 10u);
  EXPECT_EQ(tables.total(), 2210u);
  EXPECT_EQ(tables.fallback_stages, 0u);
  EXPECT_EQ(tables.tables, 4u);  // {x1,x2}, {x2,x3}, {x2}, {x1,x2,x3}
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(same_bits(a[i], b[i]));
  expect_lattice_equals_points(f, lat);
}

TEST(Lattice, Errors) {
  EXPECT_THROW(Lattice({}), std::invalid_argument);
  EXPECT_THROW(Lattice({{0, 0, 1, 2}, {0, 0, 1, 2}}), std::invalid_argument);
  EXPECT_THROW(Lattice({{0, 0, 1, 0}}), std::invalid_argument);
  EXPECT_THROW(Lattice({{0, 0, std::nan(""), 2}}), std::invalid_argument);
  try {
    (void)evaluate_lattice(x(0) + x(3), Lattice({{0, 0, 1, 2}}));
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("x(3)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace genmod
