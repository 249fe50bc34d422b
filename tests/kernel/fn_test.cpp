// Fn construction: hash-consing, simplification, broadcasting, composition, and the kernel
// claims of snyder.md section 11 (items 5, 6, 10, 11).
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "kernel/src/dag.hpp"  // white-box: the store's sharing and simplifications

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

namespace genmod {
namespace {

Interval range(const Fn& f, std::vector<Interval> box) {
  IntervalEvaluator ev;
  return ev.eval(Tape(f), box)[0];
}

double at(const Fn& f, std::vector<double> coordinates) { return evaluate(f, coordinates)[0]; }

TEST(Fn, HashConsingSharesEqualSubexpressions) {
  const Fn a = sin(x(0) * x(1)) + 2.0;
  const Fn b = sin(x(0) * x(1)) + 2.0;
  EXPECT_EQ(a.node(0), b.node(0));
  EXPECT_EQ((x(0) + x(1)).node(0), (x(1) + x(0)).node(0));  // commutative operands are ordered
  EXPECT_NE((x(0) - x(1)).node(0), (x(1) - x(0)).node(0));
  const std::size_t before = dag::size();
  for (int i = 0; i < 100; ++i) (void)(sin(x(0) * x(1)) + 2.0);
  EXPECT_EQ(dag::size(), before);
}

// == and != on Fn build the relation (as < does), never a C++ bool turned into a constant;
// a bool does not convert to Fn at all; identical() compares handles.
static_assert(std::is_same_v<decltype(x(0) == 0.5), Fn>);
static_assert(std::is_same_v<decltype(0.5 != x(0)), Fn>);
static_assert(!std::is_constructible_v<Fn, bool>);
static_assert(std::is_convertible_v<int, Fn> && std::is_convertible_v<double, Fn>);

TEST(Fn, EqualityBuildsTheRelation) {
  const Fn on = x(0) == 0.5;
  EXPECT_EQ(at(on, {0.5}), 1.0);
  EXPECT_EQ(at(on, {0.25}), 0.0);
  EXPECT_EQ(at(x(0) != 0.5, {0.25}), 1.0);
  EXPECT_EQ(at(cat({x(0), x(1)}) == cat({1.0, 2.0}), {1.0, 2.0}), 1.0);
  EXPECT_EQ(at(cat({x(0), x(1)}) == cat({1.0, 2.0}), {1.0, 3.0}), 0.0);
  // Over a box holding 0.5 the relation may hold; over one that does not, it cannot.
  EXPECT_EQ(range(on, {Interval(0, 1)}), Interval(0, 1));
  EXPECT_EQ(range(on, {Interval(0.6, 1)}), Interval(0, 0));
  EXPECT_TRUE(identical(sin(x(0)), sin(x(0))));
  EXPECT_FALSE(identical(sin(x(0)), cos(x(0))));
  const Fn three = 3;  // integers convert like doubles
  double v = 0;
  EXPECT_TRUE(three.is_constant(&v) && v == 3.0);
}

TEST(Fn, ConstructionSimplifies) {
  const Fn u = x(0);
  EXPECT_EQ((u + 0.0).node(0), u.node(0));
  EXPECT_EQ((u * 1.0).node(0), u.node(0));
  EXPECT_EQ((u / 1.0).node(0), u.node(0));
  EXPECT_EQ((-(-u)).node(0), u.node(0));
  EXPECT_TRUE((u - u).is_constant());
  EXPECT_EQ(dag::node((u * u).node(0)).op, Op::Square);
  double v;
  ASSERT_TRUE((Fn(2.0) * 3.0 + 1.5).is_constant(&v));
  EXPECT_EQ(v, 7.5);
  // Inexact results are not folded: the constant must be the real value.
  EXPECT_FALSE((Fn(1.0) / 3.0).is_constant());
  EXPECT_FALSE(sin(Fn(1.0)).is_constant());
  // x - x stays when x may be an error: sqrt(-1) - sqrt(-1) is an error, not 0.
  EXPECT_FALSE((sqrt(u) - sqrt(u)).is_constant());
}

TEST(Fn, InputSetIsTheCoordinatesUsed) {
  const Fn f = x(3) * x(7) + 1.0;
  EXPECT_EQ(f.inputs(), (std::vector<int>{3, 7}));
  EXPECT_TRUE(Fn(2.0).inputs().empty());
  EXPECT_THROW(x(-1), std::invalid_argument);
  EXPECT_THROW(x(kMaxInputs), std::invalid_argument);
}

TEST(Fn, VectorsBroadcastAndProject) {
  const Fn v = cat({x(0), x(1), 3.0});
  EXPECT_EQ(v.dim(), 3u);
  const Fn w = v * 2.0;
  EXPECT_EQ(w.dim(), 3u);
  const auto r = evaluate(w, std::vector<double>{1.0, 2.0});
  EXPECT_EQ(r, (std::vector<double>{2.0, 4.0, 6.0}));
  EXPECT_EQ(evaluate(w[1], std::vector<double>{1.0, 2.0})[0], 4.0);
  EXPECT_THROW((void)w[3], std::out_of_range);
  EXPECT_THROW((void)(v + cat({x(0), x(1)})), std::invalid_argument);
  // Vector relation = conjunction over components.
  EXPECT_EQ(at(eq(v, cat({x(0), x(1), Fn(3.0)})), {1, 2}), 1.0);
  EXPECT_EQ(at(eq(v, cat({x(0), x(0), Fn(3.0)})), {1, 2}), 0.0);
  EXPECT_EQ(at(ne(v, cat({x(0), x(0), Fn(3.0)})), {1, 2}), 1.0);
  EXPECT_THROW((void)(v && x(0)), std::invalid_argument);
}

// Claim 5: a same-node product is a square, with the tight range.
TEST(Fn, SquareOfSameNodeIsTight) {
  const Interval sq = range(x(0) * x(0), {Interval(-2, 2)});
  EXPECT_EQ(sq.lo(), 0.0);
  EXPECT_EQ(sq.hi(), 4.0);
  const Interval prod = range(x(0) * x(1), {Interval(-2, 2), Interval(-2, 2)});
  EXPECT_EQ(prod.lo(), -4.0);
  EXPECT_EQ(prod.hi(), 4.0);
}

// Claim 6: ternary relational and logical results.
TEST(Fn, RelationalResultsAreTernary) {
  const Fn lt = x(0) < x(1);
  EXPECT_EQ(range(lt, {Interval(2, 3), Interval(1, 2)}), Interval(0.0));
  EXPECT_EQ(range(lt, {Interval(0, 1), Interval(1.5, 2)}), Interval(1.0));
  EXPECT_EQ(range(lt, {Interval(0, 2), Interval(1, 3)}), Interval(0, 1));
  const Fn e = eq(x(0), x(1));
  EXPECT_EQ(range(e, {Interval(2), Interval(2)}), Interval(1.0));
  EXPECT_EQ(range(e, {Interval(2, 3), Interval(2, 3)}), Interval(0, 1));
  EXPECT_EQ(range(e, {Interval(2, 3), Interval(4, 5)}), Interval(0.0));

  // AND / OR / NOT over {[0,0], [0,1], [1,1]}: all 9 + 9 + 3 cases.
  const Interval vals[3] = {Interval(0.0), Interval(0, 1), Interval(1.0)};
  auto expect_and = [](int a, int b) { return (a == 0 || b == 0) ? 0 : (a == 2 && b == 2) ? 2 : 1; };
  auto expect_or = [](int a, int b) { return (a == 2 || b == 2) ? 2 : (a == 0 && b == 0) ? 0 : 1; };
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(range(!x(0), {vals[a]}), vals[2 - a]);
    for (int b = 0; b < 3; ++b) {
      EXPECT_EQ(range(x(0) && x(1), {vals[a], vals[b]}), vals[expect_and(a, b)]) << a << b;
      EXPECT_EQ(range(x(0) || x(1), {vals[a], vals[b]}), vals[expect_or(a, b)]) << a << b;
    }
  }
}

// Claim 10: the thesis example of symbolic differentiation.
TEST(Fn, ThesisDerivativeExample) {
  const Fn f = x(1) + sqrt(x(1) * x(2));
  const Fn df = derivative(f, 1);
  for (double a : {0.3, 1.0, 2.5})
    for (double b : {0.2, 1.7}) {
      const double expected = 1.0 + b / (2.0 * std::sqrt(a * b));
      EXPECT_NEAR(at(df, {0.0, a, b}), expected, 1e-14 * expected);
    }
  EXPECT_TRUE(derivative(f, 0).is_constant());
}

// Claim 11: errors propagate to every ancestor; error(h) selects around them.
TEST(Fn, ErrorsPropagateAndCanBeTested) {
  for (const Fn& bad : {sqrt(Fn(-1.0) + x(0) * 0.0), 1.0 / (x(0) - x(0) + 0.0 * x(0)), log(x(0) * 0.0)}) {
    EXPECT_TRUE(std::isnan(at(bad, {1.0})));
    EXPECT_TRUE(std::isnan(at(bad + 1.0, {1.0})));
    EXPECT_TRUE(std::isnan(at(min(bad, Fn(0.0)) * 2.0, {1.0})));
    EXPECT_TRUE(std::isnan(at(bad < 3.0, {1.0})));
    EXPECT_EQ(at(is_error(bad), {1.0}), 1.0);
  }
  // cond(error(sqrt(h)), -sqrt(-h), sqrt(h)) is defined everywhere.
  const Fn h = x(0);
  const Fn safe = select(is_error(sqrt(h)), -sqrt(-h), sqrt(h));
  EXPECT_EQ(at(safe, {-4.0}), -2.0);
  EXPECT_EQ(at(safe, {9.0}), 3.0);
  IntervalEvaluator ev;
  Tape t(safe);
  const Interval r = ev.eval(t, std::vector<Interval>{Interval(-4, -1)})[0];
  EXPECT_EQ(ev.errors()[0], kNoError);
  EXPECT_TRUE(r.contains(-2.0) && r.contains(-1.0));
  // The interval evaluator reports certain and possible errors.
  Tape s(sqrt(h));
  ev.eval(s, std::vector<Interval>{Interval(-3, -1)});
  EXPECT_EQ(ev.errors()[0], kCertainError);
  ev.eval(s, std::vector<Interval>{Interval(-3, 1)});
  EXPECT_EQ(ev.errors()[0], kMaybeError);
  ev.eval(s, std::vector<Interval>{Interval(0, 1)});
  EXPECT_EQ(ev.errors()[0], kNoError);
}

TEST(Fn, ComposeSubstitutes) {
  // m_eval(g, 1, h): g(x0, x1) with x1 := h(x2).
  const Fn g = x(0) * x(1) + sin(x(1));
  const Fn h = square(x(2));
  const Fn r = compose(g, 1, h);
  EXPECT_EQ(r.inputs(), (std::vector<int>{0, 2}));
  EXPECT_DOUBLE_EQ(at(r, {2.0, 0.0, 3.0}), 2.0 * 9.0 + std::sin(9.0));
  // m_eval_all(g, [0, 1, 2], h) with h of dimension 3 in x3, x4.
  const Fn g3 = x(0) + 10.0 * x(1) + 100.0 * x(2);
  const Fn h3 = cat({x(3), x(4), x(3) * x(4)});
  const std::vector<int> which = {0, 1, 2};
  const Fn r3 = compose_all(g3, which, h3);
  EXPECT_EQ(at(r3, {0, 0, 0, 2.0, 3.0}), 2.0 + 30.0 + 600.0);
  // Simultaneous, not sequential: swapping x0 and x1.
  const std::vector<int> swap = {0, 1};
  EXPECT_EQ(at(compose_all(x(0) - x(1), swap, cat({x(1), x(0)})), {5.0, 2.0}), -3.0);
  EXPECT_THROW(compose_all(g3, which, cat({x(0), x(1)})), std::invalid_argument);
  EXPECT_THROW(compose(g, 0, cat({x(0), x(1)})), std::invalid_argument);
}

}  // namespace
}  // namespace genmod
