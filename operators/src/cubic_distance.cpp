// Squared distance to a cubic curve (skeletal.hpp: distance2_to_cubic, eq. 5.8).
#include "genmod/kernel/custom_op.hpp"
#include "genmod/operators/skeletal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace genmod {
namespace {

constexpr int kRootIntervals = 256;  // sign-change search of the quintic
constexpr int kUpperSamples = 32;    // curve points for the inclusion's upper bound (+1)
constexpr int kLowerPieces = 32;     // curve pieces for the inclusion's lower bound
constexpr double kInf = std::numeric_limits<double>::infinity();

double dot3(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double distance2(const CubicCurve& c, double t, const Point3& p) {
  const Point3 q = c.at(t);
  double s = 0;
  for (int i = 0; i < 3; ++i) s += (q[i] - p[i]) * (q[i] - p[i]);
  return s;
}

double quintic(const std::array<double, 6>& k, double t) {
  double v = k[0];
  for (int i = 1; i < 6; ++i) v = v * t + k[i];
  return v;
}

// Squared distance from point p to the curve point at the upper-bound sample k: the candidate
// set of the point value contains these samples, so the point value never exceeds them.
double sample_parameter(int k) { return static_cast<double>(k) / kUpperSamples; }

// The squared distance at the best parameter (the point value).
double nearest_distance2(const CubicCurve& c, const Point3& p) { return distance2(c, cubic_nearest_parameter(c, p), p); }

Point3 point_of(std::span<const double> a) { return {a[0], a[1], a[2]}; }

// An enclosure of C over [t0, t1] by the Taylor form at the middle (exact for a cubic):
// C(m + s) = C(m) + C'(m) s + C''(m) s^2 / 2 + c1 s^3, s in [-h, h].
void piece_box(const CubicCurve& c, double t0, double t1, Interval out[3]) {
  const double m = 0.5 * (t0 + t1);
  const Interval sh = hull(Interval(t0) - Interval(m), Interval(t1) - Interval(m));
  const Interval s2 = square(sh), s3 = s2 * sh;
  const Interval mi(m);
  for (int i = 0; i < 3; ++i) {
    const Interval c1(c.c1[i]), c2(c.c2[i]), c3(c.c3[i]), c4(c.c4[i]);
    const Interval value = ((c1 * mi + c2) * mi + c3) * mi + c4;
    const Interval slope = (Interval(3.0) * c1 * mi + Interval(2.0) * c2) * mi + c3;
    const Interval curvature = Interval(3.0) * c1 * mi + c2;  // C''(m) / 2
    out[i] = value + slope * sh + curvature * s2 + c1 * s3;
  }
}

// Lower bound of the squared distance between two boxes (outward-rounded).
double box_gap2(std::span<const Interval> box, const Interval piece[3]) {
  Interval sum(0.0);
  for (int i = 0; i < 3; ++i) {
    Interval gap(0.0);
    if (box[i].lo() > piece[i].hi()) gap = Interval(box[i].lo()) - Interval(piece[i].hi());
    else if (box[i].hi() < piece[i].lo()) gap = Interval(piece[i].lo()) - Interval(box[i].hi());
    sum = sum + square(Interval(std::max(0.0, gap.lo()), std::max(0.0, gap.hi())));
  }
  return std::max(0.0, sum.lo());
}

Fn polynomial(const Point3& c1, const Point3& c2, const Point3& c3, const Point3& c4, const Fn& t, int i) {
  return ((c1[i] * t + c2[i]) * t + c3[i]) * t + c4[i];
}

class NearestParameterOp final : public CustomOp {
 public:
  explicit NearestParameterOp(const CubicCurve& c) : c_(c) {}
  std::string name() const override { return "cubic_nearest_parameter"; }
  int num_args() const override { return 3; }
  int num_outputs() const override { return 1; }
  void eval(std::span<const double> a, std::span<double> out) const override {
    out[0] = std::isnan(a[0] + a[1] + a[2]) ? std::numeric_limits<double>::quiet_NaN() : cubic_nearest_parameter(c_, point_of(a));
  }
  void inclusion(std::span<const Interval> a, std::span<Interval> out, std::span<std::uint8_t>) const override {
    out[0] = (a[0].is_empty() || a[1].is_empty() || a[2].is_empty()) ? Interval::empty() : Interval(0.0, 1.0);
  }
  // Interior minimum: g(t, p) = C'(t).(C(t) - p) = 0, so dt/dp_k = C'_k(t) / g_t with
  // g_t = C''(t).(C(t) - p) + |C'(t)|^2; at an end the parameter stays put.
  Fn derivative(std::span<const Fn> a, int k) const override;
  bool continuous() const override { return false; }  // jumps where two nearest points tie

  std::weak_ptr<const CustomOp> self;  // set by distance2_to_cubic (the derivative applies it)

 private:
  CubicCurve c_;
};

Fn NearestParameterOp::derivative(std::span<const Fn> a, int k) const {
  const Fn t = apply_custom(self.lock(), a);
  const CubicCurve& c = c_;
  const Point3 zero = {0, 0, 0};
  const Point3 d1 = {3 * c.c1[0], 3 * c.c1[1], 3 * c.c1[2]}, d2 = {2 * c.c2[0], 2 * c.c2[1], 2 * c.c2[2]};
  const Point3 e1 = {6 * c.c1[0], 6 * c.c1[1], 6 * c.c1[2]};
  Fn g_t = 0.0;
  Fn velocity_k;
  for (int i = 0; i < 3; ++i) {
    const Fn v = polynomial(zero, d1, d2, c.c3, t, i);              // C'_i(t)
    const Fn acc = polynomial(zero, zero, e1, d2, t, i);            // C''_i(t)
    const Fn offset = polynomial(c.c1, c.c2, c.c3, c.c4, t, i) - a[static_cast<std::size_t>(i)];
    g_t = g_t + acc * offset + square(v);
    if (i == k) velocity_k = v;
  }
  return select(t > 0.0 && t < 1.0, velocity_k / g_t, 0.0);
}

class CubicDistanceOp final : public CustomOp {
 public:
  CubicDistanceOp(const CubicCurve& c, std::shared_ptr<const CustomOp> nearest) : c_(c), nearest_(std::move(nearest)) {
    for (int k = 0; k < kLowerPieces; ++k) {
      pieces_.emplace_back();
      piece_box(c_, static_cast<double>(k) / kLowerPieces, static_cast<double>(k + 1) / kLowerPieces, pieces_.back().data());
    }
    for (int k = 0; k <= kUpperSamples; ++k) samples_.push_back(c_.at(sample_parameter(k)));
    for (const auto& piece : pieces_)
      for (const Interval& v : piece) scale_ = std::max({scale_, std::abs(v.lo()), std::abs(v.hi())});
  }
  std::string name() const override { return "distance2_to_cubic"; }
  int num_args() const override { return 3; }
  int num_outputs() const override { return 1; }
  void eval(std::span<const double> a, std::span<double> out) const override {
    out[0] = std::isnan(a[0] + a[1] + a[2]) ? std::numeric_limits<double>::quiet_NaN() : nearest_distance2(c_, point_of(a));
  }
  void inclusion(std::span<const Interval> a, std::span<Interval> out, std::span<std::uint8_t>) const override {
    for (int i = 0; i < 3; ++i)
      if (a[i].is_empty()) {
        out[0] = Interval::empty();
        return;
      }
    double lower = kInf;
    for (const auto& piece : pieces_) lower = std::min(lower, box_gap2(a, piece.data()));
    double upper = kInf;
    for (const Point3& q : samples_) {
      double worst = 0;  // the farthest corner, in outward-rounded arithmetic
      for (int corner = 0; corner < 8; ++corner) {
        Interval s(0.0);
        for (int i = 0; i < 3; ++i) s = s + square(Interval((corner >> i) & 1 ? a[i].hi() : a[i].lo()) - Interval(q[i]));
        worst = std::max(worst, s.hi());
      }
      upper = std::min(upper, worst);
    }
    // The point value is computed in rounded arithmetic from the same sample points (at most
    // a few ulps above the exact distance to them) and from refined parameters (a computed
    // curve point is off the curve by ~1e-16 of the coordinates' size, which moves the squared
    // distance d^2 by ~2e-16 d * size): widen by a relative 1e-12 and that absolute amount.
    double size = scale_;
    for (int i = 0; i < 3; ++i) size = std::max({size, std::abs(a[i].lo()), std::abs(a[i].hi())});
    const double slack = 1e-14 * (1 + size) * (std::sqrt(lower) + 1e-14 * (1 + size));
    out[0] = Interval(std::max(0.0, lower * (1 - 1e-12) - slack), upper * (1 + 1e-12) + slack);
  }
  Fn derivative(std::span<const Fn> a, int k) const override {
    const Fn t = apply_custom(nearest_, a);
    return 2.0 * (a[static_cast<std::size_t>(k)] - polynomial(c_.c1, c_.c2, c_.c3, c_.c4, t, k));
  }
  bool continuous() const override { return true; }

 private:
  CubicCurve c_;
  std::shared_ptr<const CustomOp> nearest_;
  std::vector<std::array<Interval, 3>> pieces_;
  std::vector<Point3> samples_;
  double scale_ = 0;  // the curve's coordinate size
};

}  // namespace

Point3 CubicCurve::at(double t) const {
  Point3 q;
  for (int i = 0; i < 3; ++i) q[i] = ((c1[i] * t + c2[i]) * t + c3[i]) * t + c4[i];
  return q;
}

std::array<double, 6> cubic_distance_quintic(const CubicCurve& c, const Point3& p) {
  Point3 e;
  for (int i = 0; i < 3; ++i) e[i] = c.c4[i] - p[i];
  return {3 * dot3(c.c1, c.c1),
          5 * dot3(c.c1, c.c2),
          2 * (2 * dot3(c.c1, c.c3) + dot3(c.c2, c.c2)),
          3 * (dot3(c.c1, e) + dot3(c.c2, c.c3)),
          2 * dot3(c.c2, e) + dot3(c.c3, c.c3),
          dot3(c.c3, e)};
}

double cubic_nearest_parameter(const CubicCurve& c, const Point3& p) {
  const std::array<double, 6> k = cubic_distance_quintic(c, p);
  double best_t = 0, best = distance2(c, 0, p);
  auto consider = [&](double t) {
    const double d = distance2(c, t, p);
    if (d < best) best = d, best_t = t;
  };
  double t0 = 0, g0 = quintic(k, 0);
  for (int j = 1; j <= kRootIntervals; ++j) {
    const double t1 = static_cast<double>(j) / kRootIntervals, g1 = quintic(k, t1);
    if (j % (kRootIntervals / kUpperSamples) == 0) consider(t1);  // the inclusion's samples
    if (g0 < 0 && g1 >= 0) {  // - to +: a local minimum of the distance in [t0, t1]
      double lo = t0, hi = t1;
      for (int it = 0; it < 60 && lo < hi; ++it) {
        const double m = 0.5 * (lo + hi);
        if (m <= lo || m >= hi) break;
        (quintic(k, m) < 0 ? lo : hi) = m;
      }
      consider(lo);
      consider(hi);
    }
    t0 = t1, g0 = g1;
  }
  return best_t;
}

Fn distance2_to_cubic(const CubicCurve& c, const Fn& p) {
  if (p.dim() != 3) throw std::invalid_argument("distance2_to_cubic: the query point must have dimension 3");
  for (const Point3* v : {&c.c1, &c.c2, &c.c3, &c.c4})
    for (double x : *v)
      if (!std::isfinite(x)) throw std::invalid_argument("distance2_to_cubic: coefficients must be finite");
  auto nearest = std::make_shared<NearestParameterOp>(c);
  nearest->self = nearest;
  const std::shared_ptr<const CustomOp> nearest_op = nearest;
  const auto op = std::make_shared<CubicDistanceOp>(c, nearest_op);
  return apply_custom(std::shared_ptr<const CustomOp>(op), {p[0], p[1], p[2]});
}

}  // namespace genmod
