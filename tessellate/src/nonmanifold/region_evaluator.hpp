// f_reg for the non-manifold polygonizer: the K region functions compiled into one tape with
// K outputs, evaluated in batches, and the arg-max rule (ties to the lower index, NaN as
// -infinity) that turns their values into a region index. Counts the points evaluated.
#pragma once

#include "genmod/kernel/batch_evaluator.hpp"
#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/tape.hpp"

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace genmod::nonmanifold {

using Point = std::array<double, 3>;

// The region of one point from the K values at it.
int arg_max(const double* values, std::size_t stride, int k);

class RegionEvaluator {
 public:
  // `regions` must be scalar functions of x(0..2) (checked by the caller).
  explicit RegionEvaluator(std::span<const Fn> regions);
  // Another evaluator of the same tape (shared, not recompiled) with its own scratch and a
  // count of 0: one per thread.
  RegionEvaluator worker() const { return RegionEvaluator(k_, tape_); }
  int count_regions() const noexcept { return k_; }
  // Regions of the points, valid until the next call.
  std::span<const int> regions(std::span<const Point> points);
  int region(const Point& p) { return regions(std::span<const Point>(&p, 1))[0]; }
  std::size_t count = 0;  // points evaluated

 private:
  RegionEvaluator(int k, std::shared_ptr<const Tape> tape) : k_(k), tape_(std::move(tape)) {}

  int k_;
  std::shared_ptr<const Tape> tape_;  // immutable, shared by the workers
  BatchEvaluator batch_;
  std::vector<double> values_;
  std::vector<double*> outputs_;
  std::vector<int> out_;
};

}  // namespace genmod::nonmanifold
