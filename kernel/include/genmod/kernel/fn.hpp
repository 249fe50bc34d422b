// Fn: a cheap value handle to a function R^n -> R^m (GENMOD's MAN).
//
// An Fn holds the DAG ids of its m scalar components. Its inputs are the parametric
// coordinates x(i) it actually depends on (GENMOD's input set): x(3) has one input, {3}.
// Binary operators apply componentwise when both operands have the same dimension, and
// broadcast a scalar operand over the other's components; any other combination throws
// std::invalid_argument naming both dimensions.
//
// Example:
//   Fn u = x(0), v = x(1);
//   Fn sphere = cat({cos(u) * cos(v), sin(u) * cos(v), sin(v)});
//   Fn p = cat({x(0), x(1), x(2)});
//   Fn inside = length(p) < 1.0;        // 0/1 valued
#pragma once

#include "genmod/kernel/coordinates.hpp"

#include <concepts>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace genmod {

// The id of a scalar node of the process-wide expression store. Nodes are hash-consed:
// structurally equal live nodes share one id, so f.node(j) is a cache key for the function it
// computes while an Fn holds it. Fn values may be built, copied and dropped from any number of
// threads at once. A node, and a custom operator, is reclaimed as soon as no Fn (and no node
// above it) holds it any more, and its id may then be reused: a loop that builds and drops
// shapes runs in flat memory. live_nodes() (expression.hpp) counts the store's nodes.
using NodeId = std::uint32_t;
// Parametric coordinates are x(0) .. x(kMaxInputs - 1).
inline constexpr int kMaxInputs = 64;

namespace detail {
struct FnAccess;  // the kernel's construction from the store's own references
}

class Fn {
 public:
  // The constant scalar 0.
  Fn();
  // A constant scalar.
  Fn(double value);  // NOLINT(google-explicit-constructor): numbers convert, as in GENMOD
  // Integers convert like doubles.
  template <std::integral I>
    requires(!std::same_as<I, bool>)
  Fn(I value) : Fn(static_cast<double>(value)) {}  // NOLINT(google-explicit-constructor)
  // A bool never becomes a function: `Fn c = (f == g)` with a C++ comparison in it is a
  // mistake, caught at compile time.
  Fn(bool) = delete;
  // A function with the given component nodes (at least one, each live: ids read from an Fn
  // that is alive), taking a reference of its own on each.
  explicit Fn(std::vector<NodeId> components);
  // The scalar function of one node (read from a live Fn, like the constructor's).
  static Fn of(NodeId node) { return Fn(std::vector<NodeId>{node}); }

  // An Fn holds one reference per component: copies add them, destruction gives them back.
  Fn(const Fn& other);
  Fn(Fn&& other) noexcept;
  Fn& operator=(const Fn& other);
  Fn& operator=(Fn&& other) noexcept;
  ~Fn();

  std::size_t dim() const noexcept { return nodes_.size(); }
  NodeId node(std::size_t j) const { return nodes_.at(j); }
  std::span<const NodeId> nodes() const noexcept { return nodes_; }
  // Bit i set if the function depends on x(i).
  std::uint64_t input_mask() const noexcept;
  // The coordinates the function depends on, ascending (GENMOD's input_list).
  std::vector<int> inputs() const;
  // True when this is a scalar constant (returns the value through `value`).
  bool is_constant(double* value = nullptr) const noexcept;

  // Projection onto component j (0-based).
  Fn operator[](std::size_t j) const;

  // True when both handles hold the same nodes (hash-consing makes structurally equal
  // functions identical). Not operator==, which builds the relation.
  friend bool identical(const Fn& a, const Fn& b) noexcept { return a.nodes_ == b.nodes_; }

 private:
  friend struct detail::FnAccess;
  struct Adopt {};
  Fn(Adopt, std::vector<NodeId> owned) noexcept : nodes_(std::move(owned)) {}
  // A function that takes over the new references `owned` (what the store's constructors
  // return; kernel/src/dag.hpp).
  static Fn adopt(std::vector<NodeId> owned);
  static Fn adopt(NodeId owned) { return adopt(std::vector<NodeId>{owned}); }
  void release() noexcept;

  std::vector<NodeId> nodes_;
};

// x(i): the parametric coordinate i, 0 <= i < kMaxInputs.
Fn x(int i);
// Cartesian product: the components of all parts, in order.
Fn cat(std::initializer_list<Fn> parts);
Fn cat(std::span<const Fn> parts);

Fn operator+(const Fn& a, const Fn& b);
Fn operator-(const Fn& a, const Fn& b);
Fn operator*(const Fn& a, const Fn& b);
Fn operator/(const Fn& a, const Fn& b);
Fn operator-(const Fn& a);
inline Fn& operator+=(Fn& a, const Fn& b) { return a = a + b; }
inline Fn& operator-=(Fn& a, const Fn& b) { return a = a - b; }
inline Fn& operator*=(Fn& a, const Fn& b) { return a = a * b; }
inline Fn& operator/=(Fn& a, const Fn& b) { return a = a / b; }

// Relational operators return a scalar 0/1 function: the conjunction of the relation over
// the components (operands of equal dimension, or a scalar broadcast).
Fn operator<(const Fn& a, const Fn& b);
Fn operator<=(const Fn& a, const Fn& b);
Fn operator>(const Fn& a, const Fn& b);
Fn operator>=(const Fn& a, const Fn& b);
// == and != build relations like < does, so `solve(x(0) == 0.5, ...)` is the constraint it
// reads as; identical() compares handles.
Fn eq(const Fn& a, const Fn& b);  // 1 where all components are equal
Fn ne(const Fn& a, const Fn& b);  // 1 where any component differs
inline Fn operator==(const Fn& a, const Fn& b) { return eq(a, b); }
inline Fn operator!=(const Fn& a, const Fn& b) { return ne(a, b); }
// Logical operators on scalars: nonzero is true; results are 0/1.
Fn operator&&(const Fn& a, const Fn& b);
Fn operator||(const Fn& a, const Fn& b);
Fn operator!(const Fn& a);

// Elementary functions apply componentwise.
Fn square(const Fn& a);
Fn sqrt(const Fn& a);
Fn exp(const Fn& a);
Fn log(const Fn& a);
Fn sin(const Fn& a);
Fn cos(const Fn& a);
Fn tan(const Fn& a);
Fn asin(const Fn& a);
Fn acos(const Fn& a);
Fn atan(const Fn& a);
Fn abs(const Fn& a);
Fn floor(const Fn& a);
Fn ceil(const Fn& a);
Fn pow(const Fn& a, const Fn& b);
Fn atan2(const Fn& y, const Fn& x);
Fn min(const Fn& a, const Fn& b);
Fn max(const Fn& a, const Fn& b);
// if-then-else: `cond` is scalar (nonzero is true); the branches broadcast like + does.
Fn select(const Fn& cond, const Fn& then_fn, const Fn& else_fn);
// GENMOD's error(h): 1 where evaluating the scalar h gives an error, else 0.
Fn is_error(const Fn& h);

// d f / d x(i), built symbolically (componentwise).
Fn derivative(const Fn& f, int i);
// GENMOD's m_eval: f with x(i) replaced by the scalar function g.
Fn compose(const Fn& f, int i, const Fn& g);
// GENMOD's m_eval_all: f with x(inputs[k]) replaced by component k of g, all at once.
Fn compose_all(const Fn& f, Coordinates inputs, const Fn& g);

}  // namespace genmod
