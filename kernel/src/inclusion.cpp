#include "genmod/kernel/inclusion.hpp"

#include <algorithm>

namespace genmod {
namespace {

Fn jacobian(const Fn& f, std::span<const int> inputs) {
  std::vector<Fn> parts;
  for (std::size_t j = 0; j < f.dim(); ++j)
    for (int i : inputs) parts.push_back(derivative(f[j], i));
  return cat(parts);
}

}  // namespace

InclusionFunction::InclusionFunction(const Fn& f) : InclusionFunction(f, f.inputs()) {}

InclusionFunction::InclusionFunction(const Fn& f, Coordinates inputs)
    : f_(f, inputs), jacobian_(inputs.empty() ? Fn(0.0) : jacobian(f, inputs), inputs) {}

std::vector<Interval> InclusionFunction::eval(std::span<const Interval> box, unsigned forms,
                                              std::vector<Interval>* jacobian) {
  const std::size_t n = box.size(), m = f_.num_outputs();
  if (jacobian) jacobian->clear();
  const auto natural = ev_.eval(f_, box);
  std::vector<Interval> result(natural.begin(), natural.end());
  errors_.assign(ev_.errors().begin(), ev_.errors().end());
  const bool continuous = ev_.continuous();
  const bool bounded = std::all_of(box.begin(), box.end(), [](const Interval& x) { return x.is_bounded(); });
  const bool want_jacobian = jacobian || (forms & (kMeanValueForm | kMonotonicityForm));
  if (!want_jacobian || !continuous || n == 0 || !bounded) return result;

  // Jacobian enclosure over the box; the forms are valid only if it has no possible error.
  const auto jac_span = ev_.eval(jacobian_, box);
  const std::vector<Interval> jac(jac_span.begin(), jac_span.end());
  if (std::any_of(ev_.errors().begin(), ev_.errors().end(), [](std::uint8_t e) { return e != kNoError; }))
    return result;
  if (jacobian) *jacobian = jac;

  if (forms & kMeanValueForm) {
    std::vector<Interval> center(n);
    for (std::size_t i = 0; i < n; ++i) center[i] = Interval(box[i].mid());
    const auto at_center = ev_.eval(f_, center);
    const std::vector<Interval> fc(at_center.begin(), at_center.end());
    for (std::size_t j = 0; j < m; ++j) {
      Interval mv = fc[j];
      for (std::size_t i = 0; i < n; ++i) mv = mv + jac[j * n + i] * (box[i] - center[i]);
      result[j] = intersect(result[j], mv);
    }
  }
  if (forms & kMonotonicityForm) {
    for (std::size_t j = 0; j < m; ++j) {
      std::vector<Interval> low_face(box.begin(), box.end()), high_face(box.begin(), box.end());
      bool monotone = false;
      for (std::size_t i = 0; i < n; ++i) {
        const Interval& d = jac[j * n + i];
        if (d.lo() >= 0.0) {  // nondecreasing in input i
          low_face[i] = Interval(box[i].lo());
          high_face[i] = Interval(box[i].hi());
          monotone = true;
        } else if (d.hi() <= 0.0) {  // nonincreasing
          low_face[i] = Interval(box[i].hi());
          high_face[i] = Interval(box[i].lo());
          monotone = true;
        }
      }
      if (!monotone) continue;
      const double lo = ev_.eval(f_, low_face)[j].lo();
      const double hi = ev_.eval(f_, high_face)[j].hi();
      if (lo <= hi) result[j] = intersect(result[j], Interval::unchecked(lo, hi));
    }
  }
  return result;
}

}  // namespace genmod
