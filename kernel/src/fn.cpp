// Fn construction: operators, broadcasting and the elementary functions.
#include "genmod/kernel/fn.hpp"

#include "genmod/kernel/custom_op.hpp"

#include "dag.hpp"

#include <stdexcept>
#include <string>

namespace genmod {
namespace {

std::vector<NodeId> map1(Op op, const Fn& a) {
  std::vector<NodeId> out;
  out.reserve(a.dim());
  for (NodeId n : a.nodes()) out.push_back(dag::make(op, n));
  return out;
}

// Componentwise with scalar broadcast (GENMOD's two modes for binary operators).
std::vector<NodeId> map2(Op op, const Fn& a, const Fn& b, const char* what) {
  const std::size_t m = std::max(a.dim(), b.dim());
  if (a.dim() != b.dim() && a.dim() != 1 && b.dim() != 1)
    throw std::invalid_argument(std::string("genmod: ") + what + ": operand dimensions " + std::to_string(a.dim()) +
                                " and " + std::to_string(b.dim()) + " do not match (and neither is scalar)");
  std::vector<NodeId> out;
  out.reserve(m);
  for (std::size_t j = 0; j < m; ++j)
    out.push_back(dag::make(op, a.node(a.dim() == 1 ? 0 : j), b.node(b.dim() == 1 ? 0 : j)));
  return out;
}

// A relation over vectors is the conjunction of the componentwise relations.
Fn relation(Op op, const Fn& a, const Fn& b, const char* what) {
  const Fn parts = detail::FnAccess::adopt(map2(op, a, b, what));
  Fn acc = parts[0];
  for (std::size_t j = 1; j < parts.dim(); ++j)
    acc = detail::FnAccess::adopt(dag::make(op == Op::Ne ? Op::Or : Op::And, acc.node(0), parts.node(j)));
  return acc;
}

NodeId scalar(const Fn& f, const char* what) {
  if (f.dim() != 1)
    throw std::invalid_argument(std::string("genmod: ") + what + " needs a scalar operand, got dimension " +
                                std::to_string(f.dim()));
  return f.node(0);
}

}  // namespace

Fn::Fn() : nodes_{dag::constant(0.0)} {}
Fn::Fn(double value) : nodes_{dag::constant(value)} {}
Fn::Fn(std::vector<NodeId> components) : nodes_(std::move(components)) {
  if (nodes_.empty()) throw std::invalid_argument("genmod: an Fn needs at least one component");
  for (NodeId n : nodes_)
    if (!dag::is_live(n)) throw std::invalid_argument("genmod: Fn component " + std::to_string(n) + " is not a node");
  for (NodeId n : nodes_) dag::retain(n);
}

Fn Fn::adopt(std::vector<NodeId> owned) {
  if (owned.empty()) throw std::invalid_argument("genmod: an Fn needs at least one component");
  return Fn(Adopt{}, std::move(owned));
}

Fn::Fn(const Fn& other) : nodes_(other.nodes_) {
  for (NodeId n : nodes_) dag::retain(n);
}
Fn::Fn(Fn&& other) noexcept : nodes_(std::move(other.nodes_)) {}
Fn& Fn::operator=(const Fn& other) {
  if (this != &other) {
    for (NodeId n : other.nodes_) dag::retain(n);  // before releasing: other may share them
    release();
    nodes_ = other.nodes_;
  }
  return *this;
}
Fn& Fn::operator=(Fn&& other) noexcept {
  if (this != &other) {
    release();
    nodes_ = std::move(other.nodes_);
    other.nodes_.clear();
  }
  return *this;
}
Fn::~Fn() { release(); }
void Fn::release() noexcept {
  for (NodeId n : nodes_) dag::release(n);
  nodes_.clear();
}

std::uint64_t Fn::input_mask() const noexcept {
  std::uint64_t m = 0;
  for (NodeId n : nodes_) m |= dag::node(n).inputs;
  return m;
}

std::vector<int> Fn::inputs() const {
  std::vector<int> out;
  const std::uint64_t m = input_mask();
  for (int i = 0; i < kMaxInputs; ++i)
    if (m >> i & 1u) out.push_back(i);
  return out;
}

bool Fn::is_constant(double* value) const noexcept {
  if (nodes_.size() != 1 || dag::node(nodes_[0]).op != Op::Const) return false;
  if (value) *value = dag::node(nodes_[0]).value;
  return true;
}

Fn Fn::operator[](std::size_t j) const {
  if (j >= nodes_.size())
    throw std::out_of_range("genmod: projection [" + std::to_string(j) + "] of a function of dimension " +
                            std::to_string(nodes_.size()));
  return Fn::of(nodes_[j]);
}

Fn x(int i) { return detail::FnAccess::adopt(dag::var(i)); }

Fn cat(std::span<const Fn> parts) {
  std::vector<NodeId> out;
  for (const Fn& p : parts) out.insert(out.end(), p.nodes().begin(), p.nodes().end());
  return Fn(std::move(out));
}
Fn cat(std::initializer_list<Fn> parts) { return cat(std::span<const Fn>(parts.begin(), parts.size())); }

Fn operator+(const Fn& a, const Fn& b) { return detail::FnAccess::adopt(map2(Op::Add, a, b, "+")); }
Fn operator-(const Fn& a, const Fn& b) { return detail::FnAccess::adopt(map2(Op::Sub, a, b, "-")); }
Fn operator*(const Fn& a, const Fn& b) { return detail::FnAccess::adopt(map2(Op::Mul, a, b, "*")); }
Fn operator/(const Fn& a, const Fn& b) { return detail::FnAccess::adopt(map2(Op::Div, a, b, "/")); }
Fn operator-(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Neg, a)); }
Fn pow(const Fn& a, const Fn& b) { return detail::FnAccess::adopt(map2(Op::Pow, a, b, "pow")); }
Fn atan2(const Fn& y, const Fn& x) { return detail::FnAccess::adopt(map2(Op::Atan2, y, x, "atan2")); }
Fn min(const Fn& a, const Fn& b) { return detail::FnAccess::adopt(map2(Op::Min, a, b, "min")); }
Fn max(const Fn& a, const Fn& b) { return detail::FnAccess::adopt(map2(Op::Max, a, b, "max")); }

Fn operator<(const Fn& a, const Fn& b) { return relation(Op::Lt, a, b, "<"); }
Fn operator<=(const Fn& a, const Fn& b) { return relation(Op::Le, a, b, "<="); }
Fn operator>(const Fn& a, const Fn& b) { return relation(Op::Gt, a, b, ">"); }
Fn operator>=(const Fn& a, const Fn& b) { return relation(Op::Ge, a, b, ">="); }
Fn eq(const Fn& a, const Fn& b) { return relation(Op::Eq, a, b, "=="); }
Fn ne(const Fn& a, const Fn& b) { return relation(Op::Ne, a, b, "!="); }

Fn operator&&(const Fn& a, const Fn& b) { return detail::FnAccess::adopt(dag::make(Op::And, scalar(a, "&&"), scalar(b, "&&"))); }
Fn operator||(const Fn& a, const Fn& b) { return detail::FnAccess::adopt(dag::make(Op::Or, scalar(a, "||"), scalar(b, "||"))); }
Fn operator!(const Fn& a) { return detail::FnAccess::adopt(dag::make(Op::Not, scalar(a, "!"))); }

Fn square(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Square, a)); }
Fn sqrt(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Sqrt, a)); }
Fn exp(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Exp, a)); }
Fn log(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Log, a)); }
Fn sin(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Sin, a)); }
Fn cos(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Cos, a)); }
Fn tan(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Tan, a)); }
Fn asin(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Asin, a)); }
Fn acos(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Acos, a)); }
Fn atan(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Atan, a)); }
Fn abs(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Abs, a)); }
Fn floor(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Floor, a)); }
Fn ceil(const Fn& a) { return detail::FnAccess::adopt(map1(Op::Ceil, a)); }
Fn is_error(const Fn& h) { return detail::FnAccess::adopt(dag::make(Op::IsError, scalar(h, "is_error"))); }

Fn select(const Fn& cond, const Fn& then_fn, const Fn& else_fn) {
  const NodeId c = scalar(cond, "select condition");
  const std::size_t m = std::max(then_fn.dim(), else_fn.dim());
  if (then_fn.dim() != else_fn.dim() && then_fn.dim() != 1 && else_fn.dim() != 1)
    throw std::invalid_argument("genmod: select: branch dimensions " + std::to_string(then_fn.dim()) + " and " +
                                std::to_string(else_fn.dim()) + " do not match");
  std::vector<NodeId> out;
  for (std::size_t j = 0; j < m; ++j)
    out.push_back(dag::make(Op::Select, c, then_fn.node(then_fn.dim() == 1 ? 0 : j),
                            else_fn.node(else_fn.dim() == 1 ? 0 : j)));
  return detail::FnAccess::adopt(std::move(out));
}

Fn apply_custom(const std::shared_ptr<const CustomOp>& op, std::span<const Fn> args) {
  std::vector<NodeId> arg_nodes;
  for (const Fn& a : args) arg_nodes.push_back(scalar(a, "a custom operator argument"));
  // The registration's reference keeps the operator alive until its nodes hold it.
  const std::uint32_t id = dag::register_custom(op);
  std::vector<NodeId> out;
  try {
    for (int j = 0; j < op->num_outputs(); ++j) out.push_back(dag::make_custom(id, j, arg_nodes));
  } catch (...) {
    for (NodeId n : out) dag::release(n);
    dag::release_custom(id);
    throw;
  }
  dag::release_custom(id);
  return detail::FnAccess::adopt(std::move(out));
}

Fn apply_custom(const std::shared_ptr<const CustomOp>& op, std::initializer_list<Fn> args) {
  return apply_custom(op, std::span<const Fn>(args.begin(), args.size()));
}

}  // namespace genmod
