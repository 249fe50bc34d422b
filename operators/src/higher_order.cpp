#include "genmod/operators/higher_order.hpp"

#include "dims.hpp"
#include "genmod/operators/branching.hpp"

#include <vector>

namespace genmod {

Fn interp(const Fn& t, const Fn& a, const Fn& b) {
  if (t.dim() != 1) detail::dimension_error("interp", "t has dimension " + std::to_string(t.dim()) + ", expected 1");
  detail::require_same_dim("interp", a.dim(), b.dim());
  return a + (b - a) * t;
}

Fn concat(int parm, const Fn& in, std::span<const Fn> fns) {
  if (fns.empty()) detail::dimension_error("concat", "no functions to concatenate");
  if (in.dim() != 1) detail::dimension_error("concat", "the parameter has dimension " + std::to_string(in.dim()));
  const double n = static_cast<double>(fns.size());
  const Fn scaled = in * n;
  std::vector<Fn> pieces;
  for (std::size_t i = 0; i < fns.size(); ++i) {
    const Fn local = min(max(scaled - static_cast<double>(i), 0.0), 1.0);
    pieces.push_back(compose(fns[i], parm, local));
  }
  return index(pieces, scaled);
}

Fn concat(int parm, const Fn& in, std::initializer_list<Fn> fns) {
  return concat(parm, in, std::span<const Fn>(fns.begin(), fns.size()));
}

Fn hermite_interp(const Fn& alpha, const Fn& p1, const Fn& p2, const Fn& t1, const Fn& t2) {
  if (alpha.dim() != 1) detail::dimension_error("hermite_interp", "alpha must be scalar");
  detail::require_same_dim("hermite_interp", p1.dim(), p2.dim());
  detail::require_same_dim("hermite_interp", p1.dim(), t1.dim());
  detail::require_same_dim("hermite_interp", p1.dim(), t2.dim());
  // Horner form of a a^3 + b a^2 + c a + d (thesis section 3.1.2.1.2).
  const Fn a = t2 + t1 + 2.0 * (p1 - p2);
  const Fn b = 3.0 * (p2 - p1) - 2.0 * t1 - t2;
  return ((a * alpha + b) * alpha + t1) * alpha + p1;
}

}  // namespace genmod
