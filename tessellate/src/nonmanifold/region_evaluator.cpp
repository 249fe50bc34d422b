#include "nonmanifold/region_evaluator.hpp"

#include <cmath>
#include <limits>

namespace genmod::nonmanifold {

namespace {

Tape compile(std::span<const Fn> regions) {
  const int xyz[3] = {0, 1, 2};
  return Tape(cat(regions), xyz);
}

}  // namespace

int arg_max(const double* values, std::size_t stride, int k) {
  int best = 0;
  double best_value = -std::numeric_limits<double>::infinity();
  bool any = false;
  for (int i = 0; i < k; ++i) {
    const double v = values[static_cast<std::size_t>(i) * stride];
    if (std::isnan(v)) continue;
    if (!any || v > best_value) {
      best = i;
      best_value = v;
      any = true;
    }
  }
  return best;
}

RegionEvaluator::RegionEvaluator(std::span<const Fn> regions)
    : k_(static_cast<int>(regions.size())), tape_(compile(regions)) {}

std::span<const int> RegionEvaluator::regions(std::span<const Point> points) {
  const std::size_t n = points.size();
  x_.resize(n);
  y_.resize(n);
  z_.resize(n);
  values_.resize(n * static_cast<std::size_t>(k_));
  out_.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    x_[p] = points[p][0];
    y_[p] = points[p][1];
    z_[p] = points[p][2];
  }
  const double* inputs[3] = {x_.data(), y_.data(), z_.data()};
  outputs_.resize(static_cast<std::size_t>(k_));
  for (int i = 0; i < k_; ++i) outputs_[static_cast<std::size_t>(i)] = values_.data() + static_cast<std::size_t>(i) * n;
  if (n > 0) batch_.eval(tape_, inputs, n, outputs_);
  for (std::size_t p = 0; p < n; ++p) out_[p] = arg_max(values_.data() + p, n, k_);
  count += n;
  return {out_.data(), n};
}

}  // namespace genmod::nonmanifold
