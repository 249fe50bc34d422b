// Distance bounds of Gaussian elements and their derivatives (culled_field_bounds.hpp).
//
// Notation: omega = ln 2, phi(v) = sqrt(omega/pi) exp(-omega v^2) the density of the
// integration filter Phi (convolution.hpp), r the radius, delta the distance of p from the
// skeleton and s = delta / r.
//
// Value (spec §10.2): D <= weight Gauss(s) for point sources and for segment convolutions
// with r = the larger end radius.
//
// First derivative of a Gaussian segment convolution D = G(u) H(d) (u the axial coordinate,
// d the distance to the segment's line, G = Phi((L - u)/r) - Phi(-u/r), H = exp(-omega d^2/r^2))
// at constant radius r:
//   grad D = G'(u) H axis + G grad H,  G'(u) = (phi(u/r) - phi((L - u)/r)) / r,
//   |grad H| = (2 omega d / r^2) H.
// With x >= 0 the axial excess of p beyond the nearer end (0 beside the segment), so that
// delta^2 = d^2 + x^2: both phi terms are positive, so |G'| <= max(phi(u/r), phi((L-u)/r)) / r
// <= sqrt(omega/pi) exp(-omega x^2/r^2) / r; and G <= exp(-omega x^2/r^2) (G <= 1 beside the
// segment; beyond an end G <= Phi(-x/r) <= exp(-omega x^2/r^2)/2, the Gaussian tail bound).
// Hence, as every |dD/dx_k| <= |grad D| <= |axial part| + |radial part|,
//   |dD/dx_k| <= exp(-omega s^2) (c0 + c1 s) / r,   c0 = sqrt(omega/pi), c1 = 2 omega,
// using d <= delta. For a point source w exp(-omega s^2) the gradient is w c1 s exp(-omega s^2)/r,
// inside the same bound times w.
//
// Tapered segments: r = r(u) = r1 + clamp(u/L, 0, 1)(r2 - r1) in [r_min, r_max], with slope
// |r'| <= taper = |r2 - r1| / L. Beyond the ends r is constant (r1 or r2: the bound above holds
// there); beside the segment (x = 0, delta = d) there is an extra axial term r' dD/dr:
//   dG/dr = -[(L - u)/r phi((L - u)/r) + u/r phi(u/r)] / r, each term in [0, max_v v phi(v)]
//           = [0, 1/sqrt(2 pi e)], so |dG/dr| <= c2 / r with c2 = 2/sqrt(2 pi e);
//   dH/dr = H 2 omega d^2 / r^3;  G <= 1.
// So |r' dD/dr| <= taper exp(-omega s^2) (c2 + c1 s^2) / r, and at the point's own r(u):
//   |dD/dx_k| <= exp(-omega t^2) [(c0 + c1 t) + taper (c2 + c1 t^2)] / r,  t = delta / r(u).
// To replace r(u) by r_max: at fixed delta, (1/r) exp(-omega t^2) (c0 + c1 t) = (1/delta) q(t)
// with q(t) = t (c0 + c1 t) exp(-omega t^2), and the taper term is (1/delta) m(t) with
// m(t) = t (c2 + c1 t^2) exp(-omega t^2). For t >= 1.5 both decrease:
//   q' exp(omega t^2) = c0 + 4 omega t - 2 omega c0 t^2 - 4 omega^2 t^3 < 0, as 4 omega^2 t^3 >=
//     9 omega^2 t = 4.32 t > 4 omega t + c0 = 2.77 t + 0.47;
//   m' exp(omega t^2) = c2 + (6 omega - 2 omega c2) t^2 - 4 omega^2 t^4 < 0, as 4 omega^2 t^4 >=
//     4.32 t^2 > 3.49 t^2 + 0.49.
// So where delta >= 1.5 r_max (hence t >= 1.5 for every r(u) <= r_max) the bound at r(u) is at
// most the bound at r_max:
//   |dD/dx_k| <= B(s) = weight exp(-omega s^2) [(c0 + c1 s) + taper (c2 + c1 s^2)] / r_max,
//   s = delta / r_max >= 1.5.
// B decreases in s there (d/ds of exp(-omega s^2)(c0 + c1 s) has the sign of 2 omega - 2 omega c0 s
// - 4 omega^2 s^2 < 0, and of exp(-omega s^2)(c2 + c1 s^2) the sign of 2 - c2 - 2 omega s^2 < 0 for
// s^2 > 1.1), and it increases with weight and taper and (by the argument above) with r_max.
// So one bound with a subtree's largest weight, radius and taper holds for all its elements at
// the subtree's distance, when that distance is at least 1.5 times the largest radius.
// Numerically the last sign changes of q', m' and the two s-derivatives are at t = 1.13, 1.39,
// 0.70 and 1.05; the tests check the bound against sampled symbolic derivatives.
//
// Second derivatives, constant radius r (segment convolutions with r1 == r2, point sources).
// In an orthonormal frame (u along the axis, q the 2-vector across it, d = |q|), D = G(u) H(q)
// with H = exp(-omega |q|^2 / r^2), and the Hessian has the blocks
//   D_uu = G'' H,   D_uq = G' grad_q H,   D_qq = G hess_q H.
// Its spectral norm, which bounds every entry d^2 D / dx_j dx_k in any rotated frame, is at most
// |D_uu| + |D_uq| + ||D_qq|| (the matrix split into its diagonal blocks and its off-diagonal
// part; the latter's norm is |D_uq|). With t_x = x / r, t_d = d / r (x the axial excess as
// above), so that s^2 = t_x^2 + t_d^2 and exp(-omega t_x^2) exp(-omega t_d^2) = exp(-omega s^2):
//  * G'' = [phi'(u/r) + phi'((L - u)/r)] / r^2 = -c1 [v1 phi(v1) + v2 phi(v2)] / r^2 with
//    v1 = u/r, v2 = (L - u)/r (phi'(v) = -2 omega v phi(v)). Beside the segment both v >= 0
//    and each v phi(v) <= max_v v phi(v) = 1/sqrt(2 pi e) = c2/2. Beyond an end (say u < 0)
//    v1 = -t_x, v2 >= t_x and the two terms have opposite signs, so the sum is at most the
//    larger: t_x phi(t_x) <= c0 t_x exp(-omega t_x^2), and with v2 = t_x + w, w >= 0,
//    exp(-omega v2^2) <= exp(-omega t_x^2) exp(-omega w^2), so v2 phi(v2) <= c0 exp(-omega t_x^2)
//    (t_x + w exp(-omega w^2)) <= exp(-omega t_x^2) (c0 t_x + c2/2) (c0 / sqrt(2 omega e) = c2/2).
//    Both cases: |G''| <= c1 exp(-omega t_x^2) (2 c0 t_x + c2) / r^2.
//  * |G'| <= c0 exp(-omega t_x^2) / r and G <= exp(-omega t_x^2) (first-derivative part above).
//  * grad_q H = -(c1 / r^2) q H, so |grad_q H| = c1 t_d H / r; hess_q H = (c1 / r^2) H
//    (c1 q q^T / r^2 - I), eigenvalues (c1 / r^2) H (c1 t_d^2 - 1) and -(c1 / r^2) H, so
//    ||hess_q H|| <= (c1 / r^2) H (1 + c1 t_d^2).
// Adding the three with t_x, t_d <= s:
//   |d^2 D / dx_j dx_k| <= C(s) = weight c1 exp(-omega s^2) [(1 + c2) + 3 c0 s + c1 s^2] / r^2.
// A point source w exp(-omega s^2) has the Hessian (c1 w / r^2) H (c1 v v^T / r^2 - I) (v = p - c),
// norm <= w c1 (1 + c1 s^2) exp(-omega s^2) / r^2, inside C. Tapered segments (r varying with u)
// have further terms from r' (and r jumps in slope at the ends): not bounded here, never culled.
// Monotonicity, as for the gradient: at fixed delta, C = (1/delta^2) f(t), t = delta / r, with
// f(t) = t^2 (a + b t + c1 t^2) exp(-omega t^2), a = 1 + c2 < 1.484, b = 3 c0 < 1.41, and
//   f' exp(omega t^2) / t = 2a + 3b t + (4 c1 - 2 omega a) t^2 - 2 omega b t^3 - 2 omega c1 t^4
//                         < 2.97 + 4.23 t + 3.49 t^2 - 1.95 t^3 - 1.92 t^4 < 0 for t >= 2,
// as 1.95 t^3 >= 3.9 t^2 > 3.49 t^2 and 1.92 t^4 >= 7.68 t^2 >= 15.36 t > 4.23 t + 2.97. So
// C increases with r where delta >= 2 r_max (the last sign change is at t = 1.53). In s:
// d/ds [exp(-omega s^2)(a + b s + c1 s^2)] has the sign of b + 2 c1 s - 2 omega s (a + b s + c1 s^2)
// = b + (2 c1 - 2 omega a) s - 2 omega b s^2 - 2 omega c1 s^3 < 1.41 + 0.72 s - 1.95 s^2 < 0 for
// s >= 1. So from kHessianBoundFrom = 2 radii one bound with a subtree's largest weight and
// radius holds for all its constant-radius elements at the subtree's distance.
//
// Rounding: the bounds are evaluated in double arithmetic (they run for every culled subtree
// of every box: an outward-rounded interval operation switches the rounding mode twice):
// each operation has a relative error <= 2^-52 and glibc's exp <= 1 ulp, the constants are
// rounded up from interval enclosures, s is shrunk by 1e-12 relative (the bounds decrease in
// s) and the result grown by 1e-9 relative, far above those errors and above the 1e-16
// differences of the densities' own omega and sqrt(omega) (rounded to double) and the ~1e-15
// rounding of their derivative tapes.
#include "culled_field_bounds.hpp"

#include "genmod/kernel/interval.hpp"
#include "genmod/operators/convolution.hpp"

#include <cmath>
#include <limits>

namespace genmod::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMargin = 1 + 1e-9;

// pi lies between these two adjacent doubles.
const Interval kPi(3.141592653589793, 3.1415926535897936);

// Upper bounds of the constants of the gradient bound.
struct GradientConstants {
  double c0, c1, c2;
  GradientConstants() {
    const Interval omega(kGaussOmega);
    c0 = sqrt(omega / kPi).hi();
    c1 = (Interval(2.0) * omega).hi();
    c2 = (Interval(2.0) / sqrt(Interval(2.0) * kPi * exp(Interval(1.0)))).hi();
  }
};

const GradientConstants& constants() {
  static const GradientConstants c;
  return c;
}

}  // namespace

double gaussian_value_above(double weight, double radius, double d2) {
  // weight * exp(-omega s^2) at s^2 = d2 / r^2 shrunk (the bound decreases in s).
  const double s2 = d2 / (radius * radius) * (1 - 1e-12);
  return weight * std::exp(-kGaussOmega * s2) * kMargin + std::numeric_limits<double>::denorm_min();
}

double gaussian_gradient_above(double weight, double radius, double taper, double d2) {
  const GradientConstants& c = constants();
  const double s2 = d2 / (radius * radius) * (1 - 1e-12);
  if (!(s2 >= kGradientBoundFrom * kGradientBoundFrom)) return kInf;
  // B decreases in s from 1.5 on, so its value at the lower bound of s bounds it beyond.
  const double s = std::sqrt(s2);
  const double poly = c.c0 + c.c1 * s + taper * (c.c2 + c.c1 * s2);
  return weight * std::exp(-kGaussOmega * s2) * poly / radius * kMargin + 1e-300;
}
double gaussian_hessian_above(double weight, double radius, double d2) {
  const GradientConstants& c = constants();
  const double s2 = d2 / (radius * radius) * (1 - 1e-12);
  if (!(s2 >= kHessianBoundFrom * kHessianBoundFrom)) return kInf;
  // C decreases in s from 1 on (above), so its value at the lower bound of s bounds it beyond.
  const double s = std::sqrt(s2);
  const double poly = (1 + c.c2) + 3 * c.c0 * s + c.c1 * s2;
  return weight * c.c1 * std::exp(-kGaussOmega * s2) * poly / (radius * radius) * kMargin + 1e-300;
}

namespace {

// The smallest squared distance from `from2` on (found by doubling, then bisection) where the
// decreasing bound(d2) is at most cull_below; +infinity for cull_below <= 0.
template <class Bound>
double cull_distance2(double from2, double cull_below, Bound&& bound) {
  if (!(cull_below > 0)) return kInf;
  double lo = from2, hi = lo;
  if (bound(lo) <= cull_below) return lo;
  int steps = 0;
  while (!(bound(hi) <= cull_below)) {
    hi *= 2;
    if (++steps > 2000 || !std::isfinite(hi)) return kInf;
  }
  for (int i = 0; i < 80 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (bound(mid) <= cull_below) hi = mid;
    else lo = mid;
  }
  return hi;  // checked: the bound at hi, hence beyond, is at most cull_below
}

}  // namespace

double gaussian_gradient_cull_distance2(double weight, double radius, double taper, double cull_below) {
  return cull_distance2(kGradientBoundFrom * kGradientBoundFrom * radius * radius, cull_below,
                        [&](double d2) { return gaussian_gradient_above(weight, radius, taper, d2); });
}

double gaussian_hessian_cull_distance2(double weight, double radius, double cull_below) {
  return cull_distance2(kHessianBoundFrom * kHessianBoundFrom * radius * radius, cull_below,
                        [&](double d2) { return gaussian_hessian_above(weight, radius, d2); });
}

}  // namespace genmod::detail
