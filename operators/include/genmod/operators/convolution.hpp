// Convolution surfaces and skeletal density kernels (Bloomenthal, research/bloomenthal.md
// §2.3, §3).
//
// Densities D(p) are positive and grow toward the skeleton (the source's convention);
// superposition is the sum of element densities (§3.4). genmod's implicit convention is
// f < 0 inside, so a density becomes an implicit solid only through `density_to_implicit`,
// f = iso - D (eq. 5.30; iso = 1/2 puts the surface through free segment endpoints and at
// distance r from a long segment). Every density here is a kernel Fn (opcodes plus the `erf`
// custom operator), so its inclusion function, derivative and batch evaluation come from
// the kernel and are sound.
//
// Example:
//   Fn D = segment_convolution({0, 0, 0}, {1, 0, 0}, 0.1) + segment_convolution({1, 0, 0}, {1, 1, 0}, 0.1);
//   Fn f = density_to_implicit(D);       // 1/2 - D, negative inside
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/kernel/interval.hpp"
#include "genmod/operators/skeletal.hpp"

namespace genmod {

// The width coefficient omega = ln 2 of the source's Gaussian, so Gauss(1) = 1/2 (eq. 5.32).
inline constexpr double kGaussOmega = 0.69314718055994530942;

// ---- the error function ---------------------------------------------------------------

// An outward-rounded enclosure of erf over x: erf is increasing, so the C library's values at
// the bounds, widened by a few ulps (glibc documents <= 1 ulp for erf in every rounding mode;
// we step 3), clamped to [-1, 1] and kept exact at erf(0) = 0. Tested against MPFR.
Interval erf_enclosure(const Interval& x) noexcept;
// erf as a custom operator on a scalar Fn (point value std::erf, inclusion erf_enclosure,
// derivative 2/sqrt(pi) exp(-x^2)). The kernel has no erf opcode; this keeps the kernel
// table untouched.
Fn erf(const Fn& x);

// ---- the Gaussian and its CDF (§0, §3.3) ----------------------------------------------

// Gauss(x) = exp(-omega x^2) = 2^(-x^2).
Fn gauss(const Fn& x);
// The normalized Gaussian CDF Phi(x) = (1 + erf(sqrt(omega) x)) / 2, the area under the
// unit-integral Gaussian of width omega from -infinity to x.
Fn gauss_cdf(const Fn& x);
// Area from x1 to x2 (the source's GaussIntegral): Phi(max) - Phi(min) >= 0.
Fn gauss_integral(const Fn& x1, const Fn& x2);

// ---- finite-support kernels (§2.3) ------------------------------------------------------

// Ease(x) = 0 for x < 0, 1 for x > 1, (4x^6 - 17x^4 + 22x^2)/9 between: C^1, monotone.
Fn ease(const Fn& x);
// The Wyvill kernel of x^2 (cubic in x^2, so no square root):
// 1 - (4x^6 - 17x^4 + 22x^2)/9 for x^2 <= 1, 0 beyond. Argument: s = x^2 >= 0.
Fn wyvill_kernel_of_square(const Fn& s);
// The cubic B-spline kernel h_B(x) of §2.3.1 (support |x| < 2, h_B(0) = 2/3, unit integral).
Fn bspline_kernel(const Fn& x);

// The kernels' CDFs (the integration filters, unit total): the closed-form areas of §2.3.1 and
// §2.3.2. bspline_cdf(x) = int_{-2}^{x} h_B; wyvill_cdf(x) = int_{-1}^{x} h_wyv / 0.998941799...
// (normalized by the kernel's true integral, so it is continuous and reaches 1 at x = 1).
Fn bspline_cdf(const Fn& x);
Fn wyvill_cdf(const Fn& x);
// The Wyvill kernel's integral over [-1, 1], 2 (1 - (4/7 - 17/5 + 22/3) / 9) = 0.998941799.
inline constexpr double kWyvillIntegral = 2 * (1 - (4.0 / 7 - 17.0 / 5 + 22.0 / 3) / 9);

// ---- point sources (§3.7) ---------------------------------------------------------------

enum class Kernel {
  gaussian,  // exp(-omega d^2/r^2): infinite support
  bspline,   // 1.5 h_B(0.72235 d/r): support d < 2.769 r
  wyvill,    // h_wyv(d / 2r): support d < 2 r
};
// The three kernels normalized as in Fig. 5.54: h(0) = 1 and h(1) = 1/2 (within 2e-6 for
// the B-spline), radius in isolation 1, of the normalized distance s = d/r given as s^2.
Fn normalized_kernel(Kernel kernel, const Fn& s2);
// The support radius of the normalized kernel in units of r (infinite for the Gaussian).
double kernel_support(Kernel kernel);
// w h(|p - c| / r); r > 0, w >= 0.
Fn point_source(const Point3& c, double r, double w = 1.0, Kernel kernel = Kernel::gaussian,
                const Fn& p = skeleton_query_point());

// ---- segment convolution (§3.2) ---------------------------------------------------------

// The Gaussian convolution of the segment a -> b, normalized by the local radius:
// D = [Phi((L - u)/r) - Phi(-u/r)]_+ * Gauss(d_perp / r), u the axial coordinate of p from a,
// d_perp the distance to the segment's line, r = r1 + clamp(u/L, 0, 1)(r2 - r1) (constant
// when r1 == r2). D -> Gauss(d_perp/r) along a long segment, D = 1/2 at free endpoints.
// Bound used for culling (proved in the spec, §10.2): D <= Gauss(dist(p, segment)/max(r1, r2)).
Fn segment_convolution(const Point3& a, const Point3& b, double r1, double r2, const Fn& p = skeleton_query_point());
inline Fn segment_convolution(const Point3& a, const Point3& b, double r, const Fn& p = skeleton_query_point()) {
  return segment_convolution(a, b, r, r, p);
}

// The same product form (integration filter x distance filter, §3.5 (a)) with the B-spline or
// Wyvill kernel normalized as in Fig. 5.54 (the Gaussian kernel gives the function above):
// D = [C((L - u) s / r) - C(-u s / r)]_+ * h(d_perp / r), C the kernel's CDF, s its scale
// (0.72235 for the B-spline, 1/2 for Wyvill), h = normalized_kernel. As for the Gaussian, D ->
// h(d_perp/r) along a long segment (iso 1/2 at distance r) and D = 1/2 at free endpoints. It
// vanishes where d_perp >= support or the axial excess beyond an end is >= support
// (support = kernel_support(kernel) r), hence beyond sqrt(2) support of the segment.
Fn segment_convolution(const Point3& a, const Point3& b, double r1, double r2, Kernel kernel,
                       const Fn& p = skeleton_query_point());

// ---- the density convention boundary ---------------------------------------------------

// f = iso - D: negative inside (D > iso), the surface at D = iso. The one place a density
// enters genmod's implicit convention.
Fn density_to_implicit(const Fn& density, double iso = 0.5);

}  // namespace genmod
