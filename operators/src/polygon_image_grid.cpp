// The sampled convolution image, its min / max pyramid and its lookup operator
// (polygon_image_grid.hpp).
#include "polygon_image_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace genmod {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Smallest L with 2^L >= n.
int levels_for(int n) { return std::bit_width(static_cast<unsigned>(std::max(n, 1) - 1)); }

// Splits the sample range [first, last] into aligned dyadic blocks (level, index): greedy,
// the largest aligned block that starts at `first` and stays inside, at most 2 log2 n blocks.
template <typename F>
void for_each_block(int first, int last, int max_level, F&& f) {
  while (first <= last) {
    int level = 0;
    while (level < max_level && (first & ((2 << level) - 1)) == 0 && first + (2 << level) - 1 <= last) ++level;
    f(level, first >> level);
    first += 1 << level;
  }
}

class ImageLookupOp final : public CustomOp {
 public:
  explicit ImageLookupOp(std::shared_ptr<const ConvolutionImage::Grid> grid) : grid_(std::move(grid)) {}
  std::string name() const override { return "polygon_image"; }
  int num_args() const override { return 2; }
  int num_outputs() const override { return 1; }
  void eval(std::span<const double> args, std::span<double> out) const override { out[0] = grid_->eval(args[0], args[1]); }
  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t>) const override {
    out[0] = grid_->range(args[0], args[1]);
  }
  Fn derivative(std::span<const Fn> args, int k) const override {
    const auto op = grid_->derivative_op(k);
    if (!op) return Fn(0.0);
    return apply_custom(op, args);
  }
  bool continuous() const override { return grid_->continuous(); }

 private:
  std::shared_ptr<const ConvolutionImage::Grid> grid_;
};

}  // namespace

std::shared_ptr<const CustomOp> make_image_lookup_op(std::shared_ptr<const ConvolutionImage::Grid> grid) {
  return std::make_shared<ImageLookupOp>(std::move(grid));
}

ConvolutionImage::Grid::Grid(std::array<int, 2> size, std::array<bool, 2> is_constant, std::vector<double> values)
    : n(size), constant(is_constant), samples(std::move(values)) {
  for (int a = 0; a < 2; ++a)
    if (n[a] < (constant[a] ? 1 : 2)) throw std::invalid_argument("polygon_convolution: image grid too small");
  if (samples.size() != static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]))
    throw std::invalid_argument("polygon_convolution: image sample count does not match its size");
  double m = 0;
  for (double s : samples) {
    if (!std::isfinite(s)) throw std::invalid_argument("polygon_convolution: an image sample is not finite");
    m = std::max(m, std::abs(s));
  }
  // The interpolant (1-fu)((1-fv) s00 + fv s01) + fu((1-fv) s10 + fv s11): a few roundings of
  // terms no larger than m, each within an ulp of m.
  pad_ = 16 * std::numeric_limits<double>::epsilon() * m + std::numeric_limits<double>::denorm_min();

  continuous_ = !constant[0] && !constant[1];
  for (int i = 0; i < n[0] && continuous_; ++i) continuous_ = at(i, 0) == 0 && at(i, n[1] - 1) == 0;
  for (int j = 0; j < n[1] && continuous_; ++j) continuous_ = at(0, j) == 0 && at(n[0] - 1, j) == 0;

  // The ripmap: level (a, 0) halves level (a - 1, 0) along axis 0; level (a, b) halves
  // level (a, b - 1) along axis 1.
  levels_ = {levels_for(n[0]), levels_for(n[1])};
  const int stride = levels_[1] + 1;
  min_.resize(static_cast<std::size_t>((levels_[0] + 1) * stride));
  max_.resize(min_.size());
  min_[0] = samples;
  max_[0] = samples;
  auto height = [&](int b) { return (n[1] + (1 << b) - 1) >> b; };
  for (int a = 0; a <= levels_[0]; ++a) {
    for (int b = 0; b <= levels_[1]; ++b) {
      if (a == 0 && b == 0) continue;
      const int w = level_width(a), h = height(b);
      std::vector<double>& lo = min_[static_cast<std::size_t>(a * stride + b)];
      std::vector<double>& hi = max_[static_cast<std::size_t>(a * stride + b)];
      lo.assign(static_cast<std::size_t>(w) * h, kInf);
      hi.assign(lo.size(), -kInf);
      // The parent level and the step along the halved axis.
      const bool along0 = b == 0;
      const int pa = along0 ? a - 1 : a, pb = along0 ? b : b - 1;
      const int pw = level_width(pa), ph = height(pb);
      const std::vector<double>& plo = min_[static_cast<std::size_t>(pa * stride + pb)];
      const std::vector<double>& phi = max_[static_cast<std::size_t>(pa * stride + pb)];
      for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
          const std::size_t dst = static_cast<std::size_t>(j) * w + i;
          for (int c = 0; c < 2; ++c) {
            const int si = along0 ? 2 * i + c : i, sj = along0 ? j : 2 * j + c;
            if (si >= pw || sj >= ph) continue;
            const std::size_t src = static_cast<std::size_t>(sj) * pw + si;
            lo[dst] = std::min(lo[dst], plo[src]);
            hi[dst] = std::max(hi[dst], phi[src]);
          }
        }
    }
  }
}

int ConvolutionImage::Grid::cell(int axis, double t) const noexcept {
  const int last = constant[axis] ? n[axis] - 1 : n[axis] - 2;
  return std::clamp(static_cast<int>(std::floor(t)), 0, last);
}

double ConvolutionImage::Grid::eval(double u, double v) const {
  if (std::isnan(u) || std::isnan(v)) return std::numeric_limits<double>::quiet_NaN();
  if (!(u >= 0 && u <= domain(0) && v >= 0 && v <= domain(1))) return 0.0;
  const int i = cell(0, u), j = cell(1, v);
  const double fu = constant[0] ? 0.0 : u - i, fv = constant[1] ? 0.0 : v - j;
  const int i1 = constant[0] ? i : i + 1, j1 = constant[1] ? j : j + 1;
  const double lower = (1 - fu) * at(i, j) + fu * at(i1, j);
  const double upper = (1 - fu) * at(i, j1) + fu * at(i1, j1);
  return (1 - fv) * lower + fv * upper;
}

void ConvolutionImage::Grid::hull(int i0, int i1, int j0, int j1, double& lo, double& hi) const {
  const int stride = levels_[1] + 1;
  for_each_block(i0, i1, levels_[0], [&](int a, int bi) {
    const int w = level_width(a);
    for_each_block(j0, j1, levels_[1], [&](int b, int bj) {
      const std::size_t k = static_cast<std::size_t>(a * stride + b), idx = static_cast<std::size_t>(bj) * w + bi;
      lo = std::min(lo, min_[k][idx]);
      hi = std::max(hi, max_[k][idx]);
    });
  });
}

Interval ConvolutionImage::Grid::range(const Interval& u, const Interval& v) const {
  if (u.is_empty() || v.is_empty()) return Interval::empty();
  bool leaves = false;
  int first[2], last[2];
  const Interval box[2] = {u, v};
  for (int a = 0; a < 2; ++a) {
    const double lo = std::max(box[a].lo(), 0.0), hi = std::min(box[a].hi(), domain(a));
    if (lo > hi) return Interval(0.0);  // the box misses the image: 0 throughout
    leaves |= box[a].lo() < 0 || box[a].hi() > domain(a);
    // Every point evaluated in [lo, hi] reads the samples of its cell, and cells are
    // monotone in the coordinate: the cells from lo's to hi's, with the upper node of the
    // last along a bilinear axis.
    first[a] = cell(a, lo);
    last[a] = cell(a, hi) + (constant[a] ? 0 : 1);
  }
  double lo = kInf, hi = -kInf;
  hull(first[0], last[0], first[1], last[1], lo, hi);
  if (leaves) lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
  // The pad keeps 0 exact when every touched sample is 0 (pad_ only grows a nonzero hull).
  if (lo == 0 && hi == 0) return Interval(0.0);
  return Interval(lo - pad_, hi + pad_);
}

std::shared_ptr<const ConvolutionImage::Grid> ConvolutionImage::Grid::derivative(int axis) const {
  std::call_once(once_[axis], [&] {
    if (constant[axis]) return;  // identically 0
    std::array<int, 2> size = n;
    size[axis] -= 1;
    std::array<bool, 2> c = constant;
    c[axis] = true;
    std::vector<double> d(static_cast<std::size_t>(size[0]) * size[1]);
    for (int j = 0; j < size[1]; ++j)
      for (int i = 0; i < size[0]; ++i)
        d[static_cast<std::size_t>(j) * size[0] + i] = axis == 0 ? at(i + 1, j) - at(i, j) : at(i, j + 1) - at(i, j);
    derivative_[axis] = std::make_shared<const Grid>(size, c, std::move(d));
    derivative_op_[axis] = make_image_lookup_op(derivative_[axis]);
  });
  return derivative_[axis];
}

std::shared_ptr<const CustomOp> ConvolutionImage::Grid::derivative_op(int axis) const {
  derivative(axis);
  return derivative_op_[axis];
}

}  // namespace genmod
