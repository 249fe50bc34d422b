// Convolution surfaces and skeletal density kernels (convolution.hpp).
#include "genmod/operators/convolution.hpp"

#include "genmod/kernel/custom_op.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

// Ulp steps of widening for std::erf: glibc lists at most 1 ulp for erf in all four rounding
// modes; n one-ulp steps cover any error below n - 1/2 ulps, also across a power of two.
constexpr int kErfUlps = 3;

double step_down(double v) {
  for (int i = 0; i < kErfUlps; ++i) v = interval_detail::next_down(v);
  return v;
}
double step_up(double v) {
  for (int i = 0; i < kErfUlps; ++i) v = interval_detail::next_up(v);
  return v;
}

// Lower and upper bounds of erf at one double: widened, clamped to [-1, 1] and to the side
// of 0 the true value is on (erf(x) has the sign of x), exact at 0.
double erf_below(double x) {
  if (x == 0) return 0.0;
  const double v = step_down(std::erf(x));
  return x > 0 ? std::max(v, 0.0) : std::max(v, -1.0);
}
double erf_above(double x) {
  if (x == 0) return 0.0;
  const double v = step_up(std::erf(x));
  return x < 0 ? std::min(v, 0.0) : std::min(v, 1.0);
}

class ErfOp final : public CustomOp {
 public:
  std::string name() const override { return "erf"; }
  int num_args() const override { return 1; }
  int num_outputs() const override { return 1; }
  void eval(std::span<const double> args, std::span<double> out) const override { out[0] = std::erf(args[0]); }
  void inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t>) const override {
    out[0] = erf_enclosure(args[0]);
  }
  Fn derivative(std::span<const Fn> args, int) const override {
    return (2.0 / std::sqrt(std::numbers::pi)) * exp(-square(args[0]));
  }
  bool continuous() const override { return true; }
};

const std::shared_ptr<const CustomOp>& erf_op() {
  static const std::shared_ptr<const CustomOp> op = std::make_shared<ErfOp>();
  return op;
}

Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

void check_radius(double r, const char* who) {
  if (!(r > 0 && std::isfinite(r))) throw std::invalid_argument(std::string(who) + ": radius must be finite and > 0, got " + std::to_string(r));
}

}  // namespace

Interval erf_enclosure(const Interval& x) noexcept {
  if (x.is_empty()) return Interval::empty();
  return Interval(erf_below(x.lo()), erf_above(x.hi()));
}

Fn erf(const Fn& x) {
  if (x.dim() == 1) return apply_custom(erf_op(), {x});
  std::vector<Fn> parts;
  for (std::size_t j = 0; j < x.dim(); ++j) parts.push_back(apply_custom(erf_op(), {x[j]}));
  return cat(parts);
}

Fn gauss(const Fn& x) { return exp(-kGaussOmega * square(x)); }

Fn gauss_cdf(const Fn& x) { return 0.5 + 0.5 * erf(std::sqrt(kGaussOmega) * x); }

Fn gauss_integral(const Fn& x1, const Fn& x2) { return gauss_cdf(max(x1, x2)) - gauss_cdf(min(x1, x2)); }

Fn ease(const Fn& x) {
  const Fn s = square(x);
  const Fn inner = s * (22.0 - s * (17.0 - 4.0 * s)) * (1.0 / 9.0);
  return select(x <= 0.0, 0.0, select(x >= 1.0, 1.0, inner));
}

Fn wyvill_kernel_of_square(const Fn& s) {
  return select(s >= 1.0, 0.0, 1.0 - s * (22.0 - s * (17.0 - 4.0 * s)) * (1.0 / 9.0));
}

namespace {
constexpr double kBsplineHalf = 0.72235;  // h_B(0.72235) = h_B(0)/2 (Fig. 5.54)
}

Fn bspline_kernel(const Fn& x) {
  const Fn t = abs(x);
  const Fn inner = (t * t * (3.0 * t - 6.0) + 4.0) * (1.0 / 6.0);
  const Fn outer = (2.0 - t) * (2.0 - t) * (2.0 - t) * (1.0 / 6.0);
  return select(t >= 2.0, 0.0, select(t >= 1.0, outer, inner));
}


Fn normalized_kernel(Kernel kernel, const Fn& s2) {
  switch (kernel) {
    case Kernel::gaussian: return exp(-kGaussOmega * s2);
    case Kernel::bspline: return 1.5 * bspline_kernel(kBsplineHalf * sqrt(s2));
    case Kernel::wyvill: return wyvill_kernel_of_square(0.25 * s2);
  }
  throw std::invalid_argument("normalized_kernel: unknown kernel");
}

double kernel_support(Kernel kernel) {
  switch (kernel) {
    case Kernel::gaussian: return std::numeric_limits<double>::infinity();
    case Kernel::bspline: return 2.0 / kBsplineHalf;
    case Kernel::wyvill: return 2.0;
  }
  throw std::invalid_argument("kernel_support: unknown kernel");
}

Fn point_source(const Point3& c, double r, double w, Kernel kernel, const Fn& p) {
  check_radius(r, "point_source");
  if (!(w >= 0 && std::isfinite(w))) throw std::invalid_argument("point_source: weight must be finite and >= 0");
  return w * normalized_kernel(kernel, distance2_to_point(c, p) * (1.0 / (r * r)));
}

Fn bspline_cdf(const Fn& x) {
  // area from -2 to -|x| (times 24), then reflected for x > 0 (the kernel is even)
  const Fn t = -abs(x);
  const Fn t2 = square(t);
  const Fn neg = select(t < -2.0, 0.0, select(t < -1.0, square(square(t + 2.0)), t * (16.0 - t2 * (8.0 + 3.0 * t)) + 12.0));
  return select(x < 0.0, neg, 24.0 - neg) * (1.0 / 24.0);
}

Fn wyvill_cdf(const Fn& x) {
  const Fn c = min(max(x, -1.0), 1.0);
  const Fn c2 = square(c);
  // F(c) = int_0^c h_wyv = c - c^3 (22/3 - c^2 (17/5 - (4/7) c^2)) / 9, odd; F(1) = kWyvillIntegral / 2
  const Fn f = c - c * c2 * (22.0 / 3 - c2 * (17.0 / 5 - (4.0 / 7) * c2)) * (1.0 / 9.0);
  return 0.5 + f * (1.0 / kWyvillIntegral);
}

Fn segment_convolution(const Point3& a, const Point3& b, double r1, double r2, Kernel kernel, const Fn& p) {
  check_radius(r1, "segment_convolution");
  check_radius(r2, "segment_convolution");
  const Point3 d = sub(b, a);
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(length > 0 && std::isfinite(length))) throw std::invalid_argument("segment_convolution: the segment's endpoints coincide or are not finite");
  if (p.dim() != 3) throw std::invalid_argument("segment_convolution: the query point must have dimension 3");
  const Point3 axis = {d[0] / length, d[1] / length, d[2] / length};
  const Fn u = (p[0] - a[0]) * axis[0] + (p[1] - a[1]) * axis[1] + (p[2] - a[2]) * axis[2];
  const Fn r = r1 == r2 ? Fn(r1) : r1 + min(max(u * (1.0 / length), 0.0), 1.0) * (r2 - r1);
  // The integration filter (the source's Subtend) is the kernel's CDF at the ends' normalized
  // axial coordinates, non-negative since the CDF increases; the distance filter is the
  // normalized kernel of the distance to the line.
  const double scale = kernel == Kernel::bspline ? kBsplineHalf : kernel == Kernel::wyvill ? 0.5 : 1.0;
  const Fn s = scale / r;
  auto cdf = [&](const Fn& v) {
    return kernel == Kernel::gaussian ? gauss_cdf(v) : kernel == Kernel::bspline ? bspline_cdf(v) : wyvill_cdf(v);
  };
  const Fn subtend = max(cdf((length - u) * s) - cdf(-u * s), 0.0);
  return subtend * normalized_kernel(kernel, distance2_to_line(a, b, p) / square(r));
}

Fn segment_convolution(const Point3& a, const Point3& b, double r1, double r2, const Fn& p) {
  return segment_convolution(a, b, r1, r2, Kernel::gaussian, p);
}

Fn density_to_implicit(const Fn& density, double iso) {
  if (!std::isfinite(iso)) throw std::invalid_argument("density_to_implicit: iso-value must be finite");
  return iso - density;
}

}  // namespace genmod
