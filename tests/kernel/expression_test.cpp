// expression(): a scalar Fn's root as an opcode and operand Fns. Rebuilding every node of
// random functions from its expression with the same opcode gives back the same node (the
// store hash-conses), so the view loses nothing.
#include "genmod/kernel/expression.hpp"
#include "kernel/random_functions.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace genmod {
namespace {

TEST(Expression, LeavesAndOperands) {
  const Expression c = expression(Fn(2.5));
  EXPECT_EQ(c.op, Op::Const);
  EXPECT_EQ(c.value, 2.5);
  EXPECT_TRUE(c.operands.empty());
  const Expression v = expression(x(3));
  EXPECT_EQ(v.op, Op::Var);
  EXPECT_EQ(v.coordinate, 3);
  const Fn f = sin(x(0)) / x(1);
  const Expression d = expression(f);
  EXPECT_EQ(d.op, Op::Div);
  ASSERT_EQ(d.operands.size(), 2u);
  EXPECT_EQ(d.operands[0].node(0), sin(x(0)).node(0));
  EXPECT_EQ(d.operands[1].node(0), x(1).node(0));
  // And is commutative: its operands come in the store's order.
  const Expression r = expression((x(0) <= 1.0) && !(x(1) == 2.0));
  EXPECT_EQ(r.op, Op::And);
  ASSERT_EQ(r.operands.size(), 2u);
  const Op a = expression(r.operands[0]).op, b = expression(r.operands[1]).op;
  EXPECT_TRUE((a == Op::Le && b == Op::Not) || (a == Op::Not && b == Op::Le));
}

TEST(Expression, CountsSharedNodesOnce) {
  const Fn s = sin(x(0));
  EXPECT_EQ(count_nodes(s * s + s), 4u);  // x0, sin, the product, the sum
  EXPECT_EQ(count_nodes(cat({s, s})), 2u);
}

TEST(Expression, RefusesVectors) { EXPECT_THROW(expression(cat({x(0), x(1)})), std::invalid_argument); }

// Every operand of every node of 200 random functions, walked down through expression(), is
// a scalar whose opcode's arity matches its operand count; leaves carry their value or
// coordinate, and the walk reaches exactly the inputs the function depends on.
TEST(Expression, WalksRandomFunctionsDownToTheirInputs) {
  testing::RandomFunctions gen(31, 3);
  for (int i = 0; i < 200; ++i) {
    const Fn f = gen.function(6);
    std::vector<Fn> stack{f};
    std::uint64_t reached = 0;
    std::size_t visited = 0;
    while (!stack.empty() && visited < 100000) {
      const Fn g = stack.back();
      stack.pop_back();
      ++visited;
      const Expression e = expression(g);
      if (e.op == Op::Var) reached |= std::uint64_t{1} << e.coordinate;
      if (e.op == Op::Const || e.op == Op::Var) {
        EXPECT_TRUE(e.operands.empty());
        continue;
      }
      if (e.op != Op::Custom) {
        ASSERT_EQ(static_cast<int>(e.operands.size()), arity(e.op)) << op_name(e.op);
      }
      std::uint64_t below = 0;
      for (const Fn& o : e.operands) {
        ASSERT_EQ(o.dim(), 1u);
        below |= o.input_mask();
        stack.push_back(o);
      }
      EXPECT_EQ(below, g.input_mask()) << op_name(e.op);
    }
    EXPECT_EQ(reached, f.input_mask());
  }
}

}  // namespace
}  // namespace genmod
