// Superposition with per-box culling (culled_field.hpp).
#include "genmod/operators/culled_field.hpp"

#include "genmod/kernel/custom_op.hpp"
#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/operators/convolution.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <array>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const int kXyz[3] = {0, 1, 2};

// A lower bound of the squared distance between the box and the skeleton's bounding box.
double box_distance2_below(const FieldElement& e, std::span<const Interval> box) {
  Interval sum(0.0);
  for (int i = 0; i < 3; ++i) {
    const double s_lo = std::min(e.a[i], e.b[i]), s_hi = std::max(e.a[i], e.b[i]);
    Interval gap(0.0);
    if (box[i].lo() > s_hi) gap = Interval(box[i].lo()) - Interval(s_hi);
    else if (box[i].hi() < s_lo) gap = Interval(s_lo) - Interval(box[i].hi());
    sum = sum + square(Interval(std::max(gap.lo(), 0.0), std::max(gap.hi(), 0.0)));
  }
  return std::max(sum.lo(), 0.0);
}

// The same lower bound in plain double arithmetic, for the hot loop: each subtraction, square
// and sum is rounded with relative error <= 2^-52 in any rounding mode (the subtraction of two
// doubles is exact or correctly rounded), so the result shrunk by 1e-12 is below the exact one.
double fast_box_distance2_below(const Point3& s_lo, const Point3& s_hi, std::span<const Interval> box) {
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    double gap = 0;
    if (box[i].lo() > s_hi[i]) gap = box[i].lo() - s_hi[i];
    else if (box[i].hi() < s_lo[i]) gap = s_lo[i] - box[i].hi();
    sum += gap * gap;
  }
  return sum * (1 - 1e-12);
}

// A uniform grid over the elements' reach (skeleton bounding box grown by the cull distance):
// each cell lists the elements whose reach overlaps it. An element whose reach shares no cell
// with a box does not overlap it, so the box is beyond its cull distance. Elements with an
// infinite reach (never culled) are listed apart.
class ElementGrid {
 public:
  void build(const std::vector<Point3>& lo, const std::vector<Point3>& hi, const std::vector<double>& reach) {
    const std::size_t n = lo.size();
    Point3 glo = {kInf, kInf, kInf}, ghi = {-kInf, -kInf, -kInf};
    double extent = 0;
    std::size_t finite = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (!std::isfinite(reach[k])) {
        always_.push_back(static_cast<std::uint32_t>(k));
        continue;
      }
      ++finite;
      for (int i = 0; i < 3; ++i) {
        glo[i] = std::min(glo[i], lo[k][i] - reach[k]);
        ghi[i] = std::max(ghi[i], hi[k][i] + reach[k]);
        extent = std::max(extent, hi[k][i] - lo[k][i] + 2 * reach[k]);
      }
    }
    if (finite == 0) return;
    origin_ = glo;
    // Cells about the size of the largest reach, at most 64 per axis.
    for (int i = 0; i < 3; ++i) {
      const double span = std::max(ghi[i] - glo[i], 1e-300);
      dims_[i] = std::clamp(static_cast<int>(span / std::max(extent, 1e-300)), 1, 64);
      inv_cell_[i] = dims_[i] / span;
    }
    cells_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2], {});
    for (std::size_t k = 0; k < n; ++k) {
      if (!std::isfinite(reach[k])) continue;
      int c0[3], c1[3];
      for (int i = 0; i < 3; ++i) c0[i] = cell(i, lo[k][i] - reach[k]), c1[i] = cell(i, hi[k][i] + reach[k]);
      for (int z = c0[2]; z <= c1[2]; ++z)
        for (int y = c0[1]; y <= c1[1]; ++y)
          for (int x = c0[0]; x <= c1[0]; ++x) cells_[index(x, y, z)].push_back(static_cast<std::uint32_t>(k));
    }
  }

  // The elements that may reach the box (sorted, no repeats), into `out`.
  void candidates(std::span<const Interval> box, std::vector<std::uint32_t>& out) const {
    out.assign(always_.begin(), always_.end());
    if (cells_.empty()) return;
    int c0[3], c1[3];
    for (int i = 0; i < 3; ++i) {
      c0[i] = cell(i, box[i].lo());
      c1[i] = cell(i, box[i].hi());
      // a box wholly outside the grid on one side reaches nothing in it
      if (box[i].hi() < origin_[i] || (box[i].lo() - origin_[i]) * inv_cell_[i] >= dims_[i]) return;
    }
    for (int z = c0[2]; z <= c1[2]; ++z)
      for (int y = c0[1]; y <= c1[1]; ++y)
        for (int x = c0[0]; x <= c1[0]; ++x) {
          const auto& list = cells_[index(x, y, z)];
          out.insert(out.end(), list.begin(), list.end());
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

 private:
  int cell(int i, double v) const {
    const double c = std::floor((v - origin_[i]) * inv_cell_[i]);
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(dims_[i] - 1)));
  }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * dims_[1] + static_cast<std::size_t>(y)) * dims_[0] + static_cast<std::size_t>(x);
  }
  Point3 origin_ = {0, 0, 0};
  double inv_cell_[3] = {1, 1, 1};
  int dims_[3] = {1, 1, 1};
  std::vector<std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> always_;
};

class CulledFieldOp final : public CustomOp {
 public:
  CulledFieldOp(std::vector<FieldElement> elements, CulledFieldOptions options)
      : elements_(std::move(elements)), options_(options) {
    tapes_.reserve(elements_.size());
    for (const FieldElement& e : elements_) {
      tapes_.emplace_back(e.density, std::span<const int>(kXyz, 3));
      Point3 lo, hi;
      for (int i = 0; i < 3; ++i) lo[i] = std::min(e.a[i], e.b[i]), hi[i] = std::max(e.a[i], e.b[i]);
      skeleton_lo_.push_back(lo);
      skeleton_hi_.push_back(hi);
      // The squared distance beyond which the element's bound is at most cull_below:
      // weight exp(-omega d^2 / r^2) <= cull_below  <=>  d^2 >= r^2 ln(weight / cull_below) / omega,
      // made a little larger (1e-9 relative) to absorb the rounding of this formula.
      double d2 = 0;
      if (e.falloff == Falloff::compact) d2 = e.radius * e.radius;
      else if (e.falloff == Falloff::none || options_.cull_below <= 0) d2 = kInf;
      else if (e.weight > options_.cull_below) d2 = e.radius * e.radius * std::log(e.weight / options_.cull_below) / kGaussOmega;
      cull_distance2_.push_back(d2 * (1 + 1e-9));
      if (e.falloff == Falloff::gaussian) ++gaussian_count_;
    }
    // Reach: the cull distance, grown by 1e-6 relative (far above the rounding of the grid's
    // cell arithmetic) so that overlap in reals implies a shared cell.
    std::vector<double> reach;
    for (double d2 : cull_distance2_) reach.push_back(std::isfinite(d2) ? std::sqrt(d2) * (1 + 1e-6) + 1e-300 : kInf);
    grid_.build(skeleton_lo_, skeleton_hi_, reach);
  }
  std::string name() const override { return "culled_field"; }
  int num_args() const override { return 3; }
  int num_outputs() const override { return 1; }

  // The full sum; compact elements whose support cannot reach the point are exactly 0 there
  // and are skipped (the same sum, faster).
  void eval(std::span<const double> args, std::span<double> out) const override {
    if (std::isnan(args[0] + args[1] + args[2])) {
      out[0] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    const Interval point[3] = {Interval(args[0]), Interval(args[1]), Interval(args[2])};
    std::vector<std::uint32_t> near;
    grid_.candidates(point, near);
    PointEvaluator pv;
    double sum = 0;
    // In index order (so the sum rounds as the plain sum does): every non-compact element, and
    // the compact ones that may reach the point.
    std::size_t next = 0;
    for (std::size_t k = 0; k < tapes_.size(); ++k) {
      while (next < near.size() && near[next] < k) ++next;
      const bool listed = next < near.size() && near[next] == k;
      if (elements_[k].falloff == Falloff::compact && (!listed || point_distance2_below(k, args) >= cull_distance2_[k])) continue;
      sum += pv.eval(tapes_[k], args)[0];
    }
    out[0] = sum;
  }

  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const override {
    for (int i = 0; i < 3; ++i)
      if (args[i].is_empty()) {
        out[0] = Interval::empty();
        return;
      }
    std::vector<std::uint32_t> near;
    grid_.candidates(args, near);
    IntervalEvaluator iv;
    Interval sum(0.0);
    std::size_t gaussian_evaluated = 0;
    for (std::uint32_t k : near) {
      if (fast_box_distance2_below(skeleton_lo_[k], skeleton_hi_[k], args) >= cull_distance2_[k]) continue;
      const auto y = iv.eval(tapes_[k], args);
      err[0] |= iv.errors()[0];
      sum = sum + y[0];
      gaussian_evaluated += elements_[k].falloff == Falloff::gaussian;
    }
    // Every culled Gaussian element contributes at most cull_below (compact ones 0): the
    // count is exact, the product rounded up.
    const double culled = static_cast<double>(gaussian_count_ - gaussian_evaluated);
    const double remainder = (Interval(culled) * Interval(options_.cull_below)).hi();
    out[0] = sum + Interval(0.0, remainder);
  }

  // Another culled field, of the elements' partial derivatives: a compact element's derivative
  // vanishes where the element does, so it is culled in the same way (remainder 0); the
  // derivatives of Gaussian elements have no bound here and are never culled.
  Fn derivative(std::span<const Fn> args, int k) const override {
    std::shared_ptr<const CustomOp> d;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto& slot = derivatives_[static_cast<std::size_t>(k)];
      if (!slot) {
        std::vector<FieldElement> es = elements_;
        for (FieldElement& e : es) {
          e.density = genmod::derivative(e.density, k);
          if (e.falloff != Falloff::compact) e.falloff = Falloff::none;
        }
        slot = std::make_shared<CulledFieldOp>(std::move(es), options_);
      }
      d = slot;
    }
    return apply_custom(d, args);
  }
  bool continuous() const override { return true; }

 private:
  std::vector<FieldElement> elements_;
  CulledFieldOptions options_;
  std::vector<Tape> tapes_;
  std::vector<Point3> skeleton_lo_, skeleton_hi_;  // the skeletons' bounding boxes
  std::vector<double> cull_distance2_;             // cull when the box is at least this far (squared)
  std::size_t gaussian_count_ = 0;                 // culled ones add cull_below each
  ElementGrid grid_;
  mutable std::mutex mutex_;
  mutable std::array<std::shared_ptr<const CustomOp>, 3> derivatives_;  // built on first use

  double point_distance2_below(std::size_t k, std::span<const double> p) const {
    const Interval box[3] = {Interval(p[0]), Interval(p[1]), Interval(p[2])};
    return fast_box_distance2_below(skeleton_lo_[k], skeleton_hi_[k], box);
  }
};

void check_element(const FieldElement& e, std::size_t k) {
  const std::string who = "culled_field: element " + std::to_string(k);
  if (e.density.dim() != 1) throw std::invalid_argument(who + ": the density must be scalar");
  if ((e.density.input_mask() & ~std::uint64_t{7}) != 0) throw std::invalid_argument(who + ": the density may depend on x(0), x(1), x(2) only");
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(e.a[i]) || !std::isfinite(e.b[i])) throw std::invalid_argument(who + ": skeleton coordinates must be finite");
  if (!(e.radius > 0 && std::isfinite(e.radius))) throw std::invalid_argument(who + ": radius must be finite and > 0");
  if (!(e.weight >= 0 && std::isfinite(e.weight))) throw std::invalid_argument(who + ": weight must be finite and >= 0");
}

}  // namespace

double culled_element_bound(const FieldElement& e, std::span<const Interval> box) {
  if (e.falloff == Falloff::none) return kInf;
  const double d2 = box_distance2_below(e, box);
  if (e.falloff == Falloff::compact) return d2 >= e.radius * e.radius * (1 + 1e-12) ? 0.0 : kInf;
  // weight * exp(-omega d2 / r^2), rounded upward: the exponent's upper bound.
  const Interval exponent = -Interval(kGaussOmega) * Interval(d2) / square(Interval(e.radius));
  // The relative margin covers the rounding of the element's own point evaluation (its value
  // may exceed the exact bound by a few ulps where the box touches the nearest point).
  return (Interval(e.weight) * exp(exponent) * Interval(1 + 1e-12)).hi() + std::numeric_limits<double>::denorm_min();
}

Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options, const Fn& p) {
  if (elements.empty()) throw std::invalid_argument("culled_field: no elements");
  if (p.dim() != 3) throw std::invalid_argument("culled_field: the query point must have dimension 3");
  if (!(options.cull_below >= 0)) throw std::invalid_argument("culled_field: cull_below must be >= 0");
  for (std::size_t k = 0; k < elements.size(); ++k) check_element(elements[k], k);
  auto op = std::make_shared<CulledFieldOp>(elements, options);
  return apply_custom(std::shared_ptr<const CustomOp>(op), {p[0], p[1], p[2]});
}

Fn culled_field(const std::vector<FieldElement>& elements, const CulledFieldOptions& options) {
  return culled_field(elements, options, skeleton_query_point());
}

}  // namespace genmod
