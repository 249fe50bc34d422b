#include "genmod/operators/offset.hpp"

#include "dims.hpp"
#include "genmod/operators/curve.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/vector.hpp"

#include <array>
#include <numbers>
#include <string>

namespace genmod {

namespace {

using detail::require_dim;

void require_parm(const char* op, const Fn& curve, int parm) {
  if (parm < 0 || parm >= 64) detail::dimension_error(op, "parameter index " + std::to_string(parm) + " out of range");
  if (((curve.input_mask() >> parm) & 1U) == 0)
    detail::dimension_error(op, "the curve does not depend on x(" + std::to_string(parm) + ")");
}

// The unit left normal of a planar curve.
Fn unit_normal(const Fn& curve, int parm) { return normalize(normal2d(curve, parm)); }

// sin(z) / z without a removable singularity, in a form whose natural interval extension and
// derivatives stay tight. For |z| < 3 it is the Taylor polynomial through z^26 in Horner form
// in z^2 (the first omitted term, z^28 / 29!, is below 3e-18 there): a polynomial's interval
// extension and symbolic derivatives are again polynomials, while the quotient sin(z) / z and
// its derivative (z cos z - sin z) / z^2 cancel catastrophically for small z, so that their
// enclosures over a box of width w grow like w / z^2 (an arc's tangent enclosure then
// straddled 0 and its unit normal had none). The arc below (t in [0, 1]) calls it with arguments
// no larger than its half turning angle, so the quotient serves only nearly full circles (beyond 3
// radians), where it is well conditioned; its argument is max(|z|, 3) (sinc is even), so no
// evaluation and no inclusion divides by an interval containing 0, even over boxes where the
// select is undecided.
Fn sinc(const Fn& z) {
  constexpr int kTerms = 14;  // the coefficients (-1)^k / (2k + 1)!, k = 0 .. 13
  const Fn z2 = square(z);
  std::array<double, kTerms> c{};
  c[0] = 1.0;
  for (int k = 1; k < kTerms; ++k) c[k] = -c[k - 1] / ((2.0 * k) * (2.0 * k + 1.0));
  Fn series(c[kTerms - 1]);
  for (int k = kTerms - 2; k >= 0; --k) series = c[k] + z2 * series;
  constexpr double kSwitch = 3.0;
  const Fn safe = max(abs(z), kSwitch);
  return select(abs(z) < kSwitch, series, sin(safe) / safe);
}

}  // namespace

Fn normal2d(const Fn& curve, int parm) {
  require_dim("normal2d", "the curve", curve, 2);
  require_parm("normal2d", curve, parm);
  const Fn d = derivative(curve, parm);
  return cat({-d[1], d[0]});
}

Fn offset_curve(const Fn& curve, const Fn& r, int parm) {
  require_dim("offset_curve", "the curve", curve, 2);
  require_dim("offset_curve", "the radius", r, 1);
  require_parm("offset_curve", curve, parm);
  return curve + r * unit_normal(curve, parm);
}

Fn offset_product(const Fn& cross, const Fn& profile, int cross_parm) {
  require_dim("offset_product", "the cross section", cross, 2);
  require_dim("offset_product", "the profile", profile, 2);
  require_parm("offset_product", cross, cross_parm);
  const Fn n = unit_normal(cross, cross_parm);
  return cat({cross[0] + profile[0] * n[0], cross[1] + profile[0] * n[1], profile[1]});
}

Fn offset_product(const Curve& cross, const Fn& u, const Fn& profile) {
  if (cross.dimension() != 2)
    detail::dimension_error("offset_product", "the cross section has dimension " + std::to_string(cross.dimension()) +
                                                  ", expected 2");
  require_dim("offset_product", "the parameter", u, 1);
  require_dim("offset_product", "the profile", profile, 2);
  const Fn c = cross(u), t = cross.unit_tangent(u);
  return cat({c[0] - profile[0] * t[1], c[1] + profile[0] * t[0], profile[1]});
}

Fn closed_offset(const Fn& curve, const Fn& r, int parm) {
  require_dim("closed_offset", "the curve", curve, 2);
  require_dim("closed_offset", "the radius", r, 1);
  require_parm("closed_offset", curve, parm);
  const Fn s = x(parm);
  const Fn n = unit_normal(curve, parm);
  const Fn tangent = cat({n[1], -n[0]});  // n rotated by -90 degrees: the unit tangent
  // c, n, T and r at one end, as functions of the other coordinates only.
  auto at_end = [&](double end) { return compose(cat({curve, n, tangent, r}), parm, Fn(end)); };
  const double pi = std::numbers::pi;
  const Fn c = cos(pi * s), sn = sin(pi * s);
  // A semicircle turning counter-clockwise from `from` (a unit vector) through `through`.
  auto cap = [&](const Fn& e, const Fn& from, const Fn& through) {
    const Fn center = cat({e[0], e[1]}), radius = e[6];
    return center + radius * (c * from + sn * through);
  };
  const Fn e1 = at_end(1.0), e0 = at_end(0.0);
  const Fn n1 = cat({e1[2], e1[3]}), t1 = cat({e1[4], e1[5]});
  const Fn n0 = cat({e0[2], e0[3]}), t0 = cat({e0[4], e0[5]});
  const Fn right_forward = curve - r * n;
  const Fn end_cap = cap(e1, -n1, t1);    // from c(1) - r n(1) around the front to c(1) + r n(1)
  const Fn left_backward = compose(curve + r * n, parm, 1.0 - s);
  const Fn start_cap = cap(e0, n0, -t0);  // from c(0) + r n(0) around the back to c(0) - r n(0)
  return concat(parm, s, {right_forward, end_cap, left_backward, start_cap});
}

Fn arc_2pt_height(const Fn& p1, const Fn& p2, const Fn& height, const Fn& t) {
  require_dim("arc_2pt_height", "p1", p1, 2);
  require_dim("arc_2pt_height", "p2", p2, 2);
  require_dim("arc_2pt_height", "the height", height, 1);
  require_dim("arc_2pt_height", "t", t, 1);
  // With half chord a, half turning angle alpha = 2 atan(h / a) and phi = s alpha, s = 2t - 1,
  // the arc is mid + (D/2) sin(phi)/sin(alpha) + (M/2) (cos(phi) - cos(alpha))/sin(alpha),
  // D = p2 - p1 and M its left perpendicular. Both ratios are rewritten with sinc so that
  // they only divide by sinc(alpha) > 0 and are exact at alpha = 0:
  //   sin(s alpha)/sin(alpha) = s sinc(s alpha) / sinc(alpha),
  //   (cos(s alpha) - cos(alpha))/sin(alpha)
  //     = (1 - s^2) (alpha/2) sinc((1+s) alpha/2) sinc((1-s) alpha/2) / sinc(alpha).
  const Fn d = p2 - p1;
  const Fn m = cat({-d[1], d[0]});
  const Fn mid = 0.5 * (p1 + p2);
  const Fn a = 0.5 * length(d);
  const Fn alpha = 2.0 * atan(height / a);
  const Fn s = 2.0 * t - 1.0;
  const Fn inv = 1.0 / sinc(alpha);
  const Fn along = s * sinc(s * alpha) * inv;
  const Fn across = (1.0 - square(s)) * (0.5 * alpha) * sinc(0.5 * (1.0 + s) * alpha) * sinc(0.5 * (1.0 - s) * alpha) * inv;
  return mid + 0.5 * along * d + 0.5 * across * m;
}

}  // namespace genmod
