// Tapes and evaluators: batch = scalar bitwise, pruning preserves values inside the box,
// register allocation, and a custom operator through all three methods.
#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/gradient_evaluator.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "kernel/src/tape_data.hpp"
#include "genmod/kernel/vm_format.hpp"
#include "kernel/random_functions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace genmod {
namespace {

using testing::RandomFunctions;

const std::vector<int> kXyz = {0, 1, 2};

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Evaluates `tape` at `count` points with the batch evaluator and compares each output with
// the scalar evaluator bit for bit.
void expect_batch_equals_scalar(const Tape& tape, const std::vector<std::vector<double>>& inputs, std::size_t count) {
  std::vector<const double*> in;
  for (const auto& v : inputs) in.push_back(v.data());
  std::vector<std::vector<double>> out(tape.num_outputs(), std::vector<double>(count));
  std::vector<double*> out_ptrs;
  for (auto& v : out) out_ptrs.push_back(v.data());
  BatchEvaluator batch;
  batch.eval(tape, in, count, out_ptrs);
  PointEvaluator scalar;
  std::vector<double> p(inputs.size());
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t k = 0; k < inputs.size(); ++k) p[k] = inputs[k][i];
    const auto v = scalar.eval(tape, p);
    for (std::size_t j = 0; j < v.size(); ++j)
      ASSERT_TRUE(same_bits(v[j], out[j][i]) || (std::isnan(v[j]) && std::isnan(out[j][i])))
          << "point " << i << " output " << j << ": scalar " << v[j] << " batch " << out[j][i];
  }
}

TEST(Evaluators, BatchEqualsScalarBitwiseOnRandomFunctions) {
  RandomFunctions rnd(21);
  for (int trial = 0; trial < 300; ++trial) {
    const Fn f = cat({rnd.function(6), rnd.function(3)});
    const Tape tape(f, kXyz);
    const std::size_t count = static_cast<std::size_t>(rnd.integer(1, 700));  // crosses chunk edges
    std::vector<std::vector<double>> in(3, std::vector<double>(count));
    for (auto& v : in)
      for (auto& x : v) x = rnd.uniform(-4, 4);
    expect_batch_equals_scalar(tape, in, count);
  }
}

// Strided arrays (a row-major (count, 3) array read in place, results written into the rows of
// a (count, 2) array) give the same bits as separate contiguous arrays.
TEST(Evaluators, StridedBatchEqualsContiguousBitwise) {
  RandomFunctions rnd(24);
  BatchEvaluator batch;
  for (int trial = 0; trial < 100; ++trial) {
    const Tape tape(cat({rnd.function(5), rnd.function(3)}), kXyz);
    const std::size_t count = static_cast<std::size_t>(rnd.integer(1, 700));
    std::vector<double> rows(3 * count), rows_out(2 * count, -1.0);
    std::vector<std::vector<double>> cols(3, std::vector<double>(count)), cols_out(2, std::vector<double>(count));
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t k = 0; k < 3; ++k) cols[k][i] = rows[3 * i + k] = rnd.uniform(-4, 4);
    const double* in_rows[] = {rows.data(), rows.data() + 1, rows.data() + 2};
    double* out_rows[] = {rows_out.data(), rows_out.data() + 1};
    batch.eval(tape, in_rows, count, out_rows, 3, 2);
    const double* in_cols[] = {cols[0].data(), cols[1].data(), cols[2].data()};
    double* out_cols[] = {cols_out[0].data(), cols_out[1].data()};
    batch.eval(tape, in_cols, count, out_cols);
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t j = 0; j < 2; ++j)
        ASSERT_TRUE(same_bits(rows_out[2 * i + j], cols_out[j][i]) ||
                    (std::isnan(rows_out[2 * i + j]) && std::isnan(cols_out[j][i])))
            << "point " << i << " output " << j;
  }
  const double* in[] = {nullptr, nullptr, nullptr};
  double* out[] = {nullptr, nullptr};
  const Tape tape(cat({x(0), x(1)}), kXyz);
  EXPECT_THROW(batch.eval(tape, in, 0, out, 0, 1), std::invalid_argument);
}

TEST(Evaluators, BatchEqualsScalarBitwiseOnProspero) {
  const Tape tape(load_vm(GENMOD_DATA_DIR "/prospero.vm"), std::vector<int>{0, 1});
  RandomFunctions rnd(22);
  const std::size_t count = 3000;
  std::vector<std::vector<double>> in(2, std::vector<double>(count));
  for (auto& v : in)
    for (auto& x : v) x = rnd.uniform(-1, 1);
  expect_batch_equals_scalar(tape, in, count);
}

TEST(Evaluators, IntervalAtAPointContainsThePointValue) {
  RandomFunctions rnd(23);
  IntervalEvaluator iv;
  PointEvaluator pv;
  for (int trial = 0; trial < 1000; ++trial) {
    const Tape tape(rnd.function(6), kXyz);
    const std::vector<double> p = {rnd.uniform(-3, 3), rnd.uniform(-3, 3), rnd.uniform(-3, 3)};
    const double v = pv.eval(tape, p)[0];
    const std::vector<Interval> box = {Interval(p[0]), Interval(p[1]), Interval(p[2])};
    const Interval y = iv.eval(tape, box)[0];
    EXPECT_TRUE(testing::accounts_for(y, iv.errors()[0], v)) << v << " vs " << y;
  }
}

// The invariants of both forms: the same operations in the same order; SSA ids unique, below
// num_values() and defined before use; registers below num_registers().
void expect_well_formed(const Tape& t) {
  const auto reg = detail::clauses(t);
  const auto ssa = detail::ssa(t);
  ASSERT_EQ(reg.size(), ssa.size());
  std::vector<bool> defined(detail::num_values(t), false);
  const auto check_value = [&](std::uint32_t v) {
    ASSERT_LT(v, detail::num_values(t));
    EXPECT_TRUE(defined[v]) << "value " << v << " used before its definition\n" << t.disassemble();
  };
  for (std::size_t i = 0; i < ssa.size(); ++i) {
    ASSERT_EQ(reg[i].op, ssa[i].op);
    const int ar = arity(ssa[i].op);
    const bool imm = has_immediate(ssa[i].op);
    if (ar >= 1) check_value(ssa[i].a);
    if (ar >= 2 && !imm) check_value(ssa[i].b);
    if (ar >= 3) check_value(ssa[i].c);
    if (ar >= 1) {
      EXPECT_LT(reg[i].a, t.num_registers());
    }
    EXPECT_LT(reg[i].out, t.num_registers());
    ASSERT_LT(ssa[i].out, detail::num_values(t));
    EXPECT_FALSE(defined[ssa[i].out]) << "value " << ssa[i].out << " defined twice";
    defined[ssa[i].out] = true;
  }
  for (std::uint32_t v : detail::output_values(t)) check_value(v);
  for (std::uint32_t r : detail::output_registers(t)) EXPECT_LT(r, t.num_registers());
}

bool same_clause(const Clause& x, const Clause& y) {
  return x.op == y.op && x.out == y.out && x.a == y.a && x.b == y.b && x.c == y.c;
}

// Pruned with reused scratch memory and with fresh scratch memory: the same tape.
void expect_same_tape(const Tape& x, const Tape& y) {
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_TRUE(same_clause(detail::clauses(x)[i], detail::clauses(y)[i])) << i;
    EXPECT_TRUE(same_clause(detail::ssa(x)[i], detail::ssa(y)[i])) << i;
  }
  EXPECT_TRUE(std::ranges::equal(detail::output_registers(x), detail::output_registers(y)));
  EXPECT_TRUE(std::ranges::equal(detail::output_values(x), detail::output_values(y)));
  EXPECT_EQ(x.num_registers(), y.num_registers());
}

// `pruned` equals `full` bit for bit at sample points of `box`.
void expect_equal_inside(const Tape& full, const Tape& pruned, const std::vector<Interval>& box, RandomFunctions& rnd) {
  PointEvaluator pv;
  for (int s = 0; s < 20; ++s) {
    const std::vector<double> p = {rnd.sample(box[0], s), rnd.sample(box[1], s + 1), rnd.sample(box[2], s + 2)};
    const double a = pv.eval(full, p)[0];
    const double b = pv.eval(pruned, p)[0];
    ASSERT_TRUE(same_bits(a, b) || (std::isnan(a) && std::isnan(b)))
        << a << " vs " << b << "\nfull:\n" << full.disassemble() << "pruned:\n" << pruned.disassemble();
  }
}

// Pruning as the renderers use it: one TapeSimplifier reused across tapes of all sizes (its
// scratch arrays must come back clean from every call), choices weakened at random (either
// side is always allowed), and the pruned tape pruned again inside a smaller box (a pruned
// tape keeps its parent's value ids).
TEST(Evaluators, PrunedTapeEqualsFullTapeInsideItsBox) {
  RandomFunctions rnd(24);
  IntervalEvaluator iv;
  TapeSimplifier scratch;
  int pruned = 0, pruned_again = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    // Min/max-heavy functions, as in CSG.
    Fn f = rnd.function(3);
    for (int k = 0; k < 4; ++k) f = (k % 2 ? min(f, rnd.function(3)) : max(f, rnd.function(3)));
    f = select(x(0) < rnd.uniform(-1, 1), f, rnd.function(3));
    const Tape tape(f, kXyz);
    std::vector<Interval> box = {rnd.small_interval(), rnd.small_interval(), rnd.small_interval()};
    iv.eval(tape, box);
    std::vector<std::uint8_t> choices(iv.choices().begin(), iv.choices().end());
    if (trial % 3 == 0)
      for (auto& c : choices)
        if (rnd.integer(0, 2) == 0) c = kChoiceBoth;
    const Tape shorter = tape.simplify(choices, scratch);
    expect_well_formed(shorter);
    expect_same_tape(shorter, tape.simplify(choices));
    if (shorter.size() < tape.size()) ++pruned;
    expect_equal_inside(tape, shorter, box, rnd);

    for (Interval& b : box) b = Interval(b.lo(), b.lo() + 0.25 * (b.hi() - b.lo()));
    iv.eval(shorter, box);
    const Tape shortest = shorter.simplify(iv.choices(), scratch);
    expect_well_formed(shortest);
    if (shortest.size() < shorter.size()) ++pruned_again;
    expect_equal_inside(tape, shortest, box, rnd);
  }
  EXPECT_GT(pruned, 300);
  EXPECT_GT(pruned_again, 100);
}

TEST(Evaluators, ProsperoPrunesToAFractionInSmallTiles) {
  const Tape tape(load_vm(GENMOD_DATA_DIR "/prospero.vm"), std::vector<int>{0, 1});
  EXPECT_GT(tape.size(), 6000u);          // 7,866 lines less the constants folded into clauses
  EXPECT_LT(tape.num_registers(), 1000u);  // register allocation packs the values
  IntervalEvaluator iv;
  PointEvaluator pv;
  const std::vector<Interval> box = {Interval(-0.5, -0.48), Interval(0.3, 0.32)};
  iv.eval(tape, box);
  const Tape shorter = tape.simplify(iv.choices());
  EXPECT_LT(shorter.size() * 10, tape.size());
  RandomFunctions rnd(25);
  for (int s = 0; s < 200; ++s) {
    const double p[2] = {rnd.sample(box[0], s), rnd.sample(box[1], s + 1)};
    EXPECT_EQ(pv.eval(tape, p)[0], pv.eval(shorter, p)[0]);
  }
  // Pruning again inside the pruned box keeps working (nested tiles).
  iv.eval(shorter, std::vector<Interval>{Interval(-0.5, -0.49), Interval(0.3, 0.31)});
  EXPECT_LE(shorter.simplify(iv.choices()).size(), shorter.size());
}

TEST(Evaluators, SharedSubexpressionIsEvaluatedOnce) {
  // Claim 13's sharing: g appears once on the tape of sqrt(g) + g.
  const Fn g = sin(x(0)) * cos(x(1)) + 2.0;
  const Tape t(sqrt(g) + g);
  int sines = 0;
  for (const Clause& c : detail::clauses(t)) sines += c.op == Op::Sin;
  EXPECT_EQ(sines, 1);
  EXPECT_EQ(t.size(), 8u);  // load, sin, load, cos, mul, add-imm, sqrt, add
}

TEST(Evaluators, WrongDimensionsAreReported) {
  const Tape t(x(0) + x(1));
  PointEvaluator pv;
  IntervalEvaluator iv;
  EXPECT_THROW(pv.eval(t, {1.0}), std::invalid_argument);
  EXPECT_THROW(iv.eval(t, std::vector<Interval>{Interval(0, 1)}), std::invalid_argument);
  EXPECT_THROW(Tape(x(0) + x(5), std::vector<int>{0, 1}), std::invalid_argument);
  EXPECT_THROW(Tape(x(0), std::vector<int>{0, 0}), std::invalid_argument);
  EXPECT_THROW(t.simplify(std::vector<std::uint8_t>(1)), std::invalid_argument);
}

// A custom operator: the unit circle c(t) = (cos 2 pi t, sin 2 pi t) with a rigorous
// inclusion from the elementary enclosures and an exact symbolic derivative.
class UnitCircle : public CustomOp {
 public:
  std::string name() const override { return "unit-circle"; }
  int num_args() const override { return 1; }
  int num_outputs() const override { return 2; }
  void eval(std::span<const double> args, std::span<double> out) const override {
    ++calls;
    out[0] = std::cos(2 * M_PI * args[0]);
    out[1] = std::sin(2 * M_PI * args[0]);
  }
  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t>) const override {
    const Interval two_pi(6.283185307179586, 6.2831853071795872);  // encloses 2 pi
    const Interval angle = args[0] * two_pi;
    out[0] = cos(angle);
    out[1] = sin(angle);
  }
  Fn derivative(std::span<const Fn> args, int) const override {
    const double w = 2 * M_PI;
    return cat({-w * sin(w * args[0]), w * cos(w * args[0])});
  }
  mutable std::atomic<int> calls{0};
};

TEST(Evaluators, CustomOperatorThroughAllThreeMethods) {
  auto op = std::make_shared<UnitCircle>();
  const Fn c = apply_custom(op, {square(x(0))});  // composed with t = u^2
  ASSERT_EQ(c.dim(), 2u);
  const Fn r2 = square(c[0]) + square(c[1]);
  const Tape t(cat({c, r2}));
  PointEvaluator pv;
  const double u = 0.3;
  op->calls = 0;
  const auto v = pv.eval(t, {u});
  EXPECT_EQ(op->calls.load(), 1);  // both outputs from one call
  EXPECT_NEAR(v[0], std::cos(2 * M_PI * u * u), 1e-15);
  EXPECT_NEAR(v[2], 1.0, 1e-15);
  // Inclusion through the tape.
  IntervalEvaluator iv;
  const auto y = iv.eval(t, std::vector<Interval>{Interval(0.2, 0.4)});
  for (double s = 0.2; s <= 0.4; s += 0.01) {
    EXPECT_TRUE(y[0].contains(std::cos(2 * M_PI * s * s)));
    EXPECT_TRUE(y[1].contains(std::sin(2 * M_PI * s * s)));
  }
  // Symbolic derivative (chain rule through the operator) and the gradient evaluator.
  const Fn dc = derivative(c, 0);
  const auto d = evaluate(dc, std::vector<double>{u});
  EXPECT_NEAR(d[0], -2 * M_PI * std::sin(2 * M_PI * u * u) * 2 * u, 1e-12);
  EXPECT_NEAR(d[1], 2 * M_PI * std::cos(2 * M_PI * u * u) * 2 * u, 1e-12);
  GradientEvaluator g;
  g.eval(t, std::vector<double>{u});
  EXPECT_NEAR(g.jacobian()[0], d[0], 1e-12);
  EXPECT_NEAR(g.jacobian()[1], d[1], 1e-12);
  EXPECT_NEAR(g.jacobian()[2], 0.0, 1e-12);
  // Batch evaluation equals scalar.
  std::vector<double> in(50);
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = 0.02 * static_cast<double>(i);
  expect_batch_equals_scalar(t, {in}, in.size());
  // Composition substitutes inside the operator's arguments.
  EXPECT_NEAR(evaluate(compose(c, 0, Fn(0.5)), std::vector<double>{})[0], std::cos(2 * M_PI * 0.25), 1e-15);
  EXPECT_THROW(apply_custom(op, {x(0), x(1)}), std::invalid_argument);
}


// Pruning drops a call whose outputs nothing kept needs, and keeps (renumbered) the others.
TEST(Evaluators, PruningKeepsTheCallsItNeeds) {
  auto op = std::make_shared<UnitCircle>();
  const Fn near = apply_custom(op, {x(0)});
  const Fn far = apply_custom(op, {x(0) + 0.25});
  const Tape tape(select(x(0) < 0.5, min(near[0], near[1]), far[1] * x(1)), std::vector<int>{0, 1});
  ASSERT_EQ(detail::calls(tape).size(), 2u);
  IntervalEvaluator iv;
  PointEvaluator pv;
  TapeSimplifier scratch;
  struct Case {
    double lo, hi;
    std::size_t calls;
  };
  for (const Case& c : {Case{0.1, 0.3, 1}, Case{0.6, 0.9, 1}, Case{0.3, 0.7, 2}}) {
    const std::vector<Interval> box = {Interval(c.lo, c.hi), Interval(-1, 1)};
    iv.eval(tape, box);
    const Tape pruned = tape.simplify(iv.choices(), scratch);
    expect_well_formed(pruned);
    EXPECT_EQ(detail::calls(pruned).size(), c.calls) << pruned.disassemble();
    for (int s = 0; s <= 10; ++s) {
      const std::vector<double> p = {c.lo + (c.hi - c.lo) * s / 10, 0.3};
      EXPECT_TRUE(same_bits(pv.eval(tape, p)[0], pv.eval(pruned, p)[0])) << p[0];
    }
  }
}

// A custom operator with no arguments: a named constant with a rigorous enclosure.
class GoldenRatio : public CustomOp {
 public:
  std::string name() const override { return "golden-ratio"; }
  int num_args() const override { return 0; }
  int num_outputs() const override { return 1; }
  void eval(std::span<const double>, std::span<double> out) const override { out[0] = (1 + std::sqrt(5.0)) / 2; }
  void inclusion(std::span<const Interval>, std::span<Interval> out, std::span<std::uint8_t>) const override {
    out[0] = (Interval(1.0) + sqrt(Interval(5.0))) / Interval(2.0);
  }
  Fn derivative(std::span<const Fn>, int) const override { return Fn(0.0); }
};

TEST(Evaluators, CustomOperatorWithoutArguments) {
  const Fn phi = apply_custom(std::make_shared<GoldenRatio>(), std::span<const Fn>{});
  const Fn f = phi * x(0);
  const double golden = (1 + std::sqrt(5.0)) / 2;
  EXPECT_DOUBLE_EQ(evaluate(f, std::vector<double>{2.0})[0], 2 * golden);
  IntervalEvaluator iv;
  const Interval y = iv.eval(Tape(f), {Interval(1, 2)})[0];
  EXPECT_TRUE(y.contains(golden) && y.contains(2 * golden));
  EXPECT_DOUBLE_EQ(evaluate(derivative(f, 0), std::vector<double>{3.0})[0], golden);
}

// A tape of arithmetic, min / max and square roots runs in the interval evaluator's
// error-free loop, which falls back to the general loop where an error may occur (a
// non-finite bound, a root of an interval reaching below 0). Differential check: the same
// function on a tape with one more output (abs: not plain) runs the general loop only; both
// must give the same bits, error bits and continuity on ordinary, huge, unbounded and
// degenerate boxes.
Fn plain_function(testing::RandomFunctions& rnd, int depth) {
  if (depth <= 0 || rnd.integer(0, 5) == 0) {
    if (rnd.integer(0, 2) == 0) return Fn(std::round(rnd.uniform(-3, 3) * 4) / 4);
    return x(rnd.integer(0, 2));
  }
  static const Op ops[] = {Op::Neg, Op::Square, Op::Sqrt, Op::Add, Op::Sub, Op::Mul, Op::Min, Op::Max};
  const Op op = ops[rnd.integer(0, 7)];
  const Fn a = plain_function(rnd, depth - 1);
  return arity(op) == 1 ? testing::apply_op(op, a) : testing::apply_op(op, a, plain_function(rnd, depth - 1));
}

TEST(Evaluators, PlainLoopEqualsTheGeneralLoop) {
  testing::RandomFunctions rnd(41);
  IntervalEvaluator plain_ev, general_ev;
  int plain_tapes = 0, errors_seen = 0;
  for (int f_index = 0; f_index < 300; ++f_index) {
    const Fn f = plain_function(rnd, 6);
    const Tape plain(f, std::vector<int>{0, 1, 2}), general(cat({f, abs(x(0))}), std::vector<int>{0, 1, 2});
    ASSERT_FALSE(detail::tape_data(general).plain);
    plain_tapes += detail::tape_data(plain).plain;
    for (int b = 0; b < 20; ++b) {
      const std::vector<Interval> box{rnd.interval(), rnd.small_interval(), rnd.interval()};
      const Interval p = plain_ev.eval(plain, box)[0], g = general_ev.eval(general, box)[0];
      EXPECT_TRUE(std::bit_cast<std::uint64_t>(p.lo()) == std::bit_cast<std::uint64_t>(g.lo()) || (std::isnan(p.lo()) && std::isnan(g.lo())));
      EXPECT_TRUE(std::bit_cast<std::uint64_t>(p.hi()) == std::bit_cast<std::uint64_t>(g.hi()) || (std::isnan(p.hi()) && std::isnan(g.hi())));
      EXPECT_EQ(plain_ev.errors()[0], general_ev.errors()[0]);
      EXPECT_EQ(plain_ev.continuous(), general_ev.continuous() || general_ev.errors()[1] != kNoError);
      errors_seen += plain_ev.errors()[0] != kNoError;
    }
  }
  EXPECT_GT(plain_tapes, 250);   // constants alone compile to plain tapes too
  EXPECT_GT(errors_seen, 100);  // the fallbacks were exercised
}

}  // namespace
}  // namespace genmod
