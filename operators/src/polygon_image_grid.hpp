// Private: the sampled image behind polygon_convolution.hpp's lookup operator, and the
// operator itself.
//
// A grid is a 2-D array of samples over image coordinates [0, D0] x [0, D1]; along each axis
// it is either bilinear between nodes at the integers (n nodes, D = n - 1) or piecewise
// constant over unit cells (n cells, D = n), which is what differentiating a linear axis
// gives. Outside the domain the grid is 0. The min / max pyramid holds, for every pair of
// levels (a, b), the minimum and maximum over aligned blocks of 2^a x 2^b samples (a
// "ripmap"); a sample rectangle is the union of at most 2 log2 n aligned dyadic intervals per
// axis, so its exact hull costs O(log^2 n) reads.
#pragma once

#include "genmod/kernel/custom_op.hpp"
#include "genmod/operators/polygon_convolution.hpp"

#include <array>
#include <memory>
#include <mutex>
#include <vector>

namespace genmod {

struct ConvolutionImage::Grid {
  // samples[j * n[0] + i]; constant[a]: axis a is piecewise constant over cells.
  Grid(std::array<int, 2> n, std::array<bool, 2> constant, std::vector<double> samples);

  double eval(double u, double v) const;
  Interval range(const Interval& u, const Interval& v) const;
  // The hull [lo, hi] of the samples i0..i1 x j0..j1 (inclusive, inside the grid).
  void hull(int i0, int i1, int j0, int j1, double& lo, double& hi) const;
  // The partial derivative along `axis` as a grid; null where it is identically 0 (a constant
  // axis). Built once, on first use.
  std::shared_ptr<const Grid> derivative(int axis) const;
  // The lookup operator of the derivative grid along `axis` (null: identically 0).
  std::shared_ptr<const CustomOp> derivative_op(int axis) const;
  // Continuous: both axes bilinear and the samples on the border 0 (so the zero extension
  // outside the image does not jump).
  bool continuous() const noexcept { return continuous_; }
  double domain(int axis) const noexcept { return constant[axis] ? n[axis] : n[axis] - 1; }
  double at(int i, int j) const { return samples[static_cast<std::size_t>(j) * n[0] + i]; }

  std::array<int, 2> n;
  std::array<bool, 2> constant;
  std::vector<double> samples;

 private:
  // The cell holding coordinate t in [0, domain]: the lower node (linear) or the cell.
  int cell(int axis, double t) const noexcept;
  const std::vector<double>& level_min(int a, int b) const { return min_[a * (levels_[1] + 1) + b]; }
  const std::vector<double>& level_max(int a, int b) const { return max_[a * (levels_[1] + 1) + b]; }
  int level_width(int a) const noexcept { return (n[0] + (1 << a) - 1) >> a; }

  std::array<int, 2> levels_{};
  std::vector<std::vector<double>> min_, max_;
  double pad_ = 0;  // rounding allowance of the interpolation
  bool continuous_ = false;
  mutable std::once_flag once_[2];
  mutable std::shared_ptr<const Grid> derivative_[2];
  mutable std::shared_ptr<const CustomOp> derivative_op_[2];
};

// The lookup operator: 2 arguments (image coordinates u, v), 1 output.
std::shared_ptr<const CustomOp> make_image_lookup_op(std::shared_ptr<const ConvolutionImage::Grid> grid);

}  // namespace genmod
