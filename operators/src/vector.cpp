#include "genmod/operators/vector.hpp"

#include "dims.hpp"

namespace genmod {

Fn dot(const Fn& f, const Fn& g) {
  detail::require_same_dim("dot", f.dim(), g.dim());
  Fn sum = f[0] * g[0];
  for (std::size_t k = 1; k < f.dim(); ++k) sum = sum + f[k] * g[k];
  return sum;
}

Fn length(const Fn& f) {
  // |f| for scalars keeps the derivative defined at 0 from either side (sign), where
  // sqrt(f^2) would be an error.
  if (f.dim() == 1) return abs(f);
  Fn sum = square(f[0]);
  for (std::size_t k = 1; k < f.dim(); ++k) sum = sum + square(f[k]);
  return sqrt(sum);
}

Fn cross(const Fn& f, const Fn& g) {
  if (f.dim() != 3 || g.dim() != 3)
    detail::dimension_error("cross", "operands have dimensions " + std::to_string(f.dim()) + " and " +
                                         std::to_string(g.dim()) + ", expected 3 and 3");
  return cat({f[1] * g[2] - f[2] * g[1], f[2] * g[0] - f[0] * g[2], f[0] * g[1] - f[1] * g[0]});
}

Fn normalize(const Fn& f) { return f / length(f); }

}  // namespace genmod
