#include "nonmanifold/region_evaluator.hpp"

#include <cmath>
#include <limits>

namespace genmod::nonmanifold {

namespace {

std::shared_ptr<const Tape> compile(std::span<const Fn> regions) {
  const int xyz[3] = {0, 1, 2};
  return std::make_shared<const Tape>(cat(regions), xyz);
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
  values_.resize(n * static_cast<std::size_t>(k_));
  out_.resize(n);
  if (n == 0) return {};
  // The points are read in place: coordinate k of point p is points[p][k], a stride of 3.
  static_assert(sizeof(std::array<double, 3>) == 3 * sizeof(double));
  const double* inputs[3] = {&points[0][0], &points[0][1], &points[0][2]};
  outputs_.resize(static_cast<std::size_t>(k_));
  for (int i = 0; i < k_; ++i) outputs_[static_cast<std::size_t>(i)] = values_.data() + static_cast<std::size_t>(i) * n;
  batch_.eval(*tape_, inputs, n, outputs_, 3, 1);
  for (std::size_t p = 0; p < n; ++p) out_[p] = arg_max(values_.data() + p, n, k_);
  count += n;
  return {out_.data(), n};
}

}  // namespace genmod::nonmanifold
