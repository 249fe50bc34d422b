#include "bspline_op.hpp"

#include "unit_tangent_op.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace genmod::detail {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kEps = std::numeric_limits<double>::epsilon();
// Orders of derivative a RationalDerivativeOp evaluates in fixed arrays (c, c', ..., c^(k)).
constexpr int kMaxOrderTerms = 16;

[[noreturn]] void bad(const std::string& kind, const std::string& what) {
  throw std::invalid_argument("genmod: " + kind + ": " + what);
}

}  // namespace

std::vector<double> jump_knots(const std::vector<double>& knots, int degree, int num_points, int order) {
  std::vector<double> out;
  for (int k = degree + 1; k < num_points;) {
    int m = 1;
    while (k + m < num_points && knots[static_cast<std::size_t>(k + m)] == knots[static_cast<std::size_t>(k)]) ++m;
    if (m > degree - order) out.push_back(knots[static_cast<std::size_t>(k)]);
    k += m;
  }
  return out;
}

bool jump_free(const std::vector<double>& jumps, double a, double b) noexcept {
  const auto it = std::upper_bound(jumps.begin(), jumps.end(), a);  // the first jump > a
  return it == jumps.end() || *it > b;
}

BSplineOp::BSplineOp(int dim, int degree, std::vector<double> knots, std::vector<double> points,
                     std::vector<double> weights, std::string kind)
    : dim_(dim), degree_(degree), knots_(std::move(knots)), points_(std::move(points)),
      weights_(std::move(weights)), kind_(std::move(kind)) {
  if (dim < 1 || dim > kMaxDim)
    bad(kind_, "dimension " + std::to_string(dim) + " is outside [1, " + std::to_string(kMaxDim) + "]");
  if (degree < 0 || degree > kMaxDegree)
    bad(kind_, "degree " + std::to_string(degree) + " is outside [0, " + std::to_string(kMaxDegree) + "]");
  if (points_.size() % static_cast<std::size_t>(dim) != 0)
    bad(kind_, "the coordinates are not a whole number of points");
  n_ = static_cast<int>(points_.size() / static_cast<std::size_t>(dim));
  if (n_ < degree + 1)
    bad(kind_, "degree " + std::to_string(degree) + " needs at least " + std::to_string(degree + 1) +
                   " control points, got " + std::to_string(n_));
  if (knots_.size() != static_cast<std::size_t>(n_ + degree + 1))
    bad(kind_, std::to_string(n_) + " control points of degree " + std::to_string(degree) + " need " +
                   std::to_string(n_ + degree + 1) + " knots, got " + std::to_string(knots_.size()));
  for (std::size_t i = 0; i < knots_.size(); ++i) {
    if (!std::isfinite(knots_[i])) bad(kind_, "knot " + std::to_string(i) + " is not finite");
    if (i > 0 && knots_[i] < knots_[i - 1])
      bad(kind_, "the knot vector is not nondecreasing at knot " + std::to_string(i) + " (" +
                     std::to_string(knots_[i]) + " < " + std::to_string(knots_[i - 1]) + ")");
  }
  if (!(lo() < hi())) bad(kind_, "the domain [u_p, u_n] of the knot vector is empty");
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (!std::isfinite(points_[i])) bad(kind_, "control point " + std::to_string(i / static_cast<std::size_t>(dim)) + " is not finite");
  if (!weights_.empty() && weights_.size() != static_cast<std::size_t>(n_))
    bad(kind_, std::to_string(n_) + " control points need " + std::to_string(n_) + " weights, got " +
                   std::to_string(weights_.size()));
  for (std::size_t i = 0; i < weights_.size(); ++i)
    if (!(weights_[i] > 0.0) || !std::isfinite(weights_[i]))
      bad(kind_, "weight " + std::to_string(i) + " is not a positive number");

  const std::size_t hd = static_cast<std::size_t>(hdim()), d = static_cast<std::size_t>(dim_);
  hpoints_.resize(static_cast<std::size_t>(n_) * hd);
  for (std::size_t i = 0; i < static_cast<std::size_t>(n_); ++i) {
    const double w = rational() ? weights_[i] : 1.0;
    for (std::size_t c = 0; c < d; ++c) hpoints_[i * hd + c] = w * points_[i * d + c];
    if (rational()) hpoints_[i * hd + d] = w;
  }
  check_magnitudes();
  fixed_de_boor_ = de_boor_kernel(degree_, hdim());

  // Rounding allowance per span: de Boor and the blossoms are convex combinations, each
  // level off by a few ulps of the largest control point; a rational curve divides by a
  // weight no smaller than the smallest one (see the file comment of curve.hpp).
  pad_.assign(static_cast<std::size_t>(n_), 0.0);
  span_lo_.assign(static_cast<std::size_t>(n_) * d, kNaN);
  span_hi_.assign(static_cast<std::size_t>(n_) * d, kNaN);
  for (int k = degree_; k < n_; ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    double m = 0.0, wmin = 1.0, wmax = 1.0;
    if (rational()) wmin = std::numeric_limits<double>::infinity(), wmax = 0.0;
    for (int i = k - degree_; i <= k; ++i) {
      const std::size_t iu = static_cast<std::size_t>(i);
      for (std::size_t c = 0; c < d; ++c) m = std::max(m, std::abs(points_[iu * d + c]));
      if (rational()) wmin = std::min(wmin, weights_[iu]), wmax = std::max(wmax, weights_[iu]);
    }
    pad_[ku] = 16.0 * (degree_ + 2) * kEps * m * (wmax / wmin) + std::numeric_limits<double>::denorm_min();
    if (knots_[ku] < knots_[ku + 1]) {
      double* lo_k = &span_lo_[ku * d];
      double* hi_k = &span_hi_[ku * d];
      std::fill_n(lo_k, d, std::numeric_limits<double>::infinity());
      std::fill_n(hi_k, d, -std::numeric_limits<double>::infinity());
      enclose_piece(k, knots_[ku], knots_[ku + 1], lo_k, hi_k);
    }
  }
  // Continuity: a piece boundary is C^(p - m) for an interior knot of multiplicity m, so the
  // curve jumps where m > p (and every boundary of a degree-0 curve is a jump).
  jumps_ = jump_knots(knots_, degree_, n_, 0);
  continuous_ = degree_ >= 1 && jumps_.empty();
}

bool BSplineOp::inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                                     std::span<std::uint8_t> err) const {
  inclusion(args, out, err);
  // Degree 0 too: every interior knot is listed as a jump, and a piece is constant on a box
  // that holds none but at its start (a value at a knot comes from the span starting there).
  return args[0].is_empty() || jump_free(jumps_, args[0].lo(), args[0].hi());
}

void BSplineOp::check_magnitudes() const {
  // de Boor's convex combinations, the rounding pads, the homogeneous coordinates of a NURBS
  // and the differences that make the derivative curves must all stay finite; past double's
  // range they would give wrong values and enclosures with no error flag. So a curve is
  // refused when it is built unless its knot range, its (homogeneous) control points and the
  // control points of every derivative curve are at most kMaxMagnitude; then the derivatives,
  // built on demand with the same arithmetic, never fail.
  if (!(knots_.back() - knots_.front() <= kMaxMagnitude))
    bad(kind_, "the knot range [" + std::to_string(knots_.front()) + ", " + std::to_string(knots_.back()) +
                   "] is wider than " + std::to_string(kMaxMagnitude) + " (its differences would overflow)");
  const std::size_t hd = static_cast<std::size_t>(hdim());
  std::vector<double> q = hpoints_;
  auto check = [&](int order) {
    for (std::size_t i = 0; i < q.size(); ++i)
      if (!(std::abs(q[i]) <= kMaxMagnitude))
        bad(kind_, (order == 0 ? std::string(rational() ? "weighted control point " : "control point ")
                               : "control point of the order-" + std::to_string(order) + " derivative ") +
                       std::to_string(i / hd) + " exceeds " + std::to_string(kMaxMagnitude) +
                       " in magnitude (values past double's range cannot be bounded)");
  };
  check(0);
  // Level r differentiates a degree-r curve over knots_[r0, r0 + n_r + r] (the end knots are
  // dropped at each level), as derivative_op() does.
  std::size_t n = static_cast<std::size_t>(n_), first = 0;
  for (int r = degree_, order = 1; r >= 1; --r, ++order, --n, ++first) {
    std::vector<double> next((n - 1) * hd, 0.0);
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const double den = knots_[first + i + static_cast<std::size_t>(r) + 1] - knots_[first + i + 1];
      if (den > 0.0)
        for (std::size_t c = 0; c < hd; ++c) next[i * hd + c] = r * (q[(i + 1) * hd + c] - q[i * hd + c]) / den;
    }
    q = std::move(next);
    check(order);
  }
}

int BSplineOp::span(double t) const noexcept {
  const auto first = knots_.begin() + degree_;
  const auto last = knots_.begin() + n_ + 1;
  int k = static_cast<int>(std::upper_bound(first, last, t) - knots_.begin()) - 1;
  k = std::clamp(k, degree_, n_ - 1);
  // t = u_n belongs to the last nonempty span.
  while (k > degree_ && !(knots_[static_cast<std::size_t>(k)] < knots_[static_cast<std::size_t>(k) + 1])) --k;
  return k;
}

void BSplineOp::de_boor(int k, const double* params, double* out) const {
  if (fixed_de_boor_) {
    fixed_de_boor_(knots_.data(), hpoints_.data(), k, params, out);
    return;
  }
  const int p = degree_, hd = hdim();
  double d[kMaxDegree + 1][kMaxDim + 1];
  for (int j = 0; j <= p; ++j)
    for (int c = 0; c < hd; ++c) d[j][c] = hpoints_[static_cast<std::size_t>((j + k - p) * hd + c)];
  for (int r = 1; r <= p; ++r) {
    const double x = params[r - 1];
    for (int j = p; j >= r; --j) {
      const double a = knots_[static_cast<std::size_t>(j + k - p)];
      const double b = knots_[static_cast<std::size_t>(j + 1 + k - r)];
      const double alpha = (x - a) / (b - a);  // b > a: the span [u_k, u_k+1] lies in [a, b]
      for (int c = 0; c < hd; ++c) d[j][c] = (1.0 - alpha) * d[j - 1][c] + alpha * d[j][c];
    }
  }
  for (int c = 0; c < hd; ++c) out[c] = d[p][c];
}

void BSplineOp::eval(std::span<const double> args, std::span<double> out) const {
  const double t = args[0];
  if (!(t >= lo() && t <= hi())) {  // NaN, or outside the domain
    std::fill(out.begin(), out.end(), kNaN);
    return;
  }
  double params[kMaxDegree];
  std::fill_n(params, degree_, t);
  double h[kMaxDim + 1];
  de_boor(span(t), params, h);
  for (int c = 0; c < dim_; ++c) out[static_cast<std::size_t>(c)] = rational() ? h[c] / h[dim_] : h[c];
}

void BSplineOp::enclose_piece(int k, double s, double t, double* lo, double* hi) const {
  const int p = degree_;
  double params[kMaxDegree];
  double h[kMaxDim + 1];
  const double pad = pad_[static_cast<std::size_t>(k)];
  // Bezier point i of the piece over [s, t] is the blossom f(s^(p-i), t^i).
  for (int i = 0; i <= p; ++i) {
    for (int r = 0; r < p; ++r) params[r] = r < p - i ? s : t;
    de_boor(k, params, h);
    for (int c = 0; c < dim_; ++c) {
      const double v = rational() ? h[c] / h[dim_] : h[c];
      lo[c] = std::min(lo[c], v - pad);
      hi[c] = std::max(hi[c], v + pad);
    }
  }
}

void BSplineOp::inclusion(std::span<const Interval> args, std::span<Interval> out, std::span<std::uint8_t> err) const {
  const Interval t = args[0];
  if (t.is_empty()) {
    std::fill(out.begin(), out.end(), Interval::empty());
    return;
  }
  const double a = std::max(t.lo(), lo()), b = std::min(t.hi(), hi());
  const bool outside = t.lo() < lo() || t.hi() > hi();
  if (a > b) {  // entirely outside the domain: an error everywhere
    std::fill(out.begin(), out.end(), Interval::empty());
    for (auto& e : err) e |= kCertainError;
    return;
  }
  if (outside)
    for (auto& e : err) e |= kMaybeError;
  double lo_out[kMaxDim], hi_out[kMaxDim];
  std::fill_n(lo_out, dim_, std::numeric_limits<double>::infinity());
  std::fill_n(hi_out, dim_, -std::numeric_limits<double>::infinity());
  const int ka = span(a), kb = span(b);
  const std::size_t d = static_cast<std::size_t>(dim_);
  for (int k = ka; k <= kb; ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    const double u0 = knots_[ku], u1 = knots_[ku + 1];
    if (!(u0 < u1)) continue;  // empty span: never evaluated
    if (a <= u0 && u1 <= b) {
      for (std::size_t c = 0; c < d; ++c) {
        lo_out[c] = std::min(lo_out[c], span_lo_[ku * d + c]);
        hi_out[c] = std::max(hi_out[c], span_hi_[ku * d + c]);
      }
    } else {
      enclose_piece(k, std::max(a, u0), std::min(b, u1), lo_out, hi_out);
    }
  }
  for (std::size_t c = 0; c < d; ++c) out[c] = Interval(lo_out[c], hi_out[c]);
}

std::shared_ptr<const BSplineOp> BSplineOp::derivative_op() const {
  std::call_once(derivative_once_, [this] {
    // c' = sum_i Q_i N_{i,p-1} with Q_i = p (P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1}) over the
    // knot vector without its end knots. A zero denominator belongs to a basis function
    // that vanishes, so its Q_i is 0.
    const int p = degree_;
    const std::size_t d = static_cast<std::size_t>(dim_);
    std::vector<double> q((static_cast<std::size_t>(n_) - 1) * d, 0.0);
    for (std::size_t i = 0; i + 1 < static_cast<std::size_t>(n_); ++i) {
      const double den = knots_[i + static_cast<std::size_t>(p) + 1] - knots_[i + 1];
      if (den > 0.0)
        for (std::size_t c = 0; c < d; ++c) q[i * d + c] = p * (points_[(i + 1) * d + c] - points_[i * d + c]) / den;
    }
    std::vector<double> knots(knots_.begin() + 1, knots_.end() - 1);
    derivative_ = std::make_shared<BSplineOp>(dim_, p - 1, std::move(knots), std::move(q), std::vector<double>{},
                                              kind_ + "'");
  });
  return derivative_;
}

std::shared_ptr<const BSplineOp> BSplineOp::homogeneous_op() const {
  std::call_once(homogeneous_once_, [this] {
    homogeneous_ = std::make_shared<BSplineOp>(dim_ + 1, degree_, knots_, hpoints_, std::vector<double>{},
                                               kind_ + "-homogeneous");
  });
  return homogeneous_;
}

std::shared_ptr<const RationalDerivativeOp> BSplineOp::rational_derivative_op() const {
  std::call_once(rational_derivative_once_, [this] {
    auto copy = std::make_shared<BSplineOp>(dim_, degree_, knots_, points_, weights_, kind_);
    rational_derivative_ = std::make_shared<RationalDerivativeOp>(std::move(copy), 1);
  });
  return rational_derivative_;
}

std::shared_ptr<const UnitTangentOp> BSplineOp::unit_tangent_op() const {
  std::call_once(unit_tangent_once_, [this] { unit_tangent_ = std::make_shared<UnitTangentOp>(*this); });
  return unit_tangent_;
}

Fn BSplineOp::derivative(std::span<const Fn> args, int) const {
  if (!rational()) {
    if (degree_ == 0) return cat(std::vector<Fn>(static_cast<std::size_t>(dim_), Fn(0.0)));
    return genmod::apply_custom(std::shared_ptr<const CustomOp>(derivative_op()), args);
  }
  return genmod::apply_custom(std::shared_ptr<const CustomOp>(rational_derivative_op()), args);
}

// H^(i) for i = 0 .. min(order, degree): the homogeneous B-spline and its derivatives.
std::vector<std::shared_ptr<const BSplineOp>> RationalDerivativeOp::homogeneous_derivatives(
    const std::shared_ptr<const BSplineOp>& h, int order) {
  std::vector<std::shared_ptr<const BSplineOp>> out{h};
  while (static_cast<int>(out.size()) <= std::min(order, h->degree())) {
    out.push_back(out.back()->derivative_op());
  }
  return out;
}

namespace {

double binomial(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

}  // namespace

RationalDerivativeOp::RationalDerivativeOp(std::shared_ptr<const BSplineOp> curve, int order)
    : RationalDerivativeOp(curve, homogeneous_derivatives(curve->homogeneous_op(), order), order) {}

RationalDerivativeOp::RationalDerivativeOp(std::shared_ptr<const BSplineOp> curve,
                                           std::vector<std::shared_ptr<const BSplineOp>> h, int order)
    : curve_(std::move(curve)), h_(std::move(h)), order_(order) {
  if (order < 1 || order >= kMaxOrderTerms)
    throw std::domain_error("genmod: " + curve_->name() + ": derivatives of order " + std::to_string(order) +
                            " are not supported (at most " + std::to_string(kMaxOrderTerms - 1) + ")");
  // c^(order) is C^(p - m - order) at an interior knot of multiplicity m.
  jumps_ = jump_knots(curve_->knots(), curve_->degree(), curve_->num_points(), order);
  continuous_ = jumps_.empty();
}

bool RationalDerivativeOp::inclusion_continuous(std::span<const Interval> args, std::span<Interval> out,
                                                std::span<std::uint8_t> err) const {
  inclusion(args, out, err);
  return args[0].is_empty() || jump_free(jumps_, args[0].lo(), args[0].hi());
}

std::string RationalDerivativeOp::name() const {
  return curve_->name() + "-derivative-" + std::to_string(order_);
}

void RationalDerivativeOp::eval(std::span<const double> args, std::span<double> out) const {
  const int d = curve_->dim();
  const double t = args[0];
  if (!(t >= curve_->lo() && t <= curve_->hi())) {
    std::fill(out.begin(), out.end(), kNaN);
    return;
  }
  // c[j][.] = c^(j); hv[i][.] = H^(i) (zero past the degree).
  double c[kMaxOrderTerms][BSplineOp::kMaxDim], hv[kMaxOrderTerms][BSplineOp::kMaxDim + 1];
  curve_->eval(args, std::span<double>(c[0], static_cast<std::size_t>(d)));
  for (int i = 1; i <= order_; ++i) {
    if (i < static_cast<int>(h_.size()))
      h_[static_cast<std::size_t>(i)]->eval(args, std::span<double>(hv[i], static_cast<std::size_t>(d + 1)));
    else
      std::fill_n(hv[i], d + 1, 0.0);
  }
  double h0[BSplineOp::kMaxDim + 1];
  h_[0]->eval(args, std::span<double>(h0, static_cast<std::size_t>(d + 1)));
  const double w = h0[d];
  for (int j = 1; j <= order_; ++j)
    for (int e = 0; e < d; ++e) {
      // (j w') c^(j-1) first: at order 1 the quotient rule's (A' - w' c) / w, bit for bit.
      double num = hv[j][e] - j * hv[1][d] * c[j - 1][e];
      for (int i = 2; i <= j; ++i) num -= binomial(j, i) * hv[i][d] * c[j - i][e];
      c[j][e] = num / w;
    }
  for (int e = 0; e < d; ++e) out[static_cast<std::size_t>(e)] = c[order_][e];
}

void RationalDerivativeOp::inclusion(std::span<const Interval> args, std::span<Interval> out,
                                     std::span<std::uint8_t> err) const {
  const Interval t = args[0];
  if (t.is_empty()) {
    std::fill(out.begin(), out.end(), Interval::empty());
    return;
  }
  const BSplineOp& c = *curve_;
  const double a = std::max(t.lo(), c.lo()), b = std::min(t.hi(), c.hi());
  if (a > b) {
    std::fill(out.begin(), out.end(), Interval::empty());
    for (auto& e : err) e |= kCertainError;
    return;
  }
  if (t.lo() < c.lo() || t.hi() > c.hi())
    for (auto& e : err) e |= kMaybeError;
  const int d = c.dim();
  const std::vector<double>& knots = c.knots();
  Interval result[BSplineOp::kMaxDim], piece[BSplineOp::kMaxDim];
  bool first = true;
  for (int k = c.span(a); k <= c.span(b); ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    if (!(knots[ku] < knots[ku + 1])) continue;  // empty span: never evaluated
    enclose_span(k, std::max(a, knots[ku]), std::min(b, knots[ku + 1]), piece);
    for (int q = 0; q < d; ++q) result[q] = first ? piece[q] : hull(result[q], piece[q]);
    first = false;
  }
  for (int q = 0; q < d; ++q) out[static_cast<std::size_t>(q)] = result[q];
}

void RationalDerivativeOp::enclose_span(int k, double s, double e, Interval* out) const {
  const BSplineOp& c = *curve_;
  const int d = c.dim();
  // c and H^(i), all on span k (H^(i)'s knot vector drops i knots at each end, so this span
  // is its span k - i).
  Interval cj[kMaxOrderTerms][BSplineOp::kMaxDim], hj[kMaxOrderTerms][BSplineOp::kMaxDim + 1];
  auto enclose = [&](const BSplineOp& op, int span, Interval* into) {
    double lo[BSplineOp::kMaxDim + 1], hi[BSplineOp::kMaxDim + 1];
    std::fill_n(lo, op.dim(), std::numeric_limits<double>::infinity());
    std::fill_n(hi, op.dim(), -std::numeric_limits<double>::infinity());
    op.enclose_piece(span, s, e, lo, hi);
    for (int q = 0; q < op.dim(); ++q) into[q] = Interval(lo[q], hi[q]);
  };
  enclose(c, k, cj[0]);
  for (int i = 0; i <= order_; ++i) {
    if (i < static_cast<int>(h_.size()))
      enclose(*h_[static_cast<std::size_t>(i)], k - i, hj[i]);
    else
      std::fill_n(hj[i], d + 1, Interval(0.0));
  }
  const Interval w = hj[0][d];  // weights are positive: w > 0 on the span
  for (int j = 1; j <= order_; ++j)
    for (int q = 0; q < d; ++q) {
      Interval num = hj[j][q];
      for (int i = 1; i <= j; ++i) num -= Interval(binomial(j, i)) * hj[i][d] * cj[j - i][q];
      cj[j][q] = num / w;
    }
  for (int q = 0; q < d; ++q) out[q] = cj[order_][q];
}

Fn RationalDerivativeOp::derivative(std::span<const Fn> args, int) const {
  return genmod::apply_custom(std::shared_ptr<const CustomOp>(next()), args);
}

std::shared_ptr<const RationalDerivativeOp> RationalDerivativeOp::next() const {
  std::call_once(next_once_, [this] {
    std::vector<std::shared_ptr<const BSplineOp>> h = h_;
    if (order_ + 1 <= curve_->degree()) {
      h.push_back(h.back()->derivative_op());
    }
    next_ = std::shared_ptr<const RationalDerivativeOp>(new RationalDerivativeOp(curve_, std::move(h), order_ + 1));
  });
  return next_;
}

}  // namespace genmod::detail
