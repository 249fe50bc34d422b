#include "genmod/operators/table.hpp"

#include "genmod/kernel/custom_op.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxTableDims = 8;
constexpr std::size_t kMaxCellsPerInclusion = 4096;

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument("genmod: table: " + what); }

// A table whose dimension k is either multilinear between size_[k] nodes or piecewise
// constant over size_[k] equal cells (what differentiation produces).
class TableOp final : public CustomOp {
 public:
  TableOp(int width, std::vector<int> size, std::vector<bool> constant, std::vector<double> values)
      : width_(width), size_(std::move(size)), constant_(std::move(constant)), values_(std::move(values)),
        derivatives_(size_.size()) {
    double m = 0.0;
    lo_.assign(static_cast<std::size_t>(width_), std::numeric_limits<double>::infinity());
    hi_.assign(static_cast<std::size_t>(width_), -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < values_.size(); ++i) {
      m = std::max(m, std::abs(values_[i]));
      const std::size_t j = i % static_cast<std::size_t>(width_);
      lo_[j] = std::min(lo_[j], values_[i]);
      hi_[j] = std::max(hi_[j], values_[i]);
    }
    // Interpolation forms sum_corners (prod of weights) * value: each weight is a product
    // of at most s factors and the sum has at most 2^s terms, each step off by an ulp.
    const double s = static_cast<double>(size_.size());
    pad_ = 4.0 * (s + 2.0 + std::ldexp(1.0, static_cast<int>(size_.size()))) * std::numeric_limits<double>::epsilon() * m +
           std::numeric_limits<double>::denorm_min();
    stride_.resize(size_.size());
    std::size_t st = static_cast<std::size_t>(width_);
    for (std::size_t k = 0; k < size_.size(); ++k) {
      stride_[k] = st;
      st *= static_cast<std::size_t>(size_[k]);
    }
  }

  std::string name() const override { return "table"; }
  int num_args() const override { return static_cast<int>(size_.size()); }
  int num_outputs() const override { return width_; }

  void eval(std::span<const double> args, std::span<double> out) const override {
    int cell[kMaxTableDims];
    double frac[kMaxTableDims];
    for (std::size_t k = 0; k < size_.size(); ++k) {
      if (!(args[k] >= 0.0 && args[k] <= 1.0)) {
        std::fill(out.begin(), out.end(), kNaN);
        return;
      }
      cell[k] = cell_of(k, args[k]);
      frac[k] = constant_[k] ? 0.0 : args[k] * (size_[k] - 1) - cell[k];
    }
    interpolate(cell, frac, out.data());
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    const std::size_t s = size_.size();
    int first[kMaxTableDims], last[kMaxTableDims];
    double a[kMaxTableDims], b[kMaxTableDims];
    std::size_t cells = 1;
    bool maybe_outside = false;
    for (std::size_t k = 0; k < s; ++k) {
      if (args[k].is_empty()) {
        std::fill(out.begin(), out.end(), Interval::empty());
        return;
      }
      a[k] = std::max(args[k].lo(), 0.0);
      b[k] = std::min(args[k].hi(), 1.0);
      if (a[k] > b[k]) {
        std::fill(out.begin(), out.end(), Interval::empty());
        for (auto& e : err) e |= kCertainError;
        return;
      }
      maybe_outside |= args[k].lo() < 0.0 || args[k].hi() > 1.0;
      first[k] = cell_of(k, a[k]);
      last[k] = cell_of(k, b[k]);
      cells *= static_cast<std::size_t>(last[k] - first[k] + 1);
    }
    if (maybe_outside)
      for (auto& e : err) e |= kMaybeError;
    const std::size_t w = static_cast<std::size_t>(width_);
    std::vector<double> lo(w, std::numeric_limits<double>::infinity()), hi(w, -std::numeric_limits<double>::infinity());
    if (cells > kMaxCellsPerInclusion) {
      lo = lo_;  // the hull of all samples is always valid
      hi = hi_;
    } else {
      int cell[kMaxTableDims];
      std::copy_n(first, s, cell);
      double v[64];
      for (;;) {
        // The fractional range of the box inside this cell, per multilinear dimension,
        // computed exactly as eval() computes fractions (so monotone rounding keeps every
        // evaluated fraction inside it).
        double flo[kMaxTableDims], fhi[kMaxTableDims];
        for (std::size_t k = 0; k < s; ++k) {
          if (constant_[k]) {
            flo[k] = fhi[k] = 0.0;
            continue;
          }
          const double n1 = size_[k] - 1;
          flo[k] = cell[k] == first[k] ? a[k] * n1 - cell[k] : 0.0;
          fhi[k] = cell[k] == last[k] ? b[k] * n1 - cell[k] : 1.0;
        }
        for (unsigned corner = 0; corner < (1u << s); ++corner) {
          double frac[kMaxTableDims];
          for (std::size_t k = 0; k < s; ++k) frac[k] = (corner >> k & 1u) ? fhi[k] : flo[k];
          interpolate(cell, frac, v);
          for (std::size_t j = 0; j < w; ++j) lo[j] = std::min(lo[j], v[j]), hi[j] = std::max(hi[j], v[j]);
        }
        std::size_t k = 0;
        while (k < s && cell[k] == last[k]) cell[k] = first[k], ++k;
        if (k == s) break;
        ++cell[k];
      }
    }
    for (std::size_t j = 0; j < w; ++j) out[j] = Interval(lo[j] - pad_, hi[j] + pad_);
  }

  Fn derivative(std::span<const Fn> args, int k) const override {
    const std::size_t ku = static_cast<std::size_t>(k);
    if (constant_[ku]) return cat(std::vector<Fn>(static_cast<std::size_t>(width_), Fn(0.0)));
    std::shared_ptr<const TableOp> d;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!derivatives_[ku]) derivatives_[ku] = difference_table(ku);
      d = derivatives_[ku];
    }
    return genmod::apply_custom(std::shared_ptr<const CustomOp>(d), args);
  }

 private:
  int cell_of(std::size_t k, double u) const {
    if (constant_[k]) return std::min(static_cast<int>(std::floor(u * size_[k])), size_[k] - 1);
    return std::min(static_cast<int>(std::floor(u * (size_[k] - 1))), size_[k] - 2);
  }

  // sum over the corners of the cell of (product of weights) * node values; constant
  // dimensions use the cell's own value.
  void interpolate(const int* cell, const double* frac, double* out) const {
    const std::size_t s = size_.size(), w = static_cast<std::size_t>(width_);
    std::fill_n(out, w, 0.0);
    for (unsigned corner = 0; corner < (1u << s); ++corner) {
      double weight = 1.0;
      std::size_t offset = 0;
      bool skip = false;
      for (std::size_t k = 0; k < s; ++k) {
        const bool up = corner >> k & 1u;
        if (constant_[k]) {
          if (up) skip = true;
          offset += stride_[k] * static_cast<std::size_t>(cell[k]);
          continue;
        }
        weight *= up ? frac[k] : 1.0 - frac[k];
        offset += stride_[k] * static_cast<std::size_t>(cell[k] + (up ? 1 : 0));
      }
      if (skip) continue;
      for (std::size_t j = 0; j < w; ++j) out[j] += weight * values_[offset + j];
    }
  }

  std::shared_ptr<const TableOp> difference_table(std::size_t k) const {
    std::vector<int> size = size_;
    size[k] -= 1;
    std::vector<bool> constant = constant_;
    constant[k] = true;
    std::size_t count = static_cast<std::size_t>(width_);
    for (int n : size) count *= static_cast<std::size_t>(n);
    std::vector<double> d(count);
    const double scale = size_[k] - 1;
    // Walk the new layout; the node above along k is one stride_[k] further in the old one.
    for (std::size_t i = 0; i < count; ++i) {
      std::size_t rest = i;
      std::size_t old = rest % static_cast<std::size_t>(width_);
      rest /= static_cast<std::size_t>(width_);
      for (std::size_t m = 0; m < size.size(); ++m) {
        const std::size_t idx = rest % static_cast<std::size_t>(size[m]);
        rest /= static_cast<std::size_t>(size[m]);
        old += idx * stride_[m];
      }
      d[i] = scale * (values_[old + stride_[k]] - values_[old]);
    }
    return std::make_shared<TableOp>(width_, std::move(size), std::move(constant), std::move(d));
  }

  int width_;
  std::vector<int> size_;
  std::vector<bool> constant_;
  std::vector<double> values_;
  std::vector<std::size_t> stride_;
  std::vector<double> lo_, hi_;
  double pad_ = 0.0;
  mutable std::mutex mutex_;
  mutable std::vector<std::shared_ptr<const TableOp>> derivatives_;
};

}  // namespace

Fn table(std::span<const double> samples, std::span<const int> dimen, const Fn& in) {
  if (dimen.size() < 2) bad("dimen needs n0 and at least one grid dimension");
  if (dimen.size() - 1 > static_cast<std::size_t>(kMaxTableDims))
    bad("at most " + std::to_string(kMaxTableDims) + " grid dimensions");
  if (dimen[0] < 1 || dimen[0] > 64) bad("n0 = " + std::to_string(dimen[0]) + " is outside 1..64");
  std::size_t count = static_cast<std::size_t>(dimen[0]);
  std::vector<int> size;
  for (std::size_t k = 1; k < dimen.size(); ++k) {
    if (dimen[k] < 2) bad("grid dimension " + std::to_string(k) + " has " + std::to_string(dimen[k]) + " nodes, expected >= 2");
    size.push_back(dimen[k]);
    count *= static_cast<std::size_t>(dimen[k]);
  }
  if (samples.size() != count)
    bad("dimen needs " + std::to_string(count) + " samples, got " + std::to_string(samples.size()));
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (!std::isfinite(samples[i])) bad("sample " + std::to_string(i) + " is not finite");
  if (in.dim() != size.size())
    bad("the argument has dimension " + std::to_string(in.dim()) + ", the table " + std::to_string(size.size()));
  auto op = std::make_shared<TableOp>(dimen[0], size, std::vector<bool>(size.size(), false),
                                      std::vector<double>(samples.begin(), samples.end()));
  std::vector<Fn> args;
  for (std::size_t k = 0; k < in.dim(); ++k) args.push_back(in[k]);
  return genmod::apply_custom(std::shared_ptr<const CustomOp>(op), args);
}

}  // namespace genmod
