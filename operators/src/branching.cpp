#include "genmod/operators/branching.hpp"

#include "dims.hpp"

#include <vector>

namespace genmod {

Fn error_fn(std::size_t dim) {
  // sqrt(-1) is not constant-folded (folding never hides an error), so it stays an error.
  const Fn e = sqrt(Fn(-1.0));
  std::vector<Fn> parts(dim == 0 ? 1 : dim, e);
  return cat(parts);
}

Fn index(std::span<const Fn> fns, const Fn& q) {
  if (fns.empty()) detail::dimension_error("index", "no functions to choose from");
  if (q.dim() != 1) detail::dimension_error("index", "the index has dimension " + std::to_string(q.dim()) + ", expected 1");
  for (const Fn& f : fns) detail::require_same_dim("index", fns[0].dim(), f.dim());
  // From the last function down: q < i + 1 picks f_i, which also clamps q < 0 to f_0 and
  // q >= n - 1 to f_{n-1}.
  Fn result = fns.back();
  for (std::size_t i = fns.size() - 1; i-- > 0;) result = select(q < static_cast<double>(i + 1), fns[i], result);
  return result;
}

Fn index(std::initializer_list<Fn> fns, const Fn& q) { return index(std::span<const Fn>(fns.begin(), fns.size()), q); }

Fn select_case(std::span<const Fn> guards, std::span<const Fn> evals) {
  if (guards.size() != evals.size())
    detail::dimension_error("select_case", std::to_string(guards.size()) + " guards for " +
                                               std::to_string(evals.size()) + " functions");
  if (evals.empty()) detail::dimension_error("select_case", "no functions to choose from");
  for (const Fn& g : guards)
    if (g.dim() != 1) detail::dimension_error("select_case", "a guard has dimension " + std::to_string(g.dim()));
  for (const Fn& f : evals) detail::require_same_dim("select_case", evals[0].dim(), f.dim());
  Fn result = error_fn(evals[0].dim());
  for (std::size_t i = evals.size(); i-- > 0;) result = select(guards[i], evals[i], result);
  return result;
}

Fn select_case(std::initializer_list<Fn> guards, std::initializer_list<Fn> evals) {
  return select_case(std::span<const Fn>(guards.begin(), guards.size()), std::span<const Fn>(evals.begin(), evals.size()));
}

}  // namespace genmod
